#pragma once
// The comb-cell classifier: a small convolutional network (train_digits.py beside it in
// classifier/ trains it on the mnist package's handwritten digits and writes its weights) that
// reads one cell's crop as a digit 0-9, a minus sign or an empty cell.
//
// The forward pass is written here (about a hundred lines) rather than run by OpenCV's dnn
// module: the network is tiny (61,000 weights, 2 M multiply-adds a cell), dnn would bring
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

class DigitClassifier {
 public:
  // The weights file's bytes ("EPDG", version 1, count, float32 little endian); throws
  // std::runtime_error when they are not a version-1 weights file of the right size.
  explicit DigitClassifier(std::string_view weights);
  // The network epure carries (classifier/digits.weights, compiled in).
  static const DigitClassifier& builtin();

  CellReading classify(const CellCrop& crop) const;
  // The network's raw outputs (before the softmax), for the test against train_digits.py.
  std::array<float, kClassCount> logits(const CellCrop& crop) const;

 private:
  std::vector<float> w_;  // every layer's weights and biases, in the file's order
  std::size_t conv1_w_, conv1_b_, conv2_w_, conv2_b_, conv3_w_, conv3_b_, fc1_w_, fc1_b_, fc2_w_, fc2_b_;
};

}  // namespace epure::scan
