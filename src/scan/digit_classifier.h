#pragma once
// The comb-cell classifier: small convolutional networks whose probabilities are averaged
// (train_digits.py beside it in classifier/ trains them on the mnist package's handwritten digits
// and writes their weights), reading one cell's crop as a digit 0-9, a minus sign or an empty
// cell.
//
// The forward pass is written here (about a hundred and fifty lines) rather than run by
// OpenCV's dnn module: each network is small (three stages of two 3x3 convolutions of 32, 64 and
// 128 channels, 128 hidden units: 435,564 weights, 29.3 M multiply-adds a cell, batch norm folded
// into the convolutions), dnn would bring protobuf and a model-format exporter for it, and its
// kernels are chosen per CPU (SIMD widths, Winograd), so the same crop could give other bits on
// another machine. Here every sum runs in one fixed order in float with no contraction
// (-ffp-contract=off): the same crop gives the same probabilities on every run and every x86-64
// or ARM machine, whether the convolutions run eight floats a register (AVX2, where the CPU has
// it) or four (x86-64's baseline, ARM).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace epure::scan {

inline constexpr int kCropSide = 28;
inline constexpr int kClassCount = 12;
enum class CellClass : std::uint8_t { d0, d1, d2, d3, d4, d5, d6, d7, d8, d9, minus, empty };

// A cell as the network reads it: ink from 0 (paper) to 255 (full ink), row by row, the cell
// centred as train_digits.py describes (crop_geometry in comb_reader.h makes it).
using CellCrop = std::array<std::uint8_t, kCropSide * kCropSide>;

struct CellReading {
  CellClass best = CellClass::empty;
  float confidence = 0;  // the best class's probability
  std::array<float, kClassCount> probability{};
};

// A reading from its classes' probabilities: the likeliest class (the first of equals) and its
// probability.
CellReading reading_of(const std::array<float, kClassCount>& probability);

// The character a class stands for: '0'-'9', '-', or ' ' for empty.
char class_char(CellClass c);

// The network's widths, as the weights file declares them: three stages of `depth` 3x3
// convolutions of one width each (each followed by ReLU; a stage ends with a 2x2 max pool:
// 28 -> 14 -> 7 -> 3), a hidden layer, the 12 classes.
struct NetShape {
  std::uint32_t conv1 = 0, conv2 = 0, conv3 = 0, hidden = 0;
  std::uint32_t depth = 1;  // convolutions a stage (a version-2 file's: 1)
};

// One 3x3 convolution of a network (padding 1, then ReLU), where its weights and biases start in
// the network's floats, and whether a 2x2 max pool follows it.
struct ConvLayer {
  std::size_t w = 0, b = 0;
  int cin = 0, cout = 0;
  bool pool = false;
};

// One trained network: its widths and every layer's weights and biases, in the file's order.
struct DigitNetwork {
  NetShape shape;
  std::vector<float> w;
  std::vector<ConvLayer> convs;
  std::size_t fc1_w, fc1_b, fc2_w, fc2_b;
  std::vector<float> fc1_by_input;  // fc1's weights again, input by input (hidden units side by side)
};

// A deep ensemble: several networks of one architecture trained from other seeds (or other
// augmentations), whose probabilities are averaged. Members disagree most on the ambiguous
// digits, so the mean's best probability falls on them: an ensemble is better calibrated than
// any one member, which is what sending uncertain cells to review needs.
class DigitClassifier {
 public:
  // The weights file's bytes, version 3: "EPDG", u32 version 3, u32 member count (1 to 8), then
  // each member as a version-2 or version-4 file. Version 2: "EPDG", u32 version 2, u32 count, u32
  // conv1, conv2, conv3 and hidden widths, then count float32 (all little endian): conv1 weights
  // (conv1 x 1 x 3 x 3) and biases, conv2's (conv2 x conv1 x 3 x 3), conv3's, fc1's
  // (hidden x conv3·9), fc2's (12 x hidden). Version 4, stages of several convolutions: "EPDG",
  // u32 version 4, u32 count, u32 depth (1 to 3), the four widths, then for each stage of width
  // c and each of its `depth` convolutions its weights (c x cin x 3 x 3, cin the width of the
  // convolution before, 1 at first) and biases (c), then fc1 and fc2 as in version 2. A version-2 or
  // version-4 file alone is read as a one-network ensemble. Throws std::runtime_error when the
  // bytes are not that (version 1, the first network's 16-32-64-64 with no widths in the header,
  // is no longer read).
  //
  // `product`: how the convolutions run, best (eight floats a register where the CPU has AVX2,
  // four otherwise) or baseline (four, on every x86-64): the same bits, AVX2's in a third less
  // time; baseline is there for the test of both.
  enum class Product { best, baseline };
  explicit DigitClassifier(std::string_view weights, Product product = Product::best);
  // Whether the convolutions run AVX2's product (Product::best on a CPU that has it).
  bool wide() const { return wide_; }
  // The networks epure carries (classifier/digits.weights, compiled in).
  static const DigitClassifier& builtin();

  // The members' probabilities (each a softmax of its logits, in double), summed in the file's
  // order and divided by their count: the same crop gives the same bits on every run.
  CellReading classify(const CellCrop& crop) const;
  // One member's raw outputs (before the softmax), for the test against train_digits.py.
  std::array<float, kClassCount> logits(std::size_t member, const CellCrop& crop) const;

  std::size_t members() const { return nets_.size(); }
  NetShape shape(std::size_t member) const { return nets_.at(member).shape; }

 private:
  std::vector<DigitNetwork> nets_;
  bool wide_ = false;  // the convolutions' AVX2 product
};

}  // namespace epure::scan
