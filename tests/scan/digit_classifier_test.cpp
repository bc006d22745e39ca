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
                       "digit classifier: not a version-2, 3 or 4 weights file (EPDG)", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(2)), "digit classifier: not a version-2, 3 or 4 weights file (EPDG)", std::runtime_error);
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
                       "digit classifier: not a version-2, 3 or 4 weights file (EPDG)", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(1) + net + "x"), "digit classifier: the weights file's size is not its networks'",
                       std::runtime_error);
  // a member is a version-2 network, not another ensemble
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(3) + u32(1) + "EPDG" + u32(3) + u32(1) + net),
                       "digit classifier: not a version-2, 3 or 4 weights file (EPDG)", std::runtime_error);
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
    CHECK(s.depth == 2);
  }
}

namespace {
// A version-4 file (stages of `depth` convolutions) of the given widths and floats.
std::string version4(std::uint32_t depth, std::array<std::uint32_t, 4> widths, const std::vector<float>& w) {
  std::string b = "EPDG" + u32(4) + u32(static_cast<std::uint32_t>(w.size())) + u32(depth);
  for (std::uint32_t x : widths) b += u32(x);
  for (float v : w) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    b += u32(bits);
  }
  return b;
}

// The logits of a network of `depth` convolutions a stage, computed the plain way: each output
// pixel summed over its 3x3 neighbourhood (past the border, a zero input's term), a pool after a
// stage's last convolution. An independent reading of the file's layout, to check the
// classifier's im2col and blocked forward pass: in double, the values; in float, with the terms
// in the order the classifier promises (bias, then i, ky, kx), the very bits.
template <typename T>
std::array<T, kClassCount> plain_logits(std::uint32_t depth, std::array<std::uint32_t, 4> widths, const std::vector<float>& w,
                                        const CellCrop& crop) {
  std::size_t at = 0;
  int side = kCropSide, cin = 1;
  std::vector<T> a(crop.size());
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<float>(crop[i]) / 255.0f;
  for (int stage = 0; stage < 3; ++stage)
    for (std::uint32_t k = 0; k < depth; ++k) {
      const int cout = static_cast<int>(widths[static_cast<std::size_t>(stage)]);
      const std::size_t wk = at, bk = at + static_cast<std::size_t>(cout * cin * 9);
      at = bk + static_cast<std::size_t>(cout);
      std::vector<T> out(static_cast<std::size_t>(cout * side * side));
      for (int o = 0; o < cout; ++o)
        for (int y = 0; y < side; ++y)
          for (int x = 0; x < side; ++x) {
            T s = w[bk + static_cast<std::size_t>(o)];
            for (int i = 0; i < cin; ++i)
              for (int ky = 0; ky < 3; ++ky)
                for (int kx = 0; kx < 3; ++kx) {
                  const int sy = y + ky - 1, sx = x + kx - 1;
                  const bool inside = sy >= 0 && sy < side && sx >= 0 && sx < side;
                  const T v = inside ? a[static_cast<std::size_t>((i * side + sy) * side + sx)] : T(0);
                  s += static_cast<T>(w[wk + static_cast<std::size_t>(((o * cin + i) * 3 + ky) * 3 + kx)]) * v;
                }
            out[static_cast<std::size_t>((o * side + y) * side + x)] = s;
          }
      a = out;
      cin = cout;
      if (k + 1 == depth) {  // the stage's 2x2 max pool (floor), then ReLU
        const int half = side / 2;
        std::vector<T> p(static_cast<std::size_t>(cout * half * half));
        for (int o = 0; o < cout; ++o)
          for (int y = 0; y < half; ++y)
            for (int x = 0; x < half; ++x) {
              auto v = [&](int dy, int dx) { return a[static_cast<std::size_t>((o * side + 2 * y + dy) * side + 2 * x + dx)]; };
              p[static_cast<std::size_t>((o * half + y) * half + x)] = std::max(std::max(std::max(v(0, 0), v(0, 1)), std::max(v(1, 0), v(1, 1))), T(0));
            }
        a = p;
        side = half;
      } else {
        for (auto& v : a) v = std::max(v, T(0));
      }
    }
  const std::size_t hidden = widths[3], flat = a.size();
  std::vector<T> h(hidden);
  const std::size_t f1 = at, b1 = f1 + hidden * flat, f2 = b1 + hidden, b2 = f2 + kClassCount * hidden;
  for (std::size_t j = 0; j < hidden; ++j) {
    T s = w[b1 + j];
    for (std::size_t i = 0; i < flat; ++i) s += static_cast<T>(w[f1 + j * flat + i]) * a[i];
    h[j] = std::max(s, T(0));
  }
  std::array<T, kClassCount> z;
  for (std::size_t c = 0; c < kClassCount; ++c) {
    T s = w[b2 + c];
    for (std::size_t i = 0; i < hidden; ++i) s += static_cast<T>(w[f2 + c * hidden + i]) * h[i];
    z[c] = s;
  }
  return z;
}
}  // namespace

TEST_CASE("digit classifier: a version-4 network (stages of several convolutions) reads as a plain convolution does") {
  // widths that make every layer run full blocks and edges, in both products (baseline: 9 = 4 +
  // 4 + 1 planes, 10 = 4 + 4 + 2; with AVX2: 9 = 8 + 1, 10 = 8 + 2, 12 = 8 + 4; 12 hidden units =
  // 8 side by side + 4 one at a time), the pixels' edges too (196 = 24 x 8 + 4, 49 = 6 x 8 + 1)
  const std::array<std::uint32_t, 4> widths{9, 10, 12, 12};
  std::uint64_t state = 20261206;  // a fixed LCG: the same weights on every machine
  auto next = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<float>(static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24) - 0.5);
  };
  CellCrop crop;
  for (auto& v : crop) v = static_cast<std::uint8_t>(static_cast<int>((next() + 0.5f) * 255.0f) & 0xff);
  for (std::uint32_t depth : {1u, 2u, 3u}) {
    CAPTURE(depth);
    std::size_t count = 0, cin = 1;
    for (std::uint32_t s = 0; s < 3; ++s)
      for (std::uint32_t k = 0; k < depth; ++k) {
        count += widths[s] * cin * 9 + widths[s];
        cin = widths[s];
      }
    count += widths[3] * cin * 9 + widths[3] + kClassCount * widths[3] + kClassCount;
    std::vector<float> w(count);
    for (auto& v : w) v = next();
    const DigitClassifier net(version4(depth, widths, w));
    REQUIRE(net.members() == 1);
    CHECK(net.shape(0).depth == depth);
    const auto z = net.logits(0, crop);
    const auto expected = plain_logits<double>(depth, widths, w, crop);
    for (std::size_t k = 0; k < kClassCount; ++k) CHECK(z[k] == doctest::Approx(expected[k]).epsilon(1e-4).scale(1.0));
    // summed in float in the promised order: the same bits
    const auto same_order = plain_logits<float>(depth, widths, w, crop);
    CHECK(std::equal(z.begin(), z.end(), same_order.begin()));
    // the baseline product (four floats a register) too, where `net` runs AVX2's if the CPU has it
    const DigitClassifier baseline(version4(depth, widths, w), DigitClassifier::Product::baseline);
    CHECK_FALSE(baseline.wide());
#if defined(__x86_64__) && defined(__GNUC__)
    CHECK(net.wide() == static_cast<bool>(__builtin_cpu_supports("avx2")));
#endif
    if (depth == 1) {
      const char* which = net.wide() ? "the AVX2 product checked against the baseline" : "this CPU has no AVX2: the baseline product alone";
      MESSAGE(which);
    }
    const auto zs = baseline.logits(0, crop);
    CHECK(std::equal(zs.begin(), zs.end(), same_order.begin()));
    if (depth == 1) {
      // a depth-1 version-4 file is the version-2 file of the same floats
      std::string v2 = "EPDG" + u32(2) + u32(static_cast<std::uint32_t>(count));
      for (std::uint32_t x : widths) v2 += u32(x);
      v2 += version4(depth, widths, w).substr(32);
      const auto z2 = DigitClassifier(v2).logits(0, crop);
      CHECK(std::equal(z.begin(), z.end(), z2.begin()));
    }
    // in an ensemble beside a version-2 member
    const DigitClassifier both("EPDG" + u32(3) + u32(2) + version4(depth, widths, w) + biased_network({}));
    CHECK(both.shape(0).depth == depth);
    CHECK(both.shape(1).depth == 1);
    const auto zb = both.logits(0, crop);
    CHECK(std::equal(z.begin(), z.end(), zb.begin()));
  }
  // a depth of 0 or past the bound, a size not the depth's network
  CHECK_THROWS_WITH_AS(DigitClassifier(version4(0, widths, {})), "digit classifier: the weights file declares no or too many convolutions a stage",
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier(version4(4, widths, {})), "digit classifier: the weights file declares no or too many convolutions a stage",
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier(version4(2, {1, 1, 1, 1}, std::vector<float>(64))),
                       "digit classifier: the weights file's size is not its network's", std::runtime_error);
  CHECK_THROWS_WITH_AS(DigitClassifier("EPDG" + u32(4) + u32(0) + u32(1)), "digit classifier: not a version-2, 3 or 4 weights file (EPDG)",
                       std::runtime_error);
}
