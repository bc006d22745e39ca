#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "scan/digit_classifier.h"

using namespace epure::scan;

TEST_CASE("digit classifier: each member gives train_digits.py's logits, the ensemble its probabilities") {
  // digits.check: the member count, then 12 crops (one per class), each followed by every
  // member's logits and the ensemble's probabilities as PyTorch computed them
  std::ifstream in(std::string(EPURE_SOURCE_DIR) + "/src/scan/classifier/digits.check");
  REQUIRE(in);
  std::string line;
  std::getline(in, line);  // the comment
  REQUIRE(std::getline(in, line));
  std::istringstream head(line);
  std::string word;
  std::size_t members = 0;
  head >> word >> members;
  REQUIRE(word == "members");
  const DigitClassifier& net = DigitClassifier::builtin();
  REQUIRE(net.members() == members);
  auto numbers = [&in, &line] {
    REQUIRE(std::getline(in, line));
    std::istringstream s(line);
    std::vector<double> v;
    for (double x; s >> x;) v.push_back(x);
    REQUIRE(v.size() == static_cast<std::size_t>(kClassCount));
    return v;
  };
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
    for (std::size_t m = 0; m < members; ++m) {
      CAPTURE(m);
      const auto expected = numbers();
      const auto z = net.logits(m, crop);
      for (std::size_t k = 0; k < kClassCount; ++k) CHECK(std::abs(z[k] - expected[k]) <= 1e-4 * std::max(1.0, std::abs(expected[k])));
      // the same crop, the same bits, every time
      const auto again = net.logits(m, crop);
      CHECK(std::equal(z.begin(), z.end(), again.begin()));
    }
    // probabilities within 1e-5: the logits' last-bit differences move them by about 1e-6
    const auto expected = numbers();
    const CellReading r = net.classify(crop);
    for (std::size_t k = 0; k < kClassCount; ++k) CHECK(std::abs(r.probability[k] - expected[k]) <= 1e-5);
    // the class read is PyTorch's best (the check's crop of a 3 is read as an 8: a hard one)
    CHECK(static_cast<std::size_t>(r.best) == static_cast<std::size_t>(std::max_element(expected.begin(), expected.end()) - expected.begin()));
    const CellReading again = net.classify(crop);
    CHECK(std::equal(r.probability.begin(), r.probability.end(), again.probability.begin()));
  }
}

namespace {
std::string u32(std::uint32_t v) {
  return {static_cast<char>(v & 0xff), static_cast<char>(v >> 8 & 0xff), static_cast<char>(v >> 16 & 0xff), static_cast<char>(v >> 24)};
}
}  // namespace

namespace {
// A version-2 network of widths 1-1-1-1 whose weights are all zero but its output biases: its
// logits are those biases whatever the crop.
std::string biased_network(const std::array<float, kClassCount>& bias) {
  std::string b = "EPDG" + u32(2) + u32(64) + u32(1) + u32(1) + u32(1) + u32(1) + std::string(52 * 4, '\0');
  for (float v : bias) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    b += u32(bits);
  }
  return b;
}
}  // namespace

TEST_CASE("digit classifier: a weights file of another version or size is refused") {
  // version 1 (the first network's file, no widths in its header)
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(1) + u32(61004) + std::string(16, '\0')),
                       "digit classifier: not a version-2 or 3 weights file (EPDG)", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(2)), "digit classifier: not a version-2 or 3 weights file (EPDG)", std::runtime_error);
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

TEST_CASE("digit classifier: a version-3 file's members are read in turn and their probabilities averaged") {
  std::array<float, kClassCount> a{}, b{};
  a[3] = 4.0f;   // member a: sure of a 3
  b[3] = 1.0f;   // member b: hesitates between 3 and 8
  b[8] = 1.5f;
  const DigitClassifier one_a(biased_network(a)), one_b(biased_network(b));
  const DigitClassifier both("EPDG" + u32(3) + u32(2) + biased_network(a) + biased_network(b));
  REQUIRE(both.members() == 2);
  CHECK(both.shape(1).hidden == 1);
  const CellCrop crop{};
  const CellReading ra = one_a.classify(crop), rb = one_b.classify(crop), r = both.classify(crop);
  CHECK(rb.best == CellClass::d8);
  CHECK(r.best == CellClass::d3);
  for (std::size_t k = 0; k < kClassCount; ++k) {
    CAPTURE(k);
    CHECK(r.probability[k] == doctest::Approx((ra.probability[k] + rb.probability[k]) / 2).epsilon(1e-6));
    CHECK(both.logits(0, crop)[k] == a[k]);
    CHECK(both.logits(1, crop)[k] == b[k]);
  }
  // the mean is less sure than the surer member: that is what sends the ambiguous cell to review
  CHECK(r.confidence < ra.confidence);
  CHECK(r.confidence > rb.probability[3]);

  // refused: no member, too many, a member cut short, bytes after the last one
  const std::string net = biased_network(a);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(0)), "digit classifier: the weights file declares no or too many networks",
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(9) + net), "digit classifier: the weights file declares no or too many networks",
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(2) + net + net.substr(0, net.size() - 4)),
                       "digit classifier: the weights file's size is not its network's", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(2) + net + net.substr(0, 20)),
                       "digit classifier: not a version-2 or 3 weights file (EPDG)", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(1) + net + "x"), "digit classifier: the weights file's size is not its networks'",
                       std::runtime_error);
  // a member is a version-2 network, not another ensemble
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(1) + "EPDG" + u32(3) + u32(1) + net),
                       "digit classifier: not a version-2 or 3 weights file (EPDG)", std::runtime_error);
}

TEST_CASE("digit classifier: the networks carried are the ones train_digits.py describes") {
  const DigitClassifier& net = DigitClassifier::builtin();
  CHECK(net.members() == 3);
  for (std::size_t m = 0; m < net.members(); ++m) {
    CAPTURE(m);
    const NetShape s = net.shape(m);
    CHECK(s.conv1 == 32);
    CHECK(s.conv2 == 64);
    CHECK(s.conv3 == 128);
    CHECK(s.hidden == 128);
  }
}
