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
// bias of class `raised`'s output raised by `sure`. Weights in ±0.5 and no raise: unsure of
// every crop, so that every written cell gets the second look. Weights in ±0.1 and a raise of 6:
// a 3 over 0.90 whatever the crop, in readings that still differ from crop to crop.
DigitClassifier random_network(float amplitude, float sure, CellClass raised = CellClass::d3) {
  const std::uint32_t c = 4, hidden = 8;
  const std::uint32_t count = (c * 9 + c) + 2 * (c * c * 9 + c) + (hidden * c * 9 + hidden) + (12 * hidden + 12);
  std::string b = "EPDG" + u32(2) + u32(count) + u32(c) + u32(c) + u32(c) + u32(hidden);
  std::uint64_t state = 20261206;
  for (std::uint32_t i = 0; i < count; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    float w = amplitude * 2 * static_cast<float>(static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24) - 0.5);
    if (i == count - 12 + static_cast<std::uint32_t>(raised)) w += sure;  // fc2's biases are the file's last 12 floats
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
  // The seven readings' mean (the crop, then moved left, right, up, down, then 0.92 and 1.08 of
  // its size about its centre), as second_look takes it: the crops spelt out here, not taken from
  // second_look_cells.
  CellReading seven_readings(const DigitClassifier& net, const Rect& c) const {
    std::array<double, kClassCount> sum{};
    const double s = kSecondLookShift * c.height;
    const double k0 = 1 - kSecondLookScale, k1 = 1 + kSecondLookScale;
    const Rect crops[] = {c,
                          Rect{c.x - s, c.y, c.width, c.height},
                          Rect{c.x + s, c.y, c.width, c.height},
                          Rect{c.x, c.y - s, c.width, c.height},
                          Rect{c.x, c.y + s, c.width, c.height},
                          Rect{c.cx() - k0 * c.width / 2, c.cy() - k0 * c.height / 2, k0 * c.width, k0 * c.height},
                          Rect{c.cx() - k1 * c.width / 2, c.cy() - k1 * c.height / 2, k1 * c.width, k1 * c.height}};
    for (const Rect& r : crops) {
      const CellReading x = net.classify(crop_cell(page, map, r, levels));
      for (std::size_t k = 0; k < kClassCount; ++k) sum[k] += x.probability[k];
    }
    std::array<float, kClassCount> mean;
    for (std::size_t c = 0; c < kClassCount; ++c) mean[c] = static_cast<float>(sum[c] / 7);
    return reading_of(mean);
  }
};

}  // namespace

TEST_CASE("comb cells: a cell read under kSecondLook is read again from six other crops, the seven readings averaged") {
  const CombPage p;
  const DigitClassifier net = random_network(0.5f, 0);
  const FieldReading r = p.read(net);
  REQUIRE(r.cells.size() == 3);
  for (std::size_t i = 0; i < 2; ++i) {
    CAPTURE(i);
    const CellReading first = p.first_reading(net, i);
    REQUIRE(first.confidence < kSecondLook);
    const CellReading mean = p.seven_readings(net, p.field.cells[i]);
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
    REQUIRE(p.seven_readings(net, p.field.cells[i]).confidence != first.confidence);  // a second look would show
    CHECK(r.cells[i].best == CellClass::d3);
    CHECK(r.cells[i].confidence == first.confidence);
  }
  CHECK_FALSE(r.uncertain);
}

namespace {

CellReading reading(std::initializer_list<std::pair<CellClass, float>> classes) {
  std::array<float, kClassCount> p{};
  for (const auto& [c, v] : classes) p[static_cast<std::size_t>(c)] = v;
  return reading_of(p);
}

}  // namespace

TEST_CASE("sign cell: the likelier of a minus and nothing, at its share of the two") {
  // a minus the networks doubt against a 7, as the suite's scans show them
  const CellReading minus = in_sign_cell(reading({{CellClass::minus, 0.63f}, {CellClass::d7, 0.20f}, {CellClass::d4, 0.12f}, {CellClass::empty, 0.05f}}));
  CHECK(minus.best == CellClass::minus);
  CHECK(minus.confidence == doctest::Approx(0.63 / 0.68).epsilon(1e-6));
  CHECK(minus.confidence >= kCellConfidence);
  CHECK(minus.probability[static_cast<std::size_t>(CellClass::d7)] == 0.0f);
  // a 7 the likeliest class, but the minus and nothing hold more than half together: a minus,
  // doubtful still
  const CellReading seven = in_sign_cell(reading({{CellClass::d7, 0.45f}, {CellClass::minus, 0.40f}, {CellClass::empty, 0.15f}}));
  CHECK(seven.best == CellClass::minus);
  CHECK(seven.confidence == doctest::Approx(0.40 / 0.55).epsilon(1e-6));
  CHECK(seven.confidence < kCellConfidence);
  // a digit holding more than half: the cell is left as read, and its field goes to review
  const CellReading digit_read = reading({{CellClass::d7, 0.56f}, {CellClass::minus, 0.26f}, {CellClass::empty, 0.18f}});
  const CellReading digit = in_sign_cell(digit_read);
  CHECK(digit.best == CellClass::d7);
  CHECK(digit.confidence == digit_read.confidence);
  // nothing, doubted against a 1
  const CellReading empty = in_sign_cell(reading({{CellClass::empty, 0.72f}, {CellClass::d1, 0.08f}, {CellClass::d4, 0.04f}, {CellClass::minus, 0.01f}, {CellClass::d6, 0.15f}}));
  CHECK(empty.best == CellClass::empty);
  CHECK(empty.confidence == doctest::Approx(0.72 / 0.73).epsilon(1e-6));
}

TEST_CASE("comb cells: the sign cell is read as a minus or nothing, the other cells over every class") {
  CombPage p;
  p.field.sign = true;
  // a network that leans to the minus, whose digits keep some of every cell's mass
  const DigitClassifier net = random_network(0.5f, 3.0f, CellClass::minus);
  const FieldReading r = p.read(net);
  REQUIRE(r.cells.size() == 3);
  const CellReading sign_mean = p.seven_readings(net, p.field.cells[0]);
  REQUIRE(sign_mean.confidence < kSecondLook);
  const double held = static_cast<double>(sign_mean.probability[static_cast<std::size_t>(CellClass::minus)]) +
                      sign_mean.probability[static_cast<std::size_t>(CellClass::empty)];
  REQUIRE(held >= kSignCellHeld);
  REQUIRE(held < 0.99);  // the digits' share shows
  const CellReading sign = in_sign_cell(sign_mean);
  CHECK(r.cells[0].best == sign.best);
  CHECK(r.cells[0].confidence == sign.confidence);
  CHECK(r.cells[0].confidence > sign_mean.confidence);
  // the second cell is an integer digit's: every class, as the seven readings give them
  const CellReading ring = p.seven_readings(net, p.field.cells[1]);
  REQUIRE(ring.confidence < kSecondLook);
  CHECK(r.cells[1].best == ring.best);
  CHECK(r.cells[1].confidence == ring.confidence);
}

TEST_CASE("tick boxes: a box inked from kTickFilled is told by its shape") {
  auto heavy = [](double sides, double contrast, double cross_contrast) {
    TickReading r;
    r.filled = 0.82;
    r.faint = 0.9;
    r.light = 0.85;
    r.sides = sides;
    r.light_sides = sides;
    r.contrast = contrast;
    r.cross_contrast = cross_contrast;
    return tick_state(r);
  };
  // a fill: every side's middle inked, the diagonals no darker than the lightest of them
  CHECK(heavy(1.0, 0.01, 0.0) == TickState::cancelled);
  CHECK(heavy(kSidesFilled, kMarkContrast - 0.01, 0.0) == TickState::cancelled);
  // a heavy mark leaving a side's middle white
  CHECK(heavy(0.2, 0.6, -0.1) == TickState::ticked);
  CHECK(heavy(0.0, kMarkContrast, 0.0) == TickState::ticked);
  // a cross in a heavy pen at 150 dpi: half of a side's middle inked, three sides lighter than the diagonals
  CHECK(heavy(0.5, 0.45, 0.3) == TickState::ticked);
  CHECK(heavy(0.34, kMarkContrast, kCrossContrast) == TickState::ticked);
  // the same side's middle, but the other sides inked: a fill gone short of one side
  CHECK(heavy(0.34, 0.45, -0.15) == TickState::uncertain);
  CHECK(heavy(0.5, 0.45, kCrossContrast - 0.01) == TickState::uncertain);
  // inked evenly but short of a fill's sides (a copier's speckle): neither
  CHECK(heavy(0.45, 0.05, 0.0) == TickState::uncertain);
  CHECK(heavy(0.0, 0.1, 0.0) == TickState::uncertain);
  // every side's middle inked, yet one much lighter than the diagonals: neither
  CHECK(heavy(0.75, 0.3, 0.2) == TickState::uncertain);
  // under kTickFilled every mark is a tick, whatever its shape (a "+", a circled box)
  TickReading mark;
  mark.filled = 0.4;
  mark.faint = 0.5;
  mark.light = 0.45;
  mark.open_side = 0.6;
  CHECK(tick_state(mark) == TickState::ticked);
}

namespace {

// A row of tick boxes as generate prints them (10 pt, borders 0.7 pt) scanned at `dpi` (150, the
// lowest resolution scan reads, unless said), in full ink (0) on white paper.
struct TickTestRow {
  double scale;
  PageMap map;
  FieldLayout field;
  cv::Mat page;
  explicit TickTestRow(int boxes, double dpi = 150)
      : scale(dpi / 72), page(static_cast<int>(30 * dpi / 72), static_cast<int>((16 + 14 * boxes) * dpi / 72), CV_8U, cv::Scalar(255)) {
    map.h = cv::Matx33d(scale, 0, 0, 0, scale, 0, 0, 0, 1);
    field.question = "t";
    field.type = FieldType::tick;
    field.multiple = true;
    for (int i = 0; i < boxes; ++i) {
      field.cells.push_back(Rect{8.0 + 14 * i, 8, 10, 10});
      field.values.push_back(std::to_string(i));
    }
  }
  cv::Point2d px(double x, double y) const { return {x * scale, y * scale}; }
  void borders() {
    for (const Rect& c : field.cells)
      cv::rectangle(page, cv::Point(px(c.x, c.y)), cv::Point(px(c.x + c.width, c.y + c.height)), cv::Scalar(0), 1, cv::LINE_AA);
  }
  // scan's blur, as a copier's optics give it
  FieldReading read() {
    cv::Mat blurred;
    cv::GaussianBlur(page, blurred, cv::Size(0, 0), 0.6);
    return read_field(blurred, map, field, 255, 0, ",", DigitClassifier::builtin());
  }
};

}  // namespace

TEST_CASE("tick boxes at 150 dpi: a cross in a heavy pen is read as ticked, a filled box as cancelled") {
  // 3 px strokes (1.45 pt), corner to corner give or take 0.12 of the box (the suite's crosses)
  constexpr int kCrosses = 24;
  TickTestRow row(kCrosses + 2);
  std::uint64_t state = 20261206;
  auto jitter = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return 1.2 * (static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24) - 0.5) * 2;
  };
  for (int i = 0; i < kCrosses; ++i) {
    const Rect& b = row.field.cells[static_cast<std::size_t>(i)];
    const auto a0 = row.px(b.x + jitter(), b.y + jitter()), a1 = row.px(b.x + b.width + jitter(), b.y + b.height + jitter());
    const auto b0 = row.px(b.x + b.width + jitter(), b.y + jitter()), b1 = row.px(b.x + jitter(), b.y + b.height + jitter());
    cv::line(row.page, cv::Point(a0), cv::Point(a1), cv::Scalar(40), 3, cv::LINE_AA);
    cv::line(row.page, cv::Point(b0), cv::Point(b1), cv::Scalar(40), 3, cv::LINE_AA);
  }
  for (int i = kCrosses; i < kCrosses + 2; ++i) {  // filled as a pen fills a box, a little over its edges
    const Rect& b = row.field.cells[static_cast<std::size_t>(i)];
    cv::rectangle(row.page, cv::Point(row.px(b.x - 0.5, b.y - 0.5)), cv::Point(row.px(b.x + b.width + 0.5, b.y + b.height + 0.5)), cv::Scalar(40), cv::FILLED);
  }
  row.borders();
  const FieldReading r = row.read();
  REQUIRE(r.ticks.size() == kCrosses + 2);
  int heavy = 0, sides_half_inked = 0;
  for (int i = 0; i < kCrosses; ++i) {
    CAPTURE(i);
    const TickReading& t = r.ticks[static_cast<std::size_t>(i)];
    CAPTURE(t.filled);
    CAPTURE(t.sides);
    CAPTURE(t.contrast);
    CHECK(t.state == TickState::ticked);
    heavy += t.filled >= kTickFilled;
    sides_half_inked += t.filled >= kTickFilled && t.sides >= kSidesOpen;  // what the share alone left in doubt
  }
  CHECK(heavy >= kCrosses / 2);
  CHECK(sides_half_inked >= 3);
  for (int i = kCrosses; i < kCrosses + 2; ++i) {
    const TickReading& t = r.ticks[static_cast<std::size_t>(i)];
    CAPTURE(t.contrast);
    CHECK(t.state == TickState::cancelled);
  }
}

namespace {

// The rules before a box's shape was asked (its share of ink and its sides' middles only), to
// compare with: the shape's rules may send to review what these ticked, never tick a fill these
// did not.
TickState share_rule(const TickReading& r) {
  if (r.filled >= kTickFilled && r.sides >= kSidesFilled) return TickState::cancelled;
  if (r.filled >= kTickMarked && (r.filled < kTickFilled || r.sides < kSidesOpen)) return TickState::ticked;
  if (r.filled < kTickMarked && r.light >= kTickLight && r.light_sides < kSidesOpen) return TickState::ticked;
  if (r.filled <= kTickEmpty && r.faint < kTickFaint) return TickState::empty;
  return TickState::uncertain;
}

double uniform(std::uint64_t& state) {  // in [0, 1), a fixed LCG
  state = state * 6364136223846793005ULL + 1442695040888963407ULL;
  return static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24);
}

}  // namespace

TEST_CASE("tick boxes at 150, 200 and 300 dpi: a fill gone short of one side is ticked only where its share alone was") {
  std::uint64_t state = 11;
  int shape_ticked = 0, share_ticked = 0, aligned = 0;
  for (const double dpi : {150.0, 200.0, 300.0}) {
    CAPTURE(dpi);
    // filled from each side in turn to 60-95 % of the box (the pen 0.5 pt past its other edges),
    // the rest of it white; first where the layout puts the box, then three times off it by up to
    // 0.5 pt either way (registration's error)
    const double reaches[] = {0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95};
    for (int round = 0; round < 4; ++round) {
      TickTestRow row(32, dpi);
      for (int side = 0; side < 4; ++side)
        for (int k = 0; k < 8; ++k) {
          const Rect& b = row.field.cells[static_cast<std::size_t>(8 * side + k)];
          const double f = reaches[k], m = 0.5;
          const double dx = round ? uniform(state) - 0.5 : 0, dy = round ? uniform(state) - 0.5 : 0;
          Rect ink{b.x - m + dx, b.y - m + dy, b.width + 2 * m, b.height + 2 * m};
          if (side == 0) { ink.y += (1 - f) * b.height; ink.height -= (1 - f) * b.height; }  // short of the top
          if (side == 1) ink.height -= (1 - f) * b.height;                                      // of the bottom
          if (side == 2) { ink.x += (1 - f) * b.width; ink.width -= (1 - f) * b.width; }     // of the left
          if (side == 3) ink.width -= (1 - f) * b.width;                                        // of the right
          cv::rectangle(row.page, cv::Point(row.px(ink.x, ink.y)), cv::Point(row.px(ink.x + ink.width, ink.y + ink.height)), cv::Scalar(40), cv::FILLED);
        }
      row.borders();
      const FieldReading r = row.read();
      for (std::size_t i = 0; i < r.ticks.size(); ++i) {
        CAPTURE(round);
        CAPTURE(i);
        const TickReading& t = r.ticks[i];
        CAPTURE(t.filled);
        CAPTURE(t.sides);
        CAPTURE(t.contrast);
        CAPTURE(t.cross_contrast);
        const bool by_shape = t.state == TickState::ticked, by_share = share_rule(t) == TickState::ticked;
        CHECK((!by_shape || by_share));
        shape_ticked += by_shape;
        share_ticked += by_share;
        // where the layout puts it, a fill reaching 70 % or more (73 % of the box with the pen's
        // overhang) is never a tick
        if (round == 0 && i % 8 >= 2) aligned += by_shape;
      }
    }
  }
  CHECK(aligned == 0);
  // what both rules still tick (38 of these 384 boxes, the same ones): a fill leaving about a
  // quarter of the box white or more (README, Limits)
  CHECK(shape_ticked > 0);
  CHECK(shape_ticked <= share_ticked);
}

TEST_CASE("tick boxes: a box speckled evenly from 70 % black (a copier's threshold over a light fill) is rarely a tick") {
  // 100 boxes a density and resolution, each pixel black with probability p (a fixed LCG), the
  // speckle reaching a little past the box as a fill does
  for (const double dpi : {150.0, 200.0})
    for (const double p : {0.7, 0.8}) {
      CAPTURE(dpi);
      CAPTURE(p);
      TickTestRow row(100, dpi);
      std::uint64_t state = 7;
      for (const Rect& b : row.field.cells) {
        const cv::Point a(row.px(b.x - 0.3, b.y - 0.3)), z(row.px(b.x + b.width + 0.3, b.y + b.height + 0.3));
        for (int y = a.y; y <= z.y; ++y)
          for (int x = a.x; x <= z.x; ++x)
            if (uniform(state) < p) row.page.at<unsigned char>(y, x) = 0;
      }
      row.borders();
      const FieldReading r = row.read();
      int ticked = 0;
      for (const auto& t : r.ticks) ticked += t.state == TickState::ticked;
      // This draw: none (the contrast alone, without the three sides, ticked 2-13). Over 1,000
      // boxes off the layout by up to 0.5 pt (a review's probe): at 150 dpi 28 at 70 % and 4 at
      // 80 %, the share's rules 28 and 1; at 200 dpi 6 and 0, the same as the share's.
      CHECK(ticked <= 3);
    }
}
