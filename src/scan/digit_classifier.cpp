#include "scan/digit_classifier.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "embed/embedded.h"

namespace epure::scan {

namespace {

// The largest layer a weights file may declare: a bound on what a damaged or foreign file makes
// us allocate, far above any network worth running per cell.
constexpr std::uint32_t kMaxWidth = 1024;
constexpr std::size_t kHeader = 28;  // "EPDG", version, count, the four widths

std::size_t weight_count(const NetShape& s) {
  const std::size_t c1 = s.conv1, c2 = s.conv2, c3 = s.conv3, h = s.hidden;
  return c1 * 9 + c1 + c2 * c1 * 9 + c2 + c3 * c2 * 9 + c3 + h * c3 * 9 + h + kClassCount * h + kClassCount;
}

std::uint32_t read_u32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

// A 3x3 convolution with a padding of 1, then ReLU, then a 2x2 max pool (floor): `in` is
// cin planes of side n, `out` cout planes of side n / 2.
//
// The input's 3x3 neighbourhoods are laid out first (im2col: row k = 9 i + 3 ky + kx holds input
// plane i shifted by (kx - 1, ky - 1), zeros past the border), so that each output plane is
// cin x 9 passes of one multiply-add over the whole plane: loops of n² (784, 196, 49) the
// compiler vectorises, where a row at a time (28, 14, 7) was mostly loop overhead. Every output
// pixel still sums its bias, then its terms in the order i, ky, kx, each rounded in turn: the
// padding's terms add a zero, which leaves a sum as it was, so the logits are the same bits as
// a direct convolution's (and the same on every machine).
void conv_relu_pool(const float* in, int cin, int n, const float* w, const float* b, int cout, float* out) {
  const std::size_t area = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const std::size_t taps = static_cast<std::size_t>(cin) * 9;
  std::vector<float> col(taps * area, 0.0f);
  for (int i = 0; i < cin; ++i) {
    const float* src = in + static_cast<std::ptrdiff_t>(i) * n * n;
    for (int ky = 0; ky < 3; ++ky)
      for (int kx = 0; kx < 3; ++kx) {
        float* row = col.data() + (static_cast<std::size_t>(i) * 9 + static_cast<std::size_t>(ky * 3 + kx)) * area;
        for (int y = 0; y < n; ++y) {
          const int sy = y + ky - 1;
          if (sy < 0 || sy >= n) continue;
          const int x0 = std::max(0, 1 - kx), x1 = std::min(n, n + 1 - kx);
          for (int x = x0; x < x1; ++x) row[y * n + x] = src[sy * n + x + kx - 1];
        }
      }
  }
  std::vector<float> plane(area);
  const int half = n / 2;
  for (int o = 0; o < cout; ++o) {
    std::fill(plane.begin(), plane.end(), b[o]);
    const float* k = w + static_cast<std::ptrdiff_t>(o) * static_cast<std::ptrdiff_t>(taps);
    for (std::size_t t = 0; t < taps; ++t) {
      const float kv = k[t];
      const float* c = col.data() + t * area;
      float* pl = plane.data();
      for (std::size_t p = 0; p < area; ++p) pl[p] += kv * c[p];
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
  if (b.size() < kHeader || b.substr(0, 4) != "EPDG" || read_u32(b, 4) != 2)
    throw std::runtime_error("digit classifier: not a version-2 weights file (EPDG)");
  const std::uint32_t count = read_u32(b, 8);
  shape_ = {read_u32(b, 12), read_u32(b, 16), read_u32(b, 20), read_u32(b, 24)};
  for (std::uint32_t width : {shape_.conv1, shape_.conv2, shape_.conv3, shape_.hidden})
    if (width == 0 || width > kMaxWidth) throw std::runtime_error("digit classifier: the weights file declares a layer of no or too many units");
  if (count != weight_count(shape_) || b.size() != kHeader + 4 * static_cast<std::size_t>(count))
    throw std::runtime_error("digit classifier: the weights file's size is not its network's");
  w_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t bits = read_u32(b, kHeader + 4 * i);
    std::memcpy(&w_[i], &bits, 4);
  }
  const std::size_t c1 = shape_.conv1, c2 = shape_.conv2, c3 = shape_.conv3, h = shape_.hidden;
  std::size_t at = 0;
  auto take = [&](std::size_t n) { const std::size_t here = at; at += n; return here; };
  conv1_w_ = take(c1 * 9); conv1_b_ = take(c1);
  conv2_w_ = take(c2 * c1 * 9); conv2_b_ = take(c2);
  conv3_w_ = take(c3 * c2 * 9); conv3_b_ = take(c3);
  fc1_w_ = take(h * c3 * 9); fc1_b_ = take(h);
  fc2_w_ = take(kClassCount * h); fc2_b_ = take(kClassCount);
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
  const int c1 = static_cast<int>(shape_.conv1), c2 = static_cast<int>(shape_.conv2), c3 = static_cast<int>(shape_.conv3);
  const std::size_t hidden = shape_.hidden;
  std::array<float, kCropSide * kCropSide> in;
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = static_cast<float>(crop[i]) / 255.0f;
  std::vector<float> a1(static_cast<std::size_t>(c1) * 14 * 14), a2(static_cast<std::size_t>(c2) * 7 * 7),
      a3(static_cast<std::size_t>(c3) * 3 * 3), h(hidden);
  conv_relu_pool(in.data(), 1, 28, &w_[conv1_w_], &w_[conv1_b_], c1, a1.data());
  conv_relu_pool(a1.data(), c1, 14, &w_[conv2_w_], &w_[conv2_b_], c2, a2.data());
  conv_relu_pool(a2.data(), c2, 7, &w_[conv3_w_], &w_[conv3_b_], c3, a3.data());
  for (std::size_t j = 0; j < hidden; ++j) {
    float s = w_[fc1_b_ + j];
    const float* row = &w_[fc1_w_ + j * a3.size()];
    for (std::size_t i = 0; i < a3.size(); ++i) s += row[i] * a3[i];
    h[j] = std::max(s, 0.0f);
  }
  std::array<float, kClassCount> out;
  for (std::size_t c = 0; c < kClassCount; ++c) {
    float s = w_[fc2_b_ + c];
    const float* row = &w_[fc2_w_ + c * hidden];
    for (std::size_t i = 0; i < hidden; ++i) s += row[i] * h[i];
    out[c] = s;
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
