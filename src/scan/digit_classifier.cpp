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
constexpr std::size_t kHeader = 28;  // "EPDG", version 2, count, the four widths
constexpr std::size_t kHeader4 = 32;  // "EPDG", version 4, count, depth, the four widths
// The most convolutions a stage may hold in a version-4 file.
constexpr std::uint32_t kMaxDepth = 3;
// The most networks a version-3 file may hold: each costs a forward pass per cell.
constexpr std::uint32_t kMaxMembers = 8;

// The stages' widths in order, each `depth` times: the convolutions a shape declares.
std::vector<std::uint32_t> conv_widths(const NetShape& s) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t width : {s.conv1, s.conv2, s.conv3})
    for (std::uint32_t k = 0; k < s.depth; ++k) out.push_back(width);
  return out;
}

std::size_t weight_count(const NetShape& s) {
  std::size_t n = 0, cin = 1;
  for (std::size_t c : conv_widths(s)) {
    n += c * cin * 9 + c;
    cin = c;
  }
  const std::size_t h = s.hidden;
  return n + h * cin * 9 + h + kClassCount * h + kClassCount;
}

std::uint32_t read_u32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}

// Four or eight floats as one value: GCC's and Clang's vector types (elementwise IEEE
// arithmetic, no contraction), which the compiler keeps in registers where it did not keep
// arrays.
typedef float Lanes4 __attribute__((vector_size(16)));
typedef float Lanes8 __attribute__((vector_size(32)));

// The convolution as a small matrix product, out[o][p] = b[o] + Σ_t k[o][t]·col[t][p] (t < taps,
// p < area), kPlanes output planes by kVectors vectors of pixels at a time: their sums stay in
// registers over all the taps and each tap's pixels are loaded once for all the block's planes
// (one plane at a time, every multiply-add loaded and stored its sum). Each sum starts from its
// bias and adds its terms in tap order, rounded in turn, whatever the block's shape: the same
// bits as a direct convolution, on every machine.
template <int kPlanes, int kVectors, typename Lanes>
__attribute__((always_inline)) inline void product(const float* col, std::size_t taps, std::size_t area, const float* w,
                                                   const float* b, int cout, float* planes) {
  constexpr std::size_t kLanes = sizeof(Lanes) / sizeof(float);
  constexpr std::size_t kPixels = kVectors * kLanes;
  for (int o0 = 0; o0 < cout; o0 += kPlanes) {
    const int no = std::min(kPlanes, cout - o0);
    for (std::size_t p0 = 0; p0 < area; p0 += kPixels) {
      const std::size_t np = std::min(kPixels, area - p0);
      if (no == kPlanes && np == kPixels) {
        Lanes acc[kPlanes][kVectors];
        for (int j = 0; j < kPlanes; ++j)
          for (int v = 0; v < kVectors; ++v) acc[j][v] = b[o0 + j] - Lanes{};  // x - +0 is x, a -0 bias too
        const float* k0 = w + static_cast<std::ptrdiff_t>(o0) * static_cast<std::ptrdiff_t>(taps);
        for (std::size_t t = 0; t < taps; ++t) {
#pragma GCC unroll 2
          for (int v = 0; v < kVectors; ++v) {
            Lanes x;
            std::memcpy(&x, col + t * area + p0 + static_cast<std::size_t>(v) * kLanes, sizeof x);
#pragma GCC unroll 8
            for (int j = 0; j < kPlanes; ++j) acc[j][v] += k0[static_cast<std::size_t>(j) * taps + t] * x;
          }
        }
        for (int j = 0; j < kPlanes; ++j)
          std::memcpy(planes + static_cast<std::size_t>(o0 + j) * area + p0, acc[j], sizeof acc[j]);
      } else {  // the edges: fewer planes or pixels left than a block, a sum at a time in a register
        for (int j = 0; j < no; ++j) {
          float* pl = planes + static_cast<std::size_t>(o0 + j) * area + p0;
          const float* k = w + static_cast<std::ptrdiff_t>(o0 + j) * static_cast<std::ptrdiff_t>(taps);
          for (std::size_t q = 0; q < np; ++q) {
            float sum = b[o0 + j];
            for (std::size_t t = 0; t < taps; ++t) sum += k[t] * col[t * area + p0 + q];
            pl[q] = sum;
          }
        }
      }
    }
  }
}

// The product takes nearly all of a scan's time. x86-64's baseline (SSE2: 16 registers of four
// floats) holds four planes by eight pixels; a CPU with AVX2 (16 registers of eight) runs it
// eight planes by eight pixels, a third less time than the baseline's (`epure scan --jobs 1` of 24
// sheets at 200 dpi: 14.9 -> 10.0 s of CPU; main's code, four planes without the unrolling,
// 16.6-17.0 s). Both are the same sums in the same order.
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void product_avx2(const float* col, std::size_t taps, std::size_t area, const float* w,
                                                  const float* b, int cout, float* planes) {
  product<8, 1, Lanes8>(col, taps, area, w, b, cout, planes);
}
#endif

bool cpu_has_avx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return false;
#endif
}

void conv_product(const float* col, std::size_t taps, std::size_t area, const float* w, const float* b, int cout, [[maybe_unused]] bool wide,
                  float* planes) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (wide) return product_avx2(col, taps, area, w, b, cout, planes);
#endif
  product<4, 2, Lanes4>(col, taps, area, w, b, cout, planes);
}

// A 3x3 convolution with a padding of 1, then ReLU, then (when `pool`) a 2x2 max pool (floor):
// `in` is cin planes of side n, `out` cout planes of side n / 2 (n without the pool).
//
// The input's 3x3 neighbourhoods are laid out first (im2col: row k = 9 i + 3 ky + kx holds input
// plane i shifted by (kx - 1, ky - 1), zeros past the border), so that the convolution is a
// matrix product over contiguous rows (below), where a row of the image at a time (28, 14, 7)
// was mostly loop overhead. Every output
// pixel still sums its bias, then its terms in the order i, ky, kx, each rounded in turn: the
// padding's terms add a zero, which leaves a sum as it was, so the logits are the same bits as
// a direct convolution's (and the same on every machine).
void conv_relu(const float* in, int cin, int n, const float* w, const float* b, int cout, bool pool, bool wide, float* out) {
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
  std::vector<float> planes(static_cast<std::size_t>(cout) * area);
  conv_product(col.data(), taps, area, w, b, cout, wide, planes.data());
  const int half = n / 2;
  for (int o = 0; o < cout; ++o) {
    const float* plane = planes.data() + static_cast<std::size_t>(o) * area;
    if (!pool) {
      float* dst = out + static_cast<std::ptrdiff_t>(o) * static_cast<std::ptrdiff_t>(area);
      for (std::size_t p = 0; p < area; ++p) dst[p] = std::max(plane[p], 0.0f);
      continue;
    }
    float* dst = out + static_cast<std::ptrdiff_t>(o) * half * half;
    for (int y = 0; y < half; ++y)
      for (int x = 0; x < half; ++x) {
        const float* p = plane + static_cast<std::ptrdiff_t>(2 * y) * n + 2 * x;
        const float m = std::max(std::max(p[0], p[1]), std::max(p[n], p[n + 1]));
        dst[y * half + x] = std::max(m, 0.0f);  // ReLU and max commute
      }
  }
}

// One network from a version-2 or version-4 file's bytes (exactly those: a member of a version-3
// file is handed its own span).
DigitNetwork read_network(std::string_view b) {
  const std::uint32_t version = b.size() >= 8 && b.substr(0, 4) == "EPDG" ? read_u32(b, 4) : 0;
  const std::size_t header = version == 4 ? kHeader4 : kHeader;
  if ((version != 2 && version != 4) || b.size() < header)
    throw std::runtime_error("digit classifier: not a version-2, 3 or 4 weights file (EPDG)");
  DigitNetwork net;
  const std::uint32_t count = read_u32(b, 8);
  const std::size_t widths = version == 4 ? 16 : 12;
  net.shape = {read_u32(b, widths), read_u32(b, widths + 4), read_u32(b, widths + 8), read_u32(b, widths + 12), version == 4 ? read_u32(b, 12) : 1};
  if (net.shape.depth == 0 || net.shape.depth > kMaxDepth)
    throw std::runtime_error("digit classifier: the weights file declares no or too many convolutions a stage");
  for (std::uint32_t width : {net.shape.conv1, net.shape.conv2, net.shape.conv3, net.shape.hidden})
    if (width == 0 || width > kMaxWidth) throw std::runtime_error("digit classifier: the weights file declares a layer of no or too many units");
  if (count != weight_count(net.shape) || b.size() != header + 4 * static_cast<std::size_t>(count))
    throw std::runtime_error("digit classifier: the weights file's size is not its network's");
  net.w.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t bits = read_u32(b, header + 4 * i);
    std::memcpy(&net.w[i], &bits, 4);
  }
  std::size_t at = 0;
  auto take = [&](std::size_t n) { const std::size_t here = at; at += n; return here; };
  const std::vector<std::uint32_t> convs = conv_widths(net.shape);
  int cin = 1;
  for (std::size_t i = 0; i < convs.size(); ++i) {
    ConvLayer layer;
    layer.cin = cin;
    layer.cout = static_cast<int>(convs[i]);
    layer.w = take(static_cast<std::size_t>(layer.cout) * static_cast<std::size_t>(cin) * 9);
    layer.b = take(static_cast<std::size_t>(layer.cout));
    layer.pool = (i + 1) % net.shape.depth == 0;  // a stage's last convolution
    net.convs.push_back(layer);
    cin = layer.cout;
  }
  const std::size_t h = net.shape.hidden, c3 = net.shape.conv3;
  net.fc1_w = take(h * c3 * 9); net.fc1_b = take(h);
  // fc1's weights by input, then by hidden unit (see logits)
  const std::size_t flat = c3 * 9;
  net.fc1_by_input.resize(h * flat);
  for (std::size_t j = 0; j < h; ++j)
    for (std::size_t i = 0; i < flat; ++i) net.fc1_by_input[i * h + j] = net.w[net.fc1_w + j * flat + i];
  net.fc2_w = take(kClassCount * h); net.fc2_b = take(kClassCount);
  return net;
}

}  // namespace

char class_char(CellClass c) {
  const int i = static_cast<int>(c);
  if (i < 10) return static_cast<char>('0' + i);
  return c == CellClass::minus ? '-' : ' ';
}

DigitClassifier::DigitClassifier(std::string_view b, Product product) : wide_(product == Product::best && cpu_has_avx2()) {
  if (b.size() >= 12 && b.substr(0, 4) == "EPDG" && read_u32(b, 4) == 3) {
    const std::uint32_t n = read_u32(b, 8);
    if (n == 0 || n > kMaxMembers) throw std::runtime_error("digit classifier: the weights file declares no or too many networks");
    std::size_t at = 12;
    for (std::uint32_t i = 0; i < n; ++i) {
      // each member's size from its own header, read only once that header is there
      const std::string_view rest = b.substr(at);
      const std::size_t header = rest.size() >= 8 && read_u32(rest, 4) == 4 ? kHeader4 : kHeader;
      const std::size_t size = rest.size() >= header ? header + 4 * static_cast<std::size_t>(read_u32(rest, 8)) : rest.size();
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
  const std::size_t hidden = n.shape.hidden;
  // the activations between layers, in two buffers used in turn
  std::vector<float> a(static_cast<std::size_t>(kCropSide) * kCropSide), next, h(hidden);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<float>(crop[i]) / 255.0f;
  int side = kCropSide;
  for (const ConvLayer& c : n.convs) {
    const int out_side = c.pool ? side / 2 : side;
    next.assign(static_cast<std::size_t>(c.cout) * static_cast<std::size_t>(out_side) * static_cast<std::size_t>(out_side), 0.0f);
    conv_relu(a.data(), c.cin, side, &w[c.w], &w[c.b], c.cout, c.pool, wide_, next.data());
    std::swap(a, next);
    side = out_side;
  }
  const std::vector<float>& a3 = a;  // conv3 planes of 3 x 3
  // The hidden layer: each unit's sum is one long chain of additions (1,152 terms), so eight units
  // are summed side by side, from fc1's weights laid out by input: the additions of one unit
  // wait on each other, not on those of the next. Each sum keeps its order, so its bits.
  const std::size_t flat = a3.size();
  std::size_t j0 = 0;
  for (; j0 + 8 <= hidden; j0 += 8) {
    // two registers of four (a Lanes8 outside the AVX2 function goes through memory)
    Lanes4 lo, hi;
    std::memcpy(&lo, &w[n.fc1_b + j0], sizeof lo);
    std::memcpy(&hi, &w[n.fc1_b + j0 + 4], sizeof hi);
    for (std::size_t i = 0; i < flat; ++i) {
      const float* k = &n.fc1_by_input[i * hidden + j0];
      Lanes4 klo, khi;
      std::memcpy(&klo, k, sizeof klo);
      std::memcpy(&khi, k + 4, sizeof khi);
      lo += klo * a3[i];
      hi += khi * a3[i];
    }
    for (std::size_t q = 0; q < 4; ++q) {
      h[j0 + q] = std::max(lo[q], 0.0f);
      h[j0 + 4 + q] = std::max(hi[q], 0.0f);
    }
  }
  for (std::size_t j = j0; j < hidden; ++j) {
    float s = w[n.fc1_b + j];
    const float* row = &w[n.fc1_w + j * flat];
    for (std::size_t i = 0; i < flat; ++i) s += row[i] * a3[i];
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
  std::array<float, kClassCount> p;
  for (std::size_t c = 0; c < kClassCount; ++c) p[c] = static_cast<float>(mean[c] / static_cast<double>(nets_.size()));
  return reading_of(p);
}

CellReading reading_of(const std::array<float, kClassCount>& probability) {
  CellReading r;
  r.probability = probability;
  const auto best = std::max_element(r.probability.begin(), r.probability.end());
  r.best = static_cast<CellClass>(best - r.probability.begin());
  r.confidence = *best;
  return r;
}

}  // namespace epure::scan
