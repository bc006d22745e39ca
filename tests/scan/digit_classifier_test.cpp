#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "scan/digit_classifier.h"

using namespace epure::scan;

TEST_CASE("digit classifier: the C++ forward pass gives train_digits.py's logits") {
  // digits.check: 12 crops (one per class) and the logits PyTorch computed for them
  std::ifstream in(std::string(EPURE_SOURCE_DIR) + "/src/scan/classifier/digits.check");
  REQUIRE(in);
  std::string line;
  std::getline(in, line);  // the comment
  const DigitClassifier& net = DigitClassifier::builtin();
  for (int c = 0; c < kClassCount; ++c) {
    CAPTURE(c);
    CellCrop crop{};
    REQUIRE(std::getline(in, line));
    std::istringstream px(line);
    for (auto& v : crop) {
      int x;
      px >> x;
      v = static_cast<std::uint8_t>(x);
    }
    REQUIRE(std::getline(in, line));
    std::istringstream lg(line);
    const auto z = net.logits(crop);
    for (int k = 0; k < kClassCount; ++k) {
      double expected;
      lg >> expected;
      CHECK(std::abs(z[static_cast<std::size_t>(k)] - expected) <= 1e-4 * std::max(1.0, std::abs(expected)));
    }
    // the same crop, the same bits, every time
    const auto again = net.logits(crop);
    CHECK(std::equal(z.begin(), z.end(), again.begin()));
  }
}

TEST_CASE("digit classifier: a weights file of another network is refused") {
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG\x02\0\0\0"), "digit classifier: not a version-1 weights file (EPDG)", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier(std::string("EPDG\x01\0\0\0\x01\0\0\0\0\0\0\0", 16)),
                       "digit classifier: the weights file holds another network", std::runtime_error);
}
