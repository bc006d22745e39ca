#pragma once
// The comb-cell classifier: a small convolutional network (train_digits.py beside it in
// classifier/ trains it on the mnist package's handwritten digits and writes its weights) that
// reads one cell's crop as a digit 0-9, a minus sign or an empty cell.
//
// The forward pass is written here (about a hundred lines) rather than run by OpenCV's dnn
// module: the network is small (conv 32, 64, 128 channels, 128 hidden units: 241,804 weights,
// 7.6 M multiply-adds a cell, batch norm folded into the convolutions), dnn would bring
// protobuf and a model-format exporter for it, and its kernels are chosen per CPU (SIMD widths,
// Winograd), so the same crop could give other bits on another machine. Here every sum runs in
// one fixed order in float with no contraction (-ffp-contract=off): the same crop gives the same
// probabilities on every run and every x86-64 or ARM machine.
#include <array>
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

// The character a class stands for: '0'-'9', '-', or ' ' for empty.
char class_char(CellClass c);

// The network's widths, as the weights file declares them: three 3x3 convolutions (each followed
// by ReLU and a 2x2 max pool: 28 -> 14 -> 7 -> 3), a hidden layer, the 12 classes.
struct NetShape {
  std::uint32_t conv1 = 0, conv2 = 0, conv3 = 0, hidden = 0;
};

class DigitClassifier {
 public:
  // The weights file's bytes: "EPDG", u32 version 2, u32 count, u32 conv1, conv2, conv3 and hidden
  // widths, then count float32 (all little endian): conv1 weights (conv1 x 1 x 3 x 3) and biases,
  // conv2's (conv2 x conv1 x 3 x 3), conv3's, fc1's (hidden x conv3·9), fc2's (12 x hidden).
  // Throws std::runtime_error when they are not a version-2 weights file whose size is its
  // network's (version 1, the first network's 16-32-64-64 with no widths in the header, is no
  // longer read: train_digits.py writes version 2).
  explicit DigitClassifier(std::string_view weights);
  // The network epure carries (classifier/digits.weights, compiled in).
  static const DigitClassifier& builtin();

  CellReading classify(const CellCrop& crop) const;
  // The network's raw outputs (before the softmax), for the test against train_digits.py.
  std::array<float, kClassCount> logits(const CellCrop& crop) const;

  NetShape shape() const { return shape_; }

 private:
  NetShape shape_;
  std::vector<float> w_;  // every layer's weights and biases, in the file's order
  std::size_t conv1_w_, conv1_b_, conv2_w_, conv2_b_, conv3_w_, conv3_b_, fc1_w_, fc1_b_, fc2_w_, fc2_b_;
};

}  // namespace epure::scan
