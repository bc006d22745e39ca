#include "grading/marking.h"

#include "support/agrees.h"

#include <array>
#include <cmath>
#include <span>

#include "grading/answer_reading.h"
#include "grading/kind_grader.h"
#include "grading/review.h"
#include "grading/typed_cells.h"

namespace epure::grading {

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::right: return "right";
    case Verdict::follow_through: return "follow_through";
    case Verdict::wrong: return "wrong";
    case Verdict::unanswered: return "unanswered";
    case Verdict::to_check: return "to_check";
  }
  return "?";
}

namespace {

// Whether `given` is what the question `q` expects, by q's rule, for the value `target`.
bool within_rule_of(const HotQuestion& q, double given, double target) {
  if (!std::isfinite(given)) return false;
  const double d = std::abs(given - target);
  switch (q.rule) {
    case ToleranceRule::Kind::isclose: return d <= std::max(q.rel * std::abs(target), q.abs);
    case ToleranceRule::Kind::distance: return d <= q.abs;
    case ToleranceRule::Kind::exact: break;
  }
  return agrees(given, target);
}

// The coordinates of each point the key groups (in the plane x, y; in space x, y, z), in the
// order asked: the questions of one `point`, at most three.
template <class Fn>
void each_point(const ExerciseKey& key, Fn&& fn) {
  const std::size_t n = key.questions.size();
  for (std::size_t i = 0; i < n; ++i) {
    const QuestionKey& first = key.questions[i];
    if (first.point.empty() || first.type != AnswerType::number) continue;
    bool seen = false;  // an earlier question of the same point began it
    for (std::size_t j = 0; j < i && !seen; ++j) seen = key.questions[j].point == first.point;
    if (seen) continue;
    std::array<std::size_t, 3> at{i};
    std::size_t size = 1;
    for (std::size_t j = i + 1; j < n && size < 3; ++j)
      if (key.questions[j].point == first.point && key.questions[j].type == AnswerType::number) at[size++] = j;
    if (size >= 2) fn(std::span<const std::size_t>(at.data(), size));
  }
}

// The generic mistake of every point answer, named before any kind looks: two coordinates typed
// the wrong way round (x and y; in space any two). Two coordinates are swapped when each given
// value is the other's expected one, within the key's tolerance of the value it stands for (the
// point as a whole, for a point marked by distance), and one of them is wrong (a point on the
// diagonal, x = y, is simply right).
void name_swapped_coordinates(const ExerciseKey& key, ExerciseMarks& out) {
  static constexpr std::string_view kSwapped = "swapped_coordinates";
  each_point(key, [&](std::span<const std::size_t> at) {
    for (std::size_t a = 0; a < at.size(); ++a)
      for (std::size_t b = a + 1; b < at.size(); ++b) {
        QuestionMark &ma = out[at[a]], &mb = out[at[b]];
        if (!ma.given.readable() || !mb.given.readable()) continue;
        if (ma.verdict != Verdict::wrong && mb.verdict != Verdict::wrong) continue;
        const HotQuestion& ha = key.hot[at[a]];
        const HotQuestion& hb = key.hot[at[b]];
        bool swapped = false;
        if (ha.rule == ToleranceRule::Kind::distance) {
          double abs = 0, sum = 0;
          bool readable = true;
          for (std::size_t k = 0; k < at.size(); ++k) {
            const QuestionMark& m = out[at[k]];
            readable = readable && m.given.readable();
            abs = std::max(abs, key.hot[at[k]].abs);
            const double stands_for = k == a ? hb.number : k == b ? ha.number : key.hot[at[k]].number;
            const double d = m.given.number - stands_for;
            sum += d * d;
          }
          swapped = readable && std::sqrt(sum) <= abs;
        } else {
          // the given a stands for the expected b: b's tolerance, and the other way
          swapped = within_rule_of(hb, ma.given.number, hb.number) && within_rule_of(ha, mb.given.number, ha.number);
          // Two expected values that are each other's opposites: the pair given is then also
          // both signs changed (v∧u for u∧v, −N for N), a slip of the whole point that the
          // kind's method names; a swap would count it twice.
          if (swapped && within_rule_of(ha, ma.given.number, -ha.number) && within_rule_of(hb, mb.given.number, -hb.number))
            swapped = false;
        }
        if (!swapped) continue;
        for (QuestionMark* m : {&ma, &mb})
          if (m->verdict == Verdict::wrong && m->mistake.empty()) m->mistake = kSwapped;
      }
  });
}

}  // namespace

void mark_exercise(const ExerciseKey& key, std::span<const std::string_view> cells, const MarkingOptions& options,
                   ExerciseMarks& out) {
  const std::size_t n = key.questions.size();
  out.resize(n);
  bool any_blank = false, any_open = false;  // open: read, but not (yet) right
  for (std::size_t i = 0; i < n; ++i) {
    const HotQuestion& q = key.hot[i];
    QuestionMark& m = out[i];
    read_answer(i < cells.size() ? cells[i] : std::string_view{}, q.type, m.given);
    m.points = 0;
    m.mistake = {};
    m.from = {};
    m.detail.clear();
    m.value = NAN;
    m.note = {};
    m.note_field = {};
    m.corrected = false;
    switch (m.given.state) {
      case Given::State::blank:
        m.verdict = Verdict::unanswered;
        any_blank = true;
        break;
      case Given::State::unreadable:
        m.verdict = Verdict::to_check;
        any_open = true;
        break;
      case Given::State::value:
        if (q.partner >= 0) {
          m.verdict = Verdict::wrong;  // decided below, with its partner
          any_open = true;
        } else if (equal_by_rule(q, m.given)) {
          m.verdict = Verdict::right;
          m.points = q.points;
        } else {
          m.verdict = Verdict::wrong;
          any_open = true;
        }
        break;
    }
  }
  // answers typed where or as not asked (typed_cells.h): a point in one cell
  if (any_blank && any_open) read_points_in_one_cell(key, cells, options.numbers.decimal_comma, out);
  // Points marked as a whole: right when the given point is within the distance (its
  // coordinates in a ring of partners, answer_key.cpp, walked once from the first).
  for (std::size_t i = 0; i < n; ++i) {
    if (key.hot[i].partner < 0) continue;
    std::array<std::size_t, 3> at{i};
    std::size_t size = 1;
    bool first = true;
    for (int j = key.hot[i].partner; j >= 0 && static_cast<std::size_t>(j) != i && size < 3; j = key.hot[static_cast<std::size_t>(j)].partner) {
      if (static_cast<std::size_t>(j) < i) first = false;
      at[size++] = static_cast<std::size_t>(j);
    }
    if (!first) continue;
    bool any_wrong = false, readable = true;
    double abs = 0, sum = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const QuestionMark& m = out[at[k]];
      const HotQuestion& q = key.hot[at[k]];
      any_wrong = any_wrong || m.verdict == Verdict::wrong;
      readable = readable && m.given.readable();
      abs = std::max(abs, q.abs);
      const double d = m.given.number - q.number;
      sum += d * d;
    }
    if (!any_wrong || !readable || !(std::sqrt(sum) <= abs)) continue;  // none readable, or off
    for (std::size_t k = 0; k < size; ++k) {
      out[at[k]].verdict = Verdict::right;
      out[at[k]].points = key.hot[at[k]].points;
    }
  }
  if (!any_open) return;
  bool any_wrong = false;
  for (const QuestionMark& m : out) any_wrong = any_wrong || m.verdict == Verdict::wrong;
  if (any_wrong) {
    name_swapped_coordinates(key, out);
    if (key.grader) {
      ExerciseReview review(key, out, options.follow_through, options.numbers, options.decimals);
      key.grader->review(key.prepared, review);
    }
  }
  // two neighbouring answers typed in each other's cell, where the kind's method names no
  // mistake that explains them (t_ab and t_cd swapped is the segments' own "t_swapped")
  read_swapped_cells(key, cells, out);
}

}  // namespace epure::grading
