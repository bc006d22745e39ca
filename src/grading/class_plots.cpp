#include "grading/class_plots.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "render/text.h"

namespace epure::grading {

namespace {

using render::P2;
using render::Role;
using render::Side;

constexpr double kRow = 20;        // points per row: one unit of the panels' math coordinates
constexpr double kLabelSize = 10;  // render::Style's label_size
constexpr double kGap = 14;        // render's gap between two panels
constexpr double kBar = 0.5;       // a bar's thickness, in rows

double width_of(std::string_view s) { return render::text_width(s, kLabelSize); }

std::string percent(const FeedbackText& text, double share) {
  return text.texts().format("grading.summary.percent", {{"value", text.points(std::round(100 * share))}});
}

render::Polygon bar(double x0, double x1, double y, double thickness, Role role) {
  if (x1 < x0) std::swap(x0, x1);
  return render::Polygon{{{x0, y - thickness / 2}, {x1, y - thickness / 2}, {x1, y + thickness / 2}, {x0, y + thickness / 2}},
                         true, role, true};
}

// A horizontal axis under `rows` rows, from x0 to x1, with ticks at `at` (math x) named `names`.
void axis(render::Panel& p, double y, double x0, double x1, const std::vector<std::pair<double, std::string>>& ticks) {
  p.add(render::Segment{{x0, y}, {x1, y}, Role::data});
  for (const auto& [x, name] : ticks) p.add(render::Tick{{x, y}, {1, 0}, name, Role::data});
}

// A panel's math view, `width_pt` points wide, from `left` (math x) and rows from 0 down to
// −(rows − 1), with room under them for the axis.
render::Box view(double left, double width_pt, int rows, double extra_bottom = 0) {
  return {left, -(rows - 1) - 2.0 - extra_bottom, left + width_pt / kRow, 0.8};
}

}  // namespace

double plot_width(const render::Scene& scene) {
  if (scene.panels.size() != 1) return kPlotWidth;
  return std::min(kPlotWidth, scene.panels[0].view.width() * kRow);
}

render::Scene marks_plot(const ClassStatistics& stats, const MarkScale& scale, const FeedbackText& text) {
  const Texts& T = text.texts();
  const double top = scale.out_of ? *scale.out_of : std::max(1.0, std::ceil(stats.max_points()));
  const auto histogram = stats.mark_histogram(top, 10);
  int highest = 1;
  for (const auto& b : histogram) highest = std::max(highest, b.count);
  // 480 points wide, 170 high: the marks along x, the counts up
  const double unit_x = 420.0 / top;   // points per mark
  const double unit_y = 130.0 / highest;  // points per student
  const double sx = unit_x / kRow, sy = unit_y / kRow;  // math units
  render::Scene s;
  s.title = T.get("grading.report.plot_marks");
  const double mean = stats.mean_percent() / 100 * top, median = stats.median_percent() / 100 * top;
  s.description = T.format("grading.report.plot_marks_description",
                           {{"count", std::to_string(stats.marked())},
                            {"out_of", text.points(top)},
                            {"mean", text.points(scale.round(mean))},
                            {"median", text.points(scale.round(median))}});
  render::Panel p;
  p.view = {-30.0 / kRow, -28.0 / kRow, (kPlotWidth - 30) / kRow, 150.0 / kRow + 1.2};
  p.caption = s.description;
  for (const auto& b : histogram) {
    if (b.count > 0) {
      const double h = b.count * sy;
      p.add(render::Polygon{{{b.from * sx, 0}, {b.to * sx, 0}, {b.to * sx, h}, {b.from * sx, h}}, true, Role::result, true});
      p.add(render::Label{std::to_string(b.count), {(b.from + b.to) / 2 * sx, h}, Side::above, Role::result});
    }
  }
  std::vector<std::pair<double, std::string>> ticks;
  for (const auto& b : histogram) ticks.emplace_back(b.from * sx, text.points(b.from));
  ticks.emplace_back(top * sx, text.points(top));
  axis(p, 0, 0, top * sx, ticks);
  p.add(render::Label{T.get(scale.out_of ? "grading.report.axis_mark" : "grading.report.axis_points"), {top * sx, 0}, Side::right,
                      Role::data});
  p.add(render::Label{T.get("grading.class.count_axis"), {0, highest * sy}, Side::above_right, Role::data});
  // mean and median: dashed lines across the bars, named at their top
  const double line_top = highest * sy + 0.9;
  p.add(render::Segment{{mean * sx, 0}, {mean * sx, line_top}, Role::construction, true});
  p.add(render::Label{T.format("grading.report.mean_at", {{"value", text.points(scale.round(mean))}}), {mean * sx, line_top},
                      Side::above, Role::construction});
  if (std::abs(median - mean) * unit_x > 1) {
    p.add(render::Segment{{median * sx, 0}, {median * sx, line_top - 0.9}, Role::normal, true});
    p.add(render::Label{T.format("grading.report.median_at", {{"value", text.points(scale.round(median))}}),
                        {median * sx, line_top - 0.9}, median < mean ? Side::left : Side::right, Role::normal});
  }
  s.panels.push_back(std::move(p));
  return s;
}

render::Scene questions_plot(const ItemAnalysis& items, std::size_t exercise, const FeedbackText& text) {
  const Texts& T = text.texts();
  const ExerciseItem& ex = items.exercises[exercise];
  std::vector<const QuestionItem*> qs;
  for (const auto& q : items.questions)
    if (q.exercise == ex.index) qs.push_back(&q);
  const int rows = std::max<int>(1, static_cast<int>(qs.size()));
  double label = 0;
  for (const auto* q : qs) label = std::max(label, width_of(q->id));
  label += 8;
  const double room = width_of("100 %") + 8;
  const double wa = (kPlotWidth - kGap) * 0.56, wb = kPlotWidth - kGap - wa;
  render::Scene s;
  s.title = T.get("grading.report.plot_questions");
  s.description = T.get("grading.report.plot_questions_description");
  // facility: bars from 0 to L
  render::Panel a;
  a.view = view(-label / kRow, wa, rows);
  a.caption = T.get("grading.report.facility_caption");
  const double L = (wa - label - room) / kRow;
  const double axis_y = -(rows - 1) - 0.9;
  for (int i = 0; i < static_cast<int>(qs.size()); ++i) {
    const QuestionItem& q = *qs[static_cast<std::size_t>(i)];
    const double y = -i;
    a.add(render::Label{q.id, {0, y}, Side::left, Role::data});
    if (q.answers == 0) continue;
    if (q.facility > 0) a.add(bar(0, q.facility * L, y, kBar, Role::result));
    a.add(render::Label{percent(text, q.facility), {q.facility * L, y}, Side::right, Role::result});
  }
  axis(a, axis_y, 0, L, {{0, percent(text, 0)}, {L / 2, percent(text, 0.5)}, {L, percent(text, 1)}});
  // discrimination: bars from 0, r in [−1, 1] over [−M, M]
  render::Panel b;
  const double half = wb / 2;
  b.view = view(-half / kRow, wb, rows);
  b.caption = T.get("grading.report.discrimination_caption");
  const double M = (half - width_of("−0,00") - 6) / kRow;
  // the floor of a useful question, dashed; 0 is where the bars start
  b.add(render::Segment{{0.2 * M, 0.5}, {0.2 * M, axis_y}, Role::construction, true});
  for (int i = 0; i < static_cast<int>(qs.size()); ++i) {
    const QuestionItem& q = *qs[static_cast<std::size_t>(i)];
    const double y = -i;
    if (!q.discrimination) {
      b.add(render::Label{"—", {0, y}, Side::right, Role::muted});
      continue;
    }
    const double r = *q.discrimination;
    const Role role = r < 0.2 ? Role::highlight : Role::result;
    if (std::abs(r) * M * kRow > 0.5) b.add(bar(0, r * M, y, kBar, role));
    b.add(render::Label{text.numbers().rounded(r, 2), {r * M, y}, r < 0 ? Side::left : Side::right, role});
  }
  axis(b, axis_y, -M, M,
       {{-M, text.numbers().rounded(-1, 0)}, {0, "0"}, {0.2 * M, text.numbers().rounded(0.2, 1)}, {M, "1"}});
  s.panels.push_back(std::move(a));
  s.panels.push_back(std::move(b));
  return s;
}

std::optional<render::Scene> branches_plot(const ItemAnalysis& items, std::size_t exercise, const ClassWords& words,
                                           const FeedbackText& text) {
  const Texts& T = text.texts();
  std::vector<const BranchItem*> bs;
  for (const auto& b : items.branches)
    if (b.exercise == exercise) bs.push_back(&b);
  const ExerciseItem& ex = items.exercises[exercise];
  std::vector<std::pair<std::string_view, int>> mistakes(ex.mistakes.begin(), ex.mistakes.end());
  std::stable_sort(mistakes.begin(), mistakes.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
  if (bs.size() < 2 && mistakes.empty()) return std::nullopt;
  render::Scene s;
  s.title = T.get("grading.report.plot_branches");
  s.description = T.get(bs.size() >= 2 && !mistakes.empty() ? "grading.report.plot_branches_description"
                        : bs.size() >= 2                    ? "grading.report.plot_branches_only"
                                                            : "grading.report.plot_mistakes_only");
  // each row: its name above its bar, two units high
  // both panels as high, so that both are drawn at kRow points a unit
  const int total = static_cast<int>(std::max(bs.size() >= 2 ? bs.size() : 0, mistakes.size()));
  const auto names_above = [&](render::Panel& p, double width_pt, const std::vector<std::string>& names,
                               const std::vector<double>& shares, const std::vector<std::string>& values,
                               const std::vector<bool>& marked) {
    const int rows = static_cast<int>(names.size());
    p.view = {-0.3, -2.0 * total - 1.4, width_pt / kRow - 0.3, 0.2};
    double value_room = 0;
    for (const auto& v : values) value_room = std::max(value_room, width_of(v));
    const double L = (width_pt - value_room - 10) / kRow;
    for (int i = 0; i < rows; ++i) {
      const double y = -2.0 * i - 1.25;
      const auto k = static_cast<std::size_t>(i);
      p.add(render::Label{names[k], {0, y + 0.45}, Side::above_right, Role::data});
      const Role role = marked[k] ? Role::highlight : Role::result;
      if (shares[k] > 0) p.add(bar(0, shares[k] * L, y, kBar, role));
      p.add(render::Label{values[k], {shares[k] * L, y}, Side::right, role});
    }
    p.add(render::Segment{{0, 0}, {0, -2.0 * rows - 0.6}, Role::data});
    return L;
  };
  const bool both = bs.size() >= 2 && !mistakes.empty();
  const double wa = both ? (kPlotWidth - kGap) * 0.4 : bs.size() >= 2 ? kPlotWidth * 0.6 : 0;
  const double wb = both ? kPlotWidth - kGap - wa : kPlotWidth * 0.75;
  if (bs.size() >= 2) {
    render::Panel a;
    std::vector<std::string> names, values;
    std::vector<double> shares;
    std::vector<bool> marked;
    for (const auto* b : bs) {
      names.push_back(T.format("grading.report.branch_row", {{"branch", words.branch(b->branch)}, {"n", std::to_string(b->submissions)}}));
      shares.push_back(b->facility);
      values.push_back(percent(text, b->facility));
      marked.push_back(b->harder);
    }
    const double L = names_above(a, wa, names, shares, values, marked);
    axis(a, -2.0 * static_cast<double>(bs.size()) - 0.6, 0, L, {{0, percent(text, 0)}, {L, percent(text, 1)}});
    a.caption = T.get("grading.report.branches_caption");
    s.panels.push_back(std::move(a));
  }
  if (!mistakes.empty()) {
    render::Panel b;
    const int most = mistakes.front().second;
    std::vector<std::string> names, values;
    std::vector<double> shares;
    std::vector<bool> marked;
    for (const auto& [code, count] : mistakes) {
      names.push_back(words.mistake(code));
      shares.push_back(static_cast<double>(count) / most);
      values.push_back(std::to_string(count));
      marked.push_back(false);
    }
    names_above(b, wb, names, shares, values, marked);
    b.caption = T.get("grading.report.mistakes_caption");
    s.panels.push_back(std::move(b));
  }
  return s;
}

}  // namespace epure::grading
