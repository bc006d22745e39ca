#include "grading/review.h"

#include "support/agrees.h"

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

// "P" and 'x' → "P.x", without an allocation (groups are short names).
struct Coordinate {
  char text[16];
  std::size_t size;
  operator std::string_view() const { return {text, size}; }
};
Coordinate coordinate(std::string_view group, char axis) {
  Coordinate c{};
  const std::size_t n = std::min(group.size(), sizeof c.text - 2);
  for (std::size_t i = 0; i < n; ++i) c.text[i] = group[i];
  c.text[n] = '.';
  c.text[n + 1] = axis;
  c.size = n + 2;
  return c;
}

}  // namespace

namespace {

bool within_rule(ToleranceRule::Kind kind, double rel, double abs, double given, double target, double factor) {
  if (!std::isfinite(given) || !std::isfinite(target)) return false;
  const double d = std::abs(given - target);
  switch (kind) {
    case ToleranceRule::Kind::isclose: return d <= factor * std::max(rel * std::abs(target), abs);
    case ToleranceRule::Kind::distance: return d <= factor * abs;
    case ToleranceRule::Kind::exact: break;
  }
  // an exact rule on a number: equal up to the last digits of a double
  return agrees(given, target);
}

// The same from the packed copy of the question (answer_key.h: HotQuestion), which marking has
// just read: the full QuestionKey is another cache line per question, and with a large key
// each row of answers is another sheet's, so that line is a miss.
bool within(const HotQuestion& q, double given, double target, double factor) {
  return within_rule(q.rule, q.rel, q.abs, given, target, factor);
}

// Follow-through: `target` is what the student's written answers give, and the student went on
// with more digits than they wrote (method.h: the sheet's instruction); the key's follow_abs
// covers that, where it is wider than the match.
bool follows_within(const HotQuestion& q, double given, double target) {
  return within(q, given, target, kMatchFactor) ||
         (q.follow_abs > 0 && within_rule(q.rule, 0, q.follow_abs, given, target, 1.0));
}

}  // namespace

bool within(const QuestionKey& q, double given, double target, double factor) {
  return within_rule(q.rule.kind, q.rule.rel, q.rule.abs, given, target, factor);
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

// One lookup per public call: the index-based helpers below do the rest.
bool ExerciseReview::open_at(int i) const {
  if (i < 0) return false;
  const QuestionMark& m = marks_[static_cast<std::size_t>(i)];
  return m.verdict == Verdict::wrong && m.from.empty() && m.mistake.empty();
}

const QuestionMark* ExerciseReview::readable_at(int i, AnswerType type) const {
  if (i < 0) return nullptr;
  const QuestionMark& m = marks_[static_cast<std::size_t>(i)];
  if (!m.given.readable() || key_.hot[static_cast<std::size_t>(i)].type != type) return nullptr;
  return &m;
}

std::optional<double> ExerciseReview::number(std::string_view field) const {
  const auto* m = readable_at(key_.find(field), AnswerType::number);
  if (!m) return std::nullopt;
  return m->given.number;
}

std::optional<geo::Point2> ExerciseReview::point(std::string_view group) const {
  const auto x = number(coordinate(group, 'x'));
  if (!x) return std::nullopt;
  const auto y = number(coordinate(group, 'y'));
  if (!y) return std::nullopt;
  return geo::Point2{*x, *y};
}

std::optional<bool> ExerciseReview::boolean(std::string_view field) const {
  const auto* m = readable_at(key_.find(field), AnswerType::boolean);
  if (!m) return std::nullopt;
  return m->given.boolean;
}

std::optional<FaceBits> ExerciseReview::faces(std::string_view field) const {
  const auto* m = readable_at(key_.find(field), AnswerType::faces);
  if (!m) return std::nullopt;
  return m->given.faces;
}

std::optional<std::string_view> ExerciseReview::word(std::string_view field) const {
  const auto* m = readable_at(key_.find(field), AnswerType::choice);
  if (!m) return std::nullopt;
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

bool ExerciseReview::open(std::string_view field) const { return open_at(key_.find(field)); }

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
    m.points = key_.hot[static_cast<std::size_t>(index)].points;
  }
}

bool ExerciseReview::follow(std::string_view field, double value, std::string_view from, std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::number);
  if (!m || !follows_within(key_.hot[i], m->given.number, value) || !some_wrong(from)) return false;
  credit(i, from, code, value);
  return true;
}

bool ExerciseReview::coordinates_of(std::string_view group, std::size_t count, int* at) const {
  static constexpr char kAxes[] = {'x', 'y', 'z'};
  if (count < 2 || count > 3) return false;
  for (std::size_t k = 0; k < count; ++k)
    if ((at[k] = key_.find(coordinate(group, kAxes[k]))) < 0) return false;
  return true;
}

namespace {
// The distance from the given coordinates to `value`, or NaN when one is not readable.
double distance_to(std::span<const QuestionMark> marks, const int* at, std::span<const double> value) {
  double sum = 0;
  for (std::size_t k = 0; k < value.size(); ++k) {
    const QuestionMark& m = marks[static_cast<std::size_t>(at[k])];
    if (!m.given.readable()) return NAN;
    const double d = m.given.number - value[k];
    sum += d * d;
  }
  return std::sqrt(sum);
}
}  // namespace

bool ExerciseReview::follow_point(std::string_view group, std::span<const double> value, std::string_view from,
                                  std::string_view code) {
  int at[3];
  if (!coordinates_of(group, value.size(), at)) return false;
  bool any_open = false;
  for (std::size_t k = 0; k < value.size(); ++k) any_open = any_open || open_at(at[k]);
  if (!any_open) return false;
  const HotQuestion& first = key_.hot[static_cast<std::size_t>(at[0])];
  bool fit[3] = {};
  if (first.rule == ToleranceRule::Kind::distance) {
    // the point as a whole
    double abs = 0;
    for (std::size_t k = 0; k < value.size(); ++k) {
      const HotQuestion& q = key_.hot[static_cast<std::size_t>(at[k])];
      abs = std::max({abs, kMatchFactor * q.abs, q.follow_abs});
    }
    if (!(distance_to(marks_, at, value) <= abs)) return false;
    for (std::size_t k = 0; k < value.size(); ++k) fit[k] = open_at(at[k]);
  } else {
    bool any = false;
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::size_t i = static_cast<std::size_t>(at[k]);
      fit[k] = open_at(at[k]) && follows_within(key_.hot[i], marks_[i].given.number, value[k]);
      any = any || fit[k];
    }
    if (!any) return false;
  }
  if (!some_wrong(from)) return false;
  for (std::size_t k = 0; k < value.size(); ++k)
    if (fit[k]) credit(at[k], from, code, value[k]);
  return true;
}

bool ExerciseReview::follow_boolean(std::string_view field, bool value, std::string_view from, std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::boolean);
  if (!m || m->given.boolean != value || !some_wrong(from)) return false;
  credit(i, from, code, NAN);
  return true;
}

bool ExerciseReview::follow_word(std::string_view field, std::string_view w, std::string_view from,
                                 std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::choice);
  if (!m || m->given.word != w || !some_wrong(from)) return false;
  credit(i, from, code, NAN);
  return true;
}

bool ExerciseReview::follow_faces(std::string_view field, FaceBits value, std::string_view from, std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::faces);
  if (!m || m->given.faces != value || !some_wrong(from)) return false;
  credit(i, from, code, NAN);
  return true;
}

bool ExerciseReview::mistake(std::string_view field, double value, std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::number);
  if (!m || !within(key_.hot[i], m->given.number, value, kMatchFactor)) return false;
  marks_[i].mistake = code;
  marks_[i].value = value;
  return true;
}

bool ExerciseReview::mistake_point(std::string_view group, std::span<const double> value, std::string_view code) {
  int at[3];
  if (!coordinates_of(group, value.size(), at)) return false;
  // the coordinates given: all of them in the plane, two at least in space (one coordinate
  // fitting a mistake is a coincidence, not a diagnosis)
  bool any_open = false;
  std::size_t given = 0;
  for (std::size_t k = 0; k < value.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(at[k]);
    if (key_.hot[i].type != AnswerType::number) return false;
    if (marks_[i].given.readable()) ++given;
    any_open = any_open || open_at(at[k]);
  }
  if (!any_open || given < 2) return false;
  const HotQuestion& first = key_.hot[static_cast<std::size_t>(at[0])];
  if (first.rule == ToleranceRule::Kind::distance) {
    double abs = 0;
    for (std::size_t k = 0; k < value.size(); ++k) abs = std::max(abs, key_.hot[static_cast<std::size_t>(at[k])].abs);
    if (!(distance_to(marks_, at, value) <= kMatchFactor * abs)) return false;
  } else {
    // every coordinate given must fit the mistake, right ones included
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::size_t i = static_cast<std::size_t>(at[k]);
      if (marks_[i].given.readable() && !within(key_.hot[i], marks_[i].given.number, value[k], kMatchFactor))
        return false;
    }
  }
  for (std::size_t k = 0; k < value.size(); ++k) {
    if (!open_at(at[k])) continue;
    marks_[static_cast<std::size_t>(at[k])].mistake = code;
    marks_[static_cast<std::size_t>(at[k])].value = value[k];
  }
  return true;
}

bool ExerciseReview::fits(std::string_view field, double value) const {
  const int i = key_.find(field);
  const auto* m = readable_at(i, AnswerType::number);
  return !m || within(key_.hot[static_cast<std::size_t>(i)], m->given.number, value, kMatchFactor);
}

bool ExerciseReview::fits_point(std::string_view group, std::span<const double> value) const {
  static constexpr char kAxes[] = {'x', 'y', 'z'};
  for (std::size_t k = 0; k < value.size() && k < 3; ++k)
    if (!fits(coordinate(group, kAxes[k]), value[k])) return false;
  return true;
}

bool ExerciseReview::mistake_faces(std::string_view field, FaceBits value, std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::faces);
  if (!m || m->given.faces != value) return false;
  marks_[i].mistake = code;
  return true;
}

bool ExerciseReview::mistake_word(std::string_view field, std::string_view w, std::string_view code) {
  const int i = key_.find(field);
  if (!open_at(i)) return false;
  const auto* m = readable_at(i, AnswerType::choice);
  if (!m || m->given.word != w) return false;
  marks_[i].mistake = code;
  return true;
}

}  // namespace epure::grading
