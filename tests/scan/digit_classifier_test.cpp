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

namespace {
std::string u32(std::uint32_t v) {
  return {static_cast<char>(v & 0xff), static_cast<char>(v >> 8 & 0xff), static_cast<char>(v >> 16 & 0xff), static_cast<char>(v >> 24)};
}
}  // namespace

TEST_CASE("digit classifier: a weights file of another version or size is refused") {
  // version 1 (the first network's file, no widths in its header)
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(1) + u32(61004) + std::string(16, '\0')),
                       "digit classifier: not a version-2 weights file (EPDG)", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(2)), "digit classifier: not a version-2 weights file (EPDG)", std::runtime_error);
  // a width of zero or past the bound, before any allocation
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(2) + u32(0) + u32(1) + u32(0) + u32(1) + u32(1)),
                       "digit classifier: the weights file declares a layer of no or too many units", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(2) + u32(0) + u32(1) + u32(1) + u32(1) + u32(1u << 30)),
                       "digit classifier: the weights file declares a layer of no or too many units", std::runtime_error);
  // the count and the bytes must be the widths' network: 1-1-1-1 has 9+1+9+1+9+1+9+1+12+12 = 64
  const std::string head = "EPDG" + u32(2) + u32(64) + u32(1) + u32(1) + u32(1) + u32(1);
  CHECK_NOTHROW(DigitClassifier(head + std::string(64 * 4, '\0')));
  CHECK_THROWS_WITH_AS(DigitClassifier(head + std::string(63 * 4, '\0')), "digit classifier: the weights file's size is not its network's",
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(2) + u32(65) + u32(1) + u32(1) + u32(1) + u32(1) + std::string(65 * 4, '\0')),
                       "digit classifier: the weights file's size is not its network's", std::runtime_error);
}

TEST_CASE("digit classifier: the network carried is the one train_digits.py describes") {
  const NetShape s = DigitClassifier::builtin().shape();
  CHECK(s.conv1 == 32);
  CHECK(s.conv2 == 64);
  CHECK(s.conv3 == 128);
  CHECK(s.hidden == 128);
}
