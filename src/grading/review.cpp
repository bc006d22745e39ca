#include "grading/review.h"

#include <fmt/format.h>

#include <cmath>

namespace epure::grading {

namespace {

// Calls fn on each space-separated name of `list`.
template <class Fn>
void each_name(std::string_view list, Fn&& fn) {
  while (!list.empty()) {
    const auto space = list.find(' ');
    const auto name = list.substr(0, space);
    if (!name.empty()) fn(name);
    if (space == std::string_view::npos) break;
    list.remove_prefix(space + 1);
  }
}

std::string coordinate(std::string_view group, char axis) {
  std::string s(group);
  s += '.';
  s += axis;
  return s;
}

}  // namespace

bool within(const QuestionKey& q, double given, double target, double factor) {
  if (!std::isfinite(given) || !std::isfinite(target)) return false;
  const double d = std::abs(given - target);
  switch (q.rule.kind) {
    case ToleranceRule::Kind::isclose: return d <= factor * std::max(q.rule.rel * std::abs(target), q.rule.abs);
    case ToleranceRule::Kind::distance: return d <= factor * q.rule.abs;
    case ToleranceRule::Kind::exact: break;
  }
  // an exact rule on a number: equal up to the last digits of a double
  return d <= 1e-9 * std::max(1.0, std::abs(target));
}

ExerciseReview::ExerciseReview(const ExerciseKey& key, std::span<QuestionMark> marks, bool follow_through,
                               NumberStyle numbers, int decimals)
    : key_(key), marks_(marks), follow_through_(follow_through), numbers_(numbers), decimals_(decimals) {}

QuestionMark* ExerciseReview::mark(std::string_view field) {
  const int i = key_.find(field);
  return i < 0 ? nullptr : &marks_[static_cast<std::size_t>(i)];
}

const QuestionMark* ExerciseReview::mark(std::string_view field) const {
  const int i = key_.find(field);
  return i < 0 ? nullptr : &marks_[static_cast<std::size_t>(i)];
}

std::optional<double> ExerciseReview::number(std::string_view field) const {
  const auto* m = mark(field);
  if (!m || !m->given.readable() || key_.questions[key_.find(field)].type != AnswerType::number) return std::nullopt;
  return m->given.number;
}

std::optional<geo::Point2> ExerciseReview::point(std::string_view group) const {
  const auto x = number(coordinate(group, 'x')), y = number(coordinate(group, 'y'));
  if (!x || !y) return std::nullopt;
  return geo::Point2{*x, *y};
}

std::optional<bool> ExerciseReview::boolean(std::string_view field) const {
  const auto* m = mark(field);
  if (!m || !m->given.readable() || key_.questions[key_.find(field)].type != AnswerType::boolean) return std::nullopt;
  return m->given.boolean;
}

std::optional<FaceBits> ExerciseReview::faces(std::string_view field) const {
  const auto* m = mark(field);
  if (!m || !m->given.readable() || key_.questions[key_.find(field)].type != AnswerType::faces) return std::nullopt;
  return m->given.faces;
}

std::optional<std::string_view> ExerciseReview::word(std::string_view field) const {
  const auto* m = mark(field);
  if (!m || !m->given.readable() || key_.questions[key_.find(field)].type != AnswerType::word) return std::nullopt;
  return m->given.word;
}

bool ExerciseReview::right(std::string_view field) const {
  const auto* m = mark(field);
  if (m) return m->verdict == Verdict::right || m->verdict == Verdict::follow_through;
  return right_point(field);
}

bool ExerciseReview::right_coordinates(std::string_view group, int count) const {
  const char axes[] = {'x', 'y', 'z'};
  bool any = false;
  for (int i = 0; i < count; ++i) {
    const auto* m = mark(coordinate(group, axes[i]));
    if (!m) continue;
    any = true;
    if (!(m->verdict == Verdict::right || m->verdict == Verdict::follow_through)) return false;
  }
  return any;
}

bool ExerciseReview::open(std::string_view field) const {
  const auto* m = mark(field);
  return m && m->verdict == Verdict::wrong && m->from.empty() && m->mistake.empty();
}

bool ExerciseReview::some_wrong(std::string_view from) const {
  bool wrong = false;
  each_name(from, [&](std::string_view name) {
    auto check = [&](const QuestionMark* m) {
      if (m && m->given.readable() && m->verdict != Verdict::right) wrong = true;
    };
    if (const auto* m = mark(name)) {
      check(m);
    } else {
      check(mark(coordinate(name, 'x')));
      check(mark(coordinate(name, 'y')));
    }
  });
  return wrong;
}

std::string ExerciseReview::describe(std::string_view from) const {
  std::string out;
  each_name(from, [&](std::string_view name) {
    if (!out.empty()) out += numbers_.decimal_comma ? " ; " : ", ";
    if (const auto* m = mark(name)) {
      out += fmt::format("{} = {}", name, m->given.raw);
    } else {
      const auto* x = mark(coordinate(name, 'x'));
      const auto* y = mark(coordinate(name, 'y'));
      if (x && y) out += fmt::format("{} = ({}{} {})", name, x->given.raw, numbers_.decimal_comma ? " ;" : ",", y->given.raw);
    }
  });
  return out;
}

void ExerciseReview::credit(int index, std::string_view from, std::string_view mistake, double value) {
  QuestionMark& m = marks_[static_cast<std::size_t>(index)];
  m.from = from;
  m.detail = describe(from);
  if (!mistake.empty()) m.mistake = mistake;
  m.value = value;
  if (follow_through_) {
    m.verdict = Verdict::follow_through;
    m.points = key_.questions[static_cast<std::size_t>(index)].points;
  }
}

bool ExerciseReview::follow(std::string_view field, double value, std::string_view from, std::string_view code) {
  const int i = key_.find(field);
  if (i < 0 || !open(field) || !some_wrong(from)) return false;
  const auto g = number(field);
  if (!g || !within(key_.questions[i], *g, value, kMatchFactor)) return false;
  credit(i, from, code, value);
  return true;
}

bool ExerciseReview::follow_point(std::string_view group, geo::Point2 value, std::string_view from,
                                  std::string_view code) {
  const std::string fx = coordinate(group, 'x'), fy = coordinate(group, 'y');
  const int ix = key_.find(fx), iy = key_.find(fy);
  if (ix < 0 || iy < 0 || !some_wrong(from)) return false;
  const auto& qx = key_.questions[ix];
  if (qx.rule.kind == ToleranceRule::Kind::distance) {
    // the point as a whole
    const auto g = point(group);
    if (!g || !(open(fx) || open(fy))) return false;
    const double abs = std::max(qx.rule.abs, key_.questions[iy].rule.abs);
    if (!(std::hypot(g->x - value.x, g->y - value.y) <= kMatchFactor * abs)) return false;
    if (open(fx)) credit(ix, from, code, value.x);
    if (open(fy)) credit(iy, from, code, value.y);
    return true;
  }
  bool any = false;
  if (open(fx) && within(qx, marks_[ix].given.number, value.x, kMatchFactor)) credit(ix, from, code, value.x), any = true;
  if (open(fy) && within(key_.questions[iy], marks_[iy].given.number, value.y, kMatchFactor))
    credit(iy, from, code, value.y), any = true;
  return any;
}

bool ExerciseReview::follow_boolean(std::string_view field, bool value, std::string_view from, std::string_view code) {
  const int i = key_.find(field);
  if (i < 0 || !open(field) || !some_wrong(from)) return false;
  const auto g = boolean(field);
  if (!g || *g != value) return false;
  credit(i, from, code, NAN);
  return true;
}

bool ExerciseReview::follow_word(std::string_view field, std::string_view w, std::string_view from,
                                 std::string_view code) {
  const int i = key_.find(field);
  if (i < 0 || !open(field) || !some_wrong(from)) return false;
  const auto g = word(field);
  if (!g || *g != w) return false;
  credit(i, from, code, NAN);
  return true;
}

bool ExerciseReview::mistake(std::string_view field, double value, std::string_view code) {
  const int i = key_.find(field);
  if (i < 0 || !open(field)) return false;
  const auto g = number(field);
  if (!g || !within(key_.questions[i], *g, value, kMatchFactor)) return false;
  marks_[i].mistake = code;
  marks_[i].value = value;
  return true;
}

bool ExerciseReview::mistake_point(std::string_view group, geo::Point2 value, std::string_view code) {
  const std::string fx = coordinate(group, 'x'), fy = coordinate(group, 'y');
  const int ix = key_.find(fx), iy = key_.find(fy);
  if (ix < 0 || iy < 0) return false;
  const auto& qx = key_.questions[ix];
  auto name = [&](int i, double v) {
    marks_[i].mistake = code;
    marks_[i].value = v;
  };
  if (qx.rule.kind == ToleranceRule::Kind::distance) {
    const auto g = point(group);
    if (!g || !(open(fx) || open(fy))) return false;
    const double abs = std::max(qx.rule.abs, key_.questions[iy].rule.abs);
    if (!(std::hypot(g->x - value.x, g->y - value.y) <= kMatchFactor * abs)) return false;
    if (open(fx)) name(ix, value.x);
    if (open(fy)) name(iy, value.y);
    return true;
  }
  // Both coordinates must fit the mistake, right ones included: one coordinate alone
  // matching is a coincidence, not a diagnosis.
  const auto g = point(group);
  if (!g) return false;
  if (!within(qx, g->x, value.x, kMatchFactor) || !within(key_.questions[iy], g->y, value.y, kMatchFactor))
    return false;
  bool any = false;
  if (open(fx)) name(ix, value.x), any = true;
  if (open(fy)) name(iy, value.y), any = true;
  return any;
}

bool ExerciseReview::mistake_faces(std::string_view field, FaceBits value, std::string_view code) {
  const int i = key_.find(field);
  if (i < 0 || !open(field)) return false;
  const auto g = faces(field);
  if (!g || *g != value) return false;
  marks_[i].mistake = code;
  return true;
}

bool ExerciseReview::mistake_word(std::string_view field, std::string_view w, std::string_view code) {
  const int i = key_.find(field);
  if (i < 0 || !open(field)) return false;
  const auto g = word(field);
  if (!g || *g != w) return false;
  marks_[i].mistake = code;
  return true;
}

}  // namespace epure::grading
