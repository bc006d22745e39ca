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
// The most networks a version-3 file may hold: each costs a forward pass per cell.
constexpr std::uint32_t kMaxMembers = 8;

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

// One network from a version-2 file's bytes (exactly those: a member of a version-3 file is
// handed its own span).
DigitNetwork read_network(std::string_view b) {
  if (b.size() < kHeader || b.substr(0, 4) != "EPDG" || read_u32(b, 4) != 2)
    throw std::runtime_error("digit classifier: not a version-2 or 3 weights file (EPDG)");
  DigitNetwork net;
  const std::uint32_t count = read_u32(b, 8);
  net.shape = {read_u32(b, 12), read_u32(b, 16), read_u32(b, 20), read_u32(b, 24)};
  for (std::uint32_t width : {net.shape.conv1, net.shape.conv2, net.shape.conv3, net.shape.hidden})
    if (width == 0 || width > kMaxWidth) throw std::runtime_error("digit classifier: the weights file declares a layer of no or too many units");
  if (count != weight_count(net.shape) || b.size() != kHeader + 4 * static_cast<std::size_t>(count))
    throw std::runtime_error("digit classifier: the weights file's size is not its network's");
  net.w.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t bits = read_u32(b, kHeader + 4 * i);
    std::memcpy(&net.w[i], &bits, 4);
  }
  const std::size_t c1 = net.shape.conv1, c2 = net.shape.conv2, c3 = net.shape.conv3, h = net.shape.hidden;
  std::size_t at = 0;
  auto take = [&](std::size_t n) { const std::size_t here = at; at += n; return here; };
  net.conv1_w = take(c1 * 9); net.conv1_b = take(c1);
  net.conv2_w = take(c2 * c1 * 9); net.conv2_b = take(c2);
  net.conv3_w = take(c3 * c2 * 9); net.conv3_b = take(c3);
  net.fc1_w = take(h * c3 * 9); net.fc1_b = take(h);
  net.fc2_w = take(kClassCount * h); net.fc2_b = take(kClassCount);
  return net;
}

}  // namespace

char class_char(CellClass c) {
  const int i = static_cast<int>(c);
  if (i < 10) return static_cast<char>('0' + i);
  return c == CellClass::minus ? '-' : ' ';
}

DigitClassifier::DigitClassifier(std::string_view b) {
  if (b.size() >= 12 && b.substr(0, 4) == "EPDG" && read_u32(b, 4) == 3) {
    const std::uint32_t n = read_u32(b, 8);
    if (n == 0 || n > kMaxMembers) throw std::runtime_error("digit classifier: the weights file declares no or too many networks");
    std::size_t at = 12;
    for (std::uint32_t i = 0; i < n; ++i) {
      // each member's size from its own header, read only once that header is there
      const std::string_view rest = b.substr(at);
      const std::size_t size = rest.size() >= kHeader ? kHeader + 4 * static_cast<std::size_t>(read_u32(rest, 8)) : rest.size();
      nets_.push_back(read_network(rest.substr(0, std::min(size, rest.size()))));
      at += size;
    }
    if (at != b.size()) throw std::runtime_error("digit classifier: the weights file's size is not its networks'");
  } else {
    nets_.push_back(read_network(b));
  }
}

const DigitClassifier& DigitClassifier::builtin() {
  static const DigitClassifier net = [] {
    const auto data = embedded_data("classifier/digits.weights");
    if (!data) throw std::runtime_error("digit classifier: this binary carries no weights");
    return DigitClassifier(*data);
  }();
  return net;
}

std::array<float, kClassCount> DigitClassifier::logits(std::size_t member, const CellCrop& crop) const {
  const DigitNetwork& n = nets_.at(member);
  const std::vector<float>& w = n.w;
  const int c1 = static_cast<int>(n.shape.conv1), c2 = static_cast<int>(n.shape.conv2), c3 = static_cast<int>(n.shape.conv3);
  const std::size_t hidden = n.shape.hidden;
  std::array<float, kCropSide * kCropSide> in;
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = static_cast<float>(crop[i]) / 255.0f;
  std::vector<float> a1(static_cast<std::size_t>(c1) * 14 * 14), a2(static_cast<std::size_t>(c2) * 7 * 7),
      a3(static_cast<std::size_t>(c3) * 3 * 3), h(hidden);
  conv_relu_pool(in.data(), 1, 28, &w[n.conv1_w], &w[n.conv1_b], c1, a1.data());
  conv_relu_pool(a1.data(), c1, 14, &w[n.conv2_w], &w[n.conv2_b], c2, a2.data());
  conv_relu_pool(a2.data(), c2, 7, &w[n.conv3_w], &w[n.conv3_b], c3, a3.data());
  for (std::size_t j = 0; j < hidden; ++j) {
    float s = w[n.fc1_b + j];
    const float* row = &w[n.fc1_w + j * a3.size()];
    for (std::size_t i = 0; i < a3.size(); ++i) s += row[i] * a3[i];
    h[j] = std::max(s, 0.0f);
  }
  std::array<float, kClassCount> out;
  for (std::size_t c = 0; c < kClassCount; ++c) {
    float s = w[n.fc2_b + c];
    const float* row = &w[n.fc2_w + c * hidden];
    for (std::size_t i = 0; i < hidden; ++i) s += row[i] * h[i];
    out[c] = s;
  }
  return out;
}

CellReading DigitClassifier::classify(const CellCrop& crop) const {
  std::array<double, kClassCount> mean{};
  for (std::size_t m = 0; m < nets_.size(); ++m) {
    const auto z = logits(m, crop);
    const float top = *std::max_element(z.begin(), z.end());
    std::array<double, kClassCount> e;
    double sum = 0;
    for (std::size_t c = 0; c < kClassCount; ++c) sum += e[c] = std::exp(static_cast<double>(z[c] - top));
    for (std::size_t c = 0; c < kClassCount; ++c) mean[c] += e[c] / sum;
  }
  CellReading r;
  for (std::size_t c = 0; c < kClassCount; ++c) r.probability[c] = static_cast<float>(mean[c] / static_cast<double>(nets_.size()));
  const auto best = std::max_element(r.probability.begin(), r.probability.end());
  r.best = static_cast<CellClass>(best - r.probability.begin());
  r.confidence = *best;
  return r;
}

}  // namespace epure::scan
