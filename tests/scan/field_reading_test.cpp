#include <doctest/doctest.h>

#include <opencv2/imgproc.hpp>

#include <cstdint>
#include <cstring>
#include <string>

#include "scan/field_reading.h"

using namespace epure::scan;

namespace {

std::string u32(std::uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
  return s;
}

// A small network of random weights in ±amplitude (a fixed LCG: the same on every machine), the
// bias of class 3's output raised by `sure`. Weights in ±0.5 and no raise: unsure of every crop,
// so that every written cell gets the second look. Weights in ±0.1 and a raise of 6: a 3 over
// 0.90 whatever the crop, in readings that still differ from crop to crop.
DigitClassifier random_network(float amplitude, float sure) {
  const std::uint32_t c = 4, hidden = 8;
  const std::uint32_t count = (c * 9 + c) + 2 * (c * c * 9 + c) + (hidden * c * 9 + hidden) + (12 * hidden + 12);
  std::string b = "EPDG" + u32(2) + u32(count) + u32(c) + u32(c) + u32(c) + u32(hidden);
  std::uint64_t state = 20261206;
  for (std::uint32_t i = 0; i < count; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    float w = amplitude * 2 * static_cast<float>(static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24) - 0.5);
    if (i == count - 12 + 3) w += sure;  // fc2's biases are the file's last 12 floats
    std::uint32_t bits;
    std::memcpy(&bits, &w, 4);
    b += u32(bits);
  }
  return DigitClassifier(b);
}

}  // namespace

namespace {

// A page at 4 pixels a point: a comb of three cells (18 pt high, printed borders 1 pt wide in
// full ink on white paper), a stroke in the first, a ring in the second, the third empty.
struct CombPage {
  static constexpr double kScale = 4;
  PageMap map;
  FieldLayout field;
  cv::Mat page{240, 400, CV_8U, cv::Scalar(255)};
  // the ink levels read_field measures on this page: paper 255, the borders' and full ink 0
  InkLevels levels{255, 0, 0};
  CombPage() {
    map.h = cv::Matx33d(kScale, 0, 0, 0, kScale, 0, 0, 0, 1);
    field.question = "q";
    field.type = FieldType::comb;
    for (int i = 0; i < 3; ++i) field.cells.push_back(Rect{20.0 + 14 * i, 20, 14, 18});
    auto px = [](double x, double y) { return cv::Point(static_cast<int>(x * kScale), static_cast<int>(y * kScale)); };
    for (const Rect& c : field.cells) cv::rectangle(page, px(c.x, c.y), px(c.x + c.width, c.y + c.height), cv::Scalar(0), 4);
    cv::line(page, px(25, 24), px(29, 35), cv::Scalar(20), 6);
    cv::circle(page, px(41, 29), 18, cv::Scalar(20), 6);
  }
  FieldReading read(const DigitClassifier& net) const { return read_field(page, map, field, 255, -1, ",", net); }
  // Cell i's reading from its crop alone.
  CellReading first_reading(const DigitClassifier& net, std::size_t i) const {
    return net.classify(crop_cell(page, map, field.cells[i], levels));
  }
  // The five readings' mean (the crop, then moved left, right, up, down), as second_look takes it.
  CellReading five_readings(const DigitClassifier& net, const Rect& cell) const {
    std::array<double, kClassCount> sum{};
    const double s = kSecondLookShift * cell.height;
    for (const auto& d : {std::array<double, 2>{0, 0}, {-s, 0}, {s, 0}, {0, -s}, {0, s}}) {
      const CellReading r = net.classify(crop_cell(page, map, Rect{cell.x + d[0], cell.y + d[1], cell.width, cell.height}, levels));
      for (std::size_t c = 0; c < kClassCount; ++c) sum[c] += r.probability[c];
    }
    CellReading out;
    std::size_t best = 0;
    for (std::size_t c = 0; c < kClassCount; ++c) {
      out.probability[c] = static_cast<float>(sum[c] / 5);
      if (out.probability[c] > out.probability[best]) best = c;
    }
    out.best = static_cast<CellClass>(best);
    out.confidence = out.probability[best];
    return out;
  }
};

}  // namespace

TEST_CASE("comb cells: a cell read under kSecondLook is read again from four moved crops, the five readings averaged") {
  const CombPage p;
  const DigitClassifier net = random_network(0.5f, 0);
  const FieldReading r = p.read(net);
  REQUIRE(r.cells.size() == 3);
  for (std::size_t i = 0; i < 2; ++i) {
    CAPTURE(i);
    const CellReading first = p.first_reading(net, i);
    REQUIRE(first.confidence < kSecondLook);
    const CellReading mean = p.five_readings(net, p.field.cells[i]);
    CHECK(r.cells[i].best == mean.best);
    CHECK(r.cells[i].confidence == mean.confidence);
    CHECK(mean.confidence != first.confidence);  // the moved crops did change the reading
    CHECK(r.cells[i].confidence < kCellConfidence);
  }
  // the empty cell is not asked (no ink inside its border), nor looked at again
  CHECK(r.cells[2].best == CellClass::empty);
  CHECK(r.cells[2].confidence == 1.0f);
  CHECK(r.uncertain);
}

TEST_CASE("comb cells: a cell read from kSecondLook up is taken at its first reading") {
  const CombPage p;
  const DigitClassifier net = random_network(0.1f, 6);
  const FieldReading r = p.read(net);
  REQUIRE(r.cells.size() == 3);
  for (std::size_t i = 0; i < 2; ++i) {
    CAPTURE(i);
    const CellReading first = p.first_reading(net, i);
    REQUIRE(first.confidence >= kSecondLook);
    REQUIRE(p.five_readings(net, p.field.cells[i]).confidence != first.confidence);  // a second look would show
    CHECK(r.cells[i].best == CellClass::d3);
    CHECK(r.cells[i].confidence == first.confidence);
  }
  CHECK_FALSE(r.uncertain);
}
