#include "scan/field_reading.h"

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace epure::scan {

namespace {

// Bilinear grey level at an image point; outside the image, paper white.
double sample(const cv::Mat& g, double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  if (x0 < 0 || y0 < 0 || x0 + 1 >= g.cols || y0 + 1 >= g.rows) return 255;
  const double ax = x - fx, ay = y - fy;
  const unsigned char* r0 = g.ptr<unsigned char>(y0) + x0;
  const unsigned char* r1 = g.ptr<unsigned char>(y0 + 1) + x0;
  return (r0[0] * (1 - ax) + r0[1] * ax) * (1 - ay) + (r1[0] * (1 - ax) + r1[1] * ax) * ay;
}

double sample_pt(const cv::Mat& g, const PageMap& map, double x, double y) {
  const Point p = map.to_image({x, y});
  return sample(g, p.x - 0.5, p.y - 0.5);  // pixel centres at +0.5
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The field's ink level: the darkness of its boxes' printed borders, from profiles across them
// (each profile's darkest sample is the line, wherever registration put it within ±2 pt); its
// paper level: the profiles' lightest samples.
InkLevels border_levels(const cv::Mat& g, const PageMap& map, const FieldLayout& f, double page_paper, double page_ink) {
  std::vector<double> darkest, lightest;
  constexpr double kReach = 2.0;  // points either side of the printed line
  constexpr int kSteps = 9;
  auto profile = [&](double x, double y, double dx, double dy) {
    double lo = 255, hi = 0;
    for (int i = 0; i < kSteps; ++i) {
      const double t = -kReach + 2 * kReach * i / (kSteps - 1);
      const double v = sample_pt(g, map, x + t * dx, y + t * dy);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    darkest.push_back(lo);
    lightest.push_back(hi);
  };
  for (const auto& c : f.cells) {
    for (double s : {0.3, 0.5, 0.7}) {
      profile(c.x + s * c.width, c.y, 0, 1);
      profile(c.x + s * c.width, c.y + c.height, 0, 1);
      profile(c.x, c.y + s * c.height, 1, 0);
      profile(c.x + c.width, c.y + s * c.height, 1, 0);
    }
  }
  InkLevels l;
  l.border = median(darkest);
  l.ink = page_ink >= 0 ? std::min(page_ink, l.border) : l.border;
  l.paper = std::max(median(lightest), page_paper * 0.9);
  return l;
}

TickReading read_tick(const cv::Mat& g, const PageMap& map, const Rect& box, const InkLevels& levels) {
  const double inset = std::max(1.2, 0.2 * std::min(box.width, box.height));
  constexpr int kGrid = 12;
  int filled = 0, faint = 0, light = 0;
  // the middles of the four sides: rows 0-2 and 9-11 at columns 4-7, columns 0-2 and 9-11 at rows 4-7
  int side[4] = {0, 0, 0, 0}, light_side[4] = {0, 0, 0, 0};
  double side_ink[4] = {0, 0, 0, 0}, diagonals = 0;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const double x = box.x + inset + (box.width - 2 * inset) * (i + 0.5) / kGrid;
      const double y = box.y + inset + (box.height - 2 * inset) * (j + 0.5) / kGrid;
      const double ink = levels.to_ink(sample_pt(g, map, x, y));
      const double clamped = std::clamp(ink, 0.0, 1.0);
      const bool dark = ink > 0.5, lit = ink > kLightInk;
      filled += dark;
      faint += ink > 0.25;
      light += lit;
      const bool mid_i = i >= 4 && i <= 7, mid_j = j >= 4 && j <= 7;
      const int which = mid_i && j <= 2 ? 0 : mid_i && j >= 9 ? 1 : mid_j && i <= 2 ? 2 : mid_j && i >= 9 ? 3 : -1;
      if (i == j || i + j == kGrid - 1) diagonals += clamped;  // 2 × kGrid samples, none shared (kGrid even)
      if (which >= 0) {
        side[which] += dark;
        light_side[which] += lit;
        side_ink[which] += clamped;
      }
    }
  TickReading r;
  r.filled = static_cast<double>(filled) / (kGrid * kGrid);
  r.faint = static_cast<double>(faint) / (kGrid * kGrid);
  r.sides = static_cast<double>(*std::min_element(side, side + 4)) / 12;
  r.light = static_cast<double>(light) / (kGrid * kGrid);
  r.light_sides = static_cast<double>(*std::min_element(light_side, light_side + 4)) / 12;
  std::sort(side_ink, side_ink + 4);
  r.open_side = side_ink[0] / 12;
  r.contrast = diagonals / (2 * kGrid) - r.open_side;
  r.cross_contrast = diagonals / (2 * kGrid) - side_ink[2] / 12;
  r.state = tick_state(r);
  return r;
}

}  // namespace

TickState tick_state(const TickReading& r) {
  const bool mark_shaped = r.contrast >= kMarkContrast;
  if (r.filled >= kTickFilled) {
    if (r.sides >= kSidesFilled && !mark_shaped) return TickState::cancelled;
    if (r.sides < kSidesOpen && mark_shaped) return TickState::ticked;
    if (r.sides < kSidesFilled && mark_shaped && r.cross_contrast >= kCrossContrast) return TickState::ticked;
    return TickState::uncertain;
  }
  if (r.filled >= kTickMarked) return TickState::ticked;
  if (r.light >= kTickLight && r.light_sides < kSidesOpen) return TickState::ticked;
  if (r.filled <= kTickEmpty && r.faint < kTickFaint) return TickState::empty;
  return TickState::uncertain;
}

namespace {

void read_ticks(const cv::Mat& g, const PageMap& map, const FieldLayout& f, const InkLevels& levels, FieldReading& out) {
  std::vector<std::string> ticked;
  std::vector<std::size_t> doubtful;
  for (std::size_t i = 0; i < f.cells.size(); ++i) {
    out.ticks.push_back(read_tick(g, map, f.cells[i], levels));
    if (out.ticks.back().state == TickState::ticked) ticked.push_back(f.values[i]);
    if (out.ticks.back().state == TickState::uncertain) doubtful.push_back(i);
  }
  std::string joined;
  for (const auto& t : ticked) joined += (joined.empty() ? "" : " ") + t;
  out.value = joined;
  out.blank = ticked.empty() && doubtful.empty();
  if (!doubtful.empty()) {
    out.uncertain = true;
    std::string which;
    for (auto i : doubtful) which += (which.empty() ? "" : ", ") + f.values[i];
    out.why = fmt::format("box {} neither clearly ticked nor clearly empty", which);
  } else if (!f.multiple && ticked.size() > 1) {
    out.uncertain = true;
    out.why = fmt::format("{} boxes ticked where one is asked", ticked.size());
  }
  out.confidence = out.uncertain ? 0.5 : 1.0;
}

// A comb's characters as one value, or why they do not make one.
struct Assembled {
  std::string value;
  bool blank = false;
  std::string problem;
};

Assembled assemble(const std::string& chars, const FieldLayout& f, const std::string& sep) {
  Assembled a;
  const std::size_t n = chars.size();
  const std::size_t first = f.sign ? 1 : 0;
  const std::size_t dec_start = n - static_cast<std::size_t>(f.decimals);
  std::string sign;
  if (f.sign) {
    if (chars[0] == '-') sign = "-";
    else if (chars[0] != ' ') a.problem = "the sign cell holds a digit";
  }
  // the integer part: written anywhere in its cells, but in one run
  std::string integer = chars.substr(first, dec_start - first);
  const auto b = integer.find_first_not_of(' ');
  const auto e = integer.find_last_not_of(' ');
  integer = b == std::string::npos ? "" : integer.substr(b, e - b + 1);
  if (!integer.empty() && integer[0] == '-' && sign.empty() && f.sign) {
    sign = "-";  // the minus written in the first integer cell instead of the sign cell
    integer.erase(0, 1);
    if (integer.empty()) a.problem = "a minus with no digit";
  }
  std::string decimals = chars.substr(dec_start);
  const auto de = decimals.find_last_not_of(' ');
  decimals = de == std::string::npos ? "" : decimals.substr(0, de + 1);
  for (char c : integer)
    if (c < '0' || c > '9') a.problem = c == ' ' ? "an empty cell between digits" : "a minus among the digits";
  for (char c : decimals)
    if (c < '0' || c > '9') a.problem = c == ' ' ? "an empty decimal cell before a written one" : "a minus among the decimals";
  if (integer.empty() && decimals.empty()) {
    if (!sign.empty()) a.problem = "a minus with no digit";
    a.blank = a.problem.empty();
    return a;
  }
  if (integer.empty()) integer = "0";
  // an integer answer leaves its decimal cells empty: they read as zeros
  if (!decimals.empty()) decimals.append(static_cast<std::size_t>(f.decimals) - decimals.size(), '0');
  a.value = sign + integer + (decimals.empty() ? "" : sep + decimals);
  return a;
}

// A second look at a cell the networks are unsure of: the cell read again from crops made with
// the errors registration and handwriting leave (moved left, right, up and down by
// kSecondLookShift of its height; smaller and larger by kSecondLookScale about its centre), the
// seven readings' probabilities averaged (in double, in that order). A digit the networks read
// right sits in their crops wherever registration puts it and whatever its size, within what
// they were trained with; a doubtful reading is often one crop's accident (a stroke cut by the
// border, a neighbour's stroke in the margin, a digit written large or small), which the other
// crops do not share. Measured on the suite's scans (README, "epure scan"): fewer fields to
// review for as many silent errors, which is what the threshold trades.
CellReading second_look(const cv::Mat& g, const PageMap& map, const Rect& cell, const InkLevels& levels,
                        const DigitClassifier& net, const CellReading& first) {
  std::array<double, kClassCount> sum{};
  for (std::size_t c = 0; c < kClassCount; ++c) sum[c] = first.probability[c];
  for (const Rect& other : second_look_cells(cell)) {
    const CellReading r = net.classify(crop_cell(g, map, other, levels));
    for (std::size_t c = 0; c < kClassCount; ++c) sum[c] += r.probability[c];
  }
  std::array<float, kClassCount> mean;
  for (std::size_t c = 0; c < kClassCount; ++c) mean[c] = static_cast<float>(sum[c] / (1 + kSecondLookCrops));
  return reading_of(mean);
}

void read_comb(const cv::Mat& g, const PageMap& map, const FieldLayout& f, const InkLevels& levels,
               const std::string& sep, const DigitClassifier& net, FieldReading& out) {
  std::string best_chars;
  std::vector<std::string> doubtful;
  for (std::size_t i = 0; i < f.cells.size(); ++i) {
    const CellCrop crop = crop_cell(g, map, f.cells[i], levels);
    // a cell with (almost) no ink inside its border is empty: no need to ask the network
    int inked = 0;
    for (int y = 6; y < 22; ++y)
      for (int x = 8; x < 20; ++x) inked += crop[static_cast<std::size_t>(y * kCropSide + x)] > 50;
    CellReading r;
    if (inked <= 2) {
      r.best = CellClass::empty;
      r.confidence = 1;
      r.probability[static_cast<std::size_t>(CellClass::empty)] = 1;
    } else {
      r = net.classify(crop);
      if (r.confidence < kSecondLook) r = second_look(g, map, f.cells[i], levels, net, r);
      if (f.sign && i == 0) r = in_sign_cell(r);
    }
    out.cells.push_back({r.best, r.confidence});
    best_chars.push_back(class_char(r.best));
    out.chars.push_back(r.confidence >= kCellConfidence ? class_char(r.best) : '?');
    out.confidence *= r.confidence;
    if (r.confidence < kCellConfidence) doubtful.push_back(fmt::format("cell {}: {} at {:.2f}", i + 1, class_char(r.best), r.confidence));
  }
  const Assembled a = assemble(best_chars, f, sep);
  out.value = a.value;
  out.blank = a.blank && doubtful.empty();
  if (!doubtful.empty()) {
    out.uncertain = true;
    std::string w;
    for (const auto& d : doubtful) w += (w.empty() ? "" : "; ") + d;
    out.why = w;
  }
  if (!a.problem.empty()) {
    out.uncertain = true;
    out.why += (out.why.empty() ? "" : "; ") + a.problem;
  }
}

}  // namespace

CellReading in_sign_cell(const CellReading& r) {
  const std::size_t minus = static_cast<std::size_t>(CellClass::minus), empty = static_cast<std::size_t>(CellClass::empty);
  const double held = static_cast<double>(r.probability[minus]) + r.probability[empty];
  if (held < kSignCellHeld) return r;
  std::array<float, kClassCount> p{};
  p[minus] = static_cast<float>(r.probability[minus] / held);
  p[empty] = static_cast<float>(r.probability[empty] / held);
  return reading_of(p);
}

std::array<Rect, kSecondLookCrops> second_look_cells(const Rect& cell) {
  const double s = kSecondLookShift * cell.height;
  auto scaled = [&](double k) {
    return Rect{cell.cx() - k * cell.width / 2, cell.cy() - k * cell.height / 2, k * cell.width, k * cell.height};
  };
  return {Rect{cell.x - s, cell.y, cell.width, cell.height}, Rect{cell.x + s, cell.y, cell.width, cell.height},
          Rect{cell.x, cell.y - s, cell.width, cell.height}, Rect{cell.x, cell.y + s, cell.width, cell.height},
          scaled(1 - kSecondLookScale), scaled(1 + kSecondLookScale)};
}

const char* tick_state_name(TickState s) {
  switch (s) {
    case TickState::empty: return "empty";
    case TickState::ticked: return "ticked";
    case TickState::cancelled: return "cancelled";
    case TickState::uncertain: return "uncertain";
  }
  return "?";
}

double InkLevels::to_ink(double grey) const {
  const double span = paper - ink;
  return span > 1 ? (paper - grey) / span : 0;
}

double paper_level(const cv::Mat& grey) {
  cv::Mat small;
  const int f = std::max(1, std::min(grey.cols, grey.rows) / 200);
  cv::resize(grey, small, cv::Size(std::max(1, grey.cols / f), std::max(1, grey.rows / f)), 0, 0, cv::INTER_AREA);
  int hist[256] = {};
  for (int y = 0; y < small.rows; ++y) {
    const unsigned char* r = small.ptr<unsigned char>(y);
    for (int x = 0; x < small.cols; ++x) ++hist[r[x]];
  }
  const auto total = static_cast<long long>(small.total());
  long long seen = 0;
  for (int v = 0; v < 256; ++v) {
    seen += hist[v];
    if (seen * 10 >= total * 9) return v;
  }
  return 255;
}

CellCrop crop_cell(const cv::Mat& grey, const PageMap& map, const Rect& cell, const InkLevels& levels) {
  CellCrop crop{};
  const double h = cell.height;
  const double side = 1.3 * h;
  const double keep = cell.width / 2 + 0.15 * h;  // further left or right is a neighbour's cell
  const double px = side / kCropSide;
  const double cx = cell.cx(), cy = cell.cy();
  for (int j = 0; j < kCropSide; ++j)
    for (int i = 0; i < kCropSide; ++i) {
      double sum = 0;
      int n = 0;
      for (int sj = -1; sj <= 1; ++sj)
        for (int si = -1; si <= 1; ++si) {
          const double u = (i + 0.5 + si / 3.0) * px - side / 2;
          const double v = (j + 0.5 + sj / 3.0) * px - side / 2;
          ++n;
          if (std::abs(u) > keep) continue;
          sum += std::clamp(levels.to_ink(sample_pt(grey, map, cx + u, cy + v)), 0.0, 1.0);
        }
      crop[static_cast<std::size_t>(j * kCropSide + i)] = static_cast<std::uint8_t>(std::lround(255 * sum / n));
    }
  return crop;
}

FieldReading read_field(const cv::Mat& grey, const PageMap& map, const FieldLayout& field, double paper, double ink,
                        const std::string& decimal_separator, const DigitClassifier& net) {
  FieldReading out;
  out.question = field.question;
  const InkLevels levels = border_levels(grey, map, field, paper, ink);
  if (levels.paper - levels.border < 40) {
    // the printed boxes are not where the map puts them, or the scan lost them
    out.uncertain = true;
    out.confidence = 0;
    out.why = fmt::format("the field's printed boxes are not found (contrast {:.0f} of 255)", levels.paper - levels.border);
    return out;
  }
  if (field.type == FieldType::tick) read_ticks(grey, map, field, levels, out);
  else read_comb(grey, map, field, levels, decimal_separator, net, out);
  return out;
}

cv::Mat field_image(const cv::Mat& grey, const PageMap& map, const FieldLayout& field, double scale) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& c : field.cells) {
    x0 = std::min(x0, c.x), y0 = std::min(y0, c.y);
    x1 = std::max(x1, c.x + c.width), y1 = std::max(y1, c.y + c.height);
  }
  const double m = 0.3 * (y1 - y0) + 2;
  x0 -= m, y0 -= m, x1 += m, y1 += m;
  if (field.type == FieldType::tick) x1 += 40;  // the last box's label
  const cv::Matx33d crop_to_page(1 / scale, 0, x0, 0, 1 / scale, y0, 0, 0, 1);
  cv::Mat out;
  cv::warpPerspective(grey, out, map.h * crop_to_page,
                      cv::Size(std::max(1, static_cast<int>((x1 - x0) * scale)), std::max(1, static_cast<int>((y1 - y0) * scale))),
                      cv::INTER_AREA | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar(255));
  return out;
}

}  // namespace epure::scan
