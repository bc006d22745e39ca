#include "scan/digit_classifier.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "embed/embedded.h"

namespace epure::scan {

namespace {

// The network's shape (train_digits.py, class Net).
constexpr int kC1 = 16, kC2 = 32, kC3 = 64, kHidden = 64;
constexpr std::size_t kWeightCount = kC1 * 9 + kC1 + kC2 * kC1 * 9 + kC2 + kC3 * kC2 * 9 + kC3 +
                                     kHidden * kC3 * 9 + kHidden + kClassCount * kHidden + kClassCount;

std::uint32_t read_u32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

// A 3x3 convolution with a padding of 1, then ReLU, then a 2x2 max pool (floor): `in` is
// cin planes of side n, `out` cout planes of side n / 2.
void conv_relu_pool(const float* in, int cin, int n, const float* w, const float* b, int cout, float* out) {
  std::vector<float> plane(static_cast<std::size_t>(n * n));
  const int half = n / 2;
  for (int o = 0; o < cout; ++o) {
    std::fill(plane.begin(), plane.end(), b[o]);
    for (int i = 0; i < cin; ++i) {
      const float* k = w + (static_cast<std::ptrdiff_t>(o) * cin + i) * 9;
      const float* src = in + static_cast<std::ptrdiff_t>(i) * n * n;
      for (int y = 0; y < n; ++y) {
        float* row = plane.data() + static_cast<std::ptrdiff_t>(y) * n;
        for (int ky = 0; ky < 3; ++ky) {
          const int sy = y + ky - 1;
          if (sy < 0 || sy >= n) continue;
          const float* srow = src + static_cast<std::ptrdiff_t>(sy) * n;
          for (int kx = 0; kx < 3; ++kx) {
            const float kv = k[ky * 3 + kx];
            const int x0 = std::max(0, 1 - kx), x1 = std::min(n, n + 1 - kx);
            for (int x = x0; x < x1; ++x) row[x] += kv * srow[x + kx - 1];
          }
        }
      }
    }
    float* dst = out + static_cast<std::ptrdiff_t>(o) * half * half;
    for (int y = 0; y < half; ++y)
      for (int x = 0; x < half; ++x) {
        const float* p = plane.data() + static_cast<std::ptrdiff_t>(2 * y) * n + 2 * x;
        const float m = std::max(std::max(p[0], p[1]), std::max(p[n], p[n + 1]));
        dst[y * half + x] = std::max(m, 0.0f);  // ReLU and max commute
      }
  }
}

}  // namespace

char class_char(CellClass c) {
  const int i = static_cast<int>(c);
  if (i < 10) return static_cast<char>('0' + i);
  return c == CellClass::minus ? '-' : ' ';
}

DigitClassifier::DigitClassifier(std::string_view b) {
  if (b.size() < 12 || b.substr(0, 4) != "EPDG" || read_u32(b, 4) != 1)
    throw std::runtime_error("digit classifier: not a version-1 weights file (EPDG)");
  const std::uint32_t count = read_u32(b, 8);
  if (count != kWeightCount || b.size() != 12 + 4 * static_cast<std::size_t>(count))
    throw std::runtime_error("digit classifier: the weights file holds another network");
  w_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t bits = read_u32(b, 12 + 4 * i);
    std::memcpy(&w_[i], &bits, 4);
  }
  std::size_t at = 0;
  auto take = [&](std::size_t n) { const std::size_t here = at; at += n; return here; };
  conv1_w_ = take(kC1 * 9); conv1_b_ = take(kC1);
  conv2_w_ = take(kC2 * kC1 * 9); conv2_b_ = take(kC2);
  conv3_w_ = take(kC3 * kC2 * 9); conv3_b_ = take(kC3);
  fc1_w_ = take(kHidden * kC3 * 9); fc1_b_ = take(kHidden);
  fc2_w_ = take(kClassCount * kHidden); fc2_b_ = take(kClassCount);
}

const DigitClassifier& DigitClassifier::builtin() {
  static const DigitClassifier net = [] {
    const auto data = embedded_data("classifier/digits.weights");
    if (!data) throw std::runtime_error("digit classifier: this binary carries no weights");
    return DigitClassifier(*data);
  }();
  return net;
}

std::array<float, kClassCount> DigitClassifier::logits(const CellCrop& crop) const {
  std::array<float, kCropSide * kCropSide> in;
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = static_cast<float>(crop[i]) / 255.0f;
  std::array<float, kC1 * 14 * 14> a1;
  std::array<float, kC2 * 7 * 7> a2;
  std::array<float, kC3 * 3 * 3> a3;
  conv_relu_pool(in.data(), 1, 28, &w_[conv1_w_], &w_[conv1_b_], kC1, a1.data());
  conv_relu_pool(a1.data(), kC1, 14, &w_[conv2_w_], &w_[conv2_b_], kC2, a2.data());
  conv_relu_pool(a2.data(), kC2, 7, &w_[conv3_w_], &w_[conv3_b_], kC3, a3.data());
  std::array<float, kHidden> h;
  for (int j = 0; j < kHidden; ++j) {
    float s = w_[fc1_b_ + static_cast<std::size_t>(j)];
    const float* row = &w_[fc1_w_ + static_cast<std::size_t>(j) * a3.size()];
    for (std::size_t i = 0; i < a3.size(); ++i) s += row[i] * a3[i];
    h[static_cast<std::size_t>(j)] = std::max(s, 0.0f);
  }
  std::array<float, kClassCount> out;
  for (int c = 0; c < kClassCount; ++c) {
    float s = w_[fc2_b_ + static_cast<std::size_t>(c)];
    const float* row = &w_[fc2_w_ + static_cast<std::size_t>(c) * kHidden];
    for (int i = 0; i < kHidden; ++i) s += row[i] * h[static_cast<std::size_t>(i)];
    out[static_cast<std::size_t>(c)] = s;
  }
  return out;
}

CellReading DigitClassifier::classify(const CellCrop& crop) const {
  const auto z = logits(crop);
  const float top = *std::max_element(z.begin(), z.end());
  CellReading r;
  double sum = 0;
  std::array<double, kClassCount> e;
  for (int c = 0; c < kClassCount; ++c) sum += e[static_cast<std::size_t>(c)] = std::exp(static_cast<double>(z[static_cast<std::size_t>(c)] - top));
  for (int c = 0; c < kClassCount; ++c) r.probability[static_cast<std::size_t>(c)] = static_cast<float>(e[static_cast<std::size_t>(c)] / sum);
  const auto best = std::max_element(r.probability.begin(), r.probability.end());
  r.best = static_cast<CellClass>(best - r.probability.begin());
  r.confidence = *best;
  return r;
}

}  // namespace epure::scan
