#include "grading/marking.h"

#include "support/agrees.h"

#include <cmath>

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

// The generic mistake of every point answer, named before any kind looks: x and y typed the
// wrong way round. A coordinate pair is swapped when (given x, given y) is the expected (y, x),
// each within the key's tolerance of the value it stands for, and it is not the expected
// (x, y) (a point on the diagonal, x = y, is simply right).
void name_swapped_coordinates(const ExerciseKey& key, ExerciseMarks& out) {
  static constexpr std::string_view kSwapped = "swapped_coordinates";
  const std::size_t n = key.questions.size();
  for (std::size_t i = 0; i < n; ++i) {
    const QuestionKey& qx = key.questions[i];
    if (qx.point.empty() || qx.type != AnswerType::number || !qx.field.ends_with(".x")) continue;
    const std::string y_field = qx.field.substr(0, qx.field.size() - 1) + "y";
    const int j = key.find(y_field);
    if (j < 0) continue;
    QuestionMark &mx = out[i], &my = out[static_cast<std::size_t>(j)];
    if (!mx.given.readable() || !my.given.readable()) continue;
    if (mx.verdict != Verdict::wrong && my.verdict != Verdict::wrong) continue;
    const HotQuestion& hx = key.hot[i];
    const HotQuestion& hy = key.hot[static_cast<std::size_t>(j)];
    bool swapped = false;
    if (hx.rule == ToleranceRule::Kind::distance) {
      const double abs = std::max(hx.abs, hy.abs);
      swapped = std::hypot(mx.given.number - hy.number, my.given.number - hx.number) <= abs;
    } else {
      // the x given stands for the expected y: the y question's tolerance, and the other way
      swapped = within_rule_of(hy, mx.given.number, hy.number) && within_rule_of(hx, my.given.number, hx.number);
    }
    if (!swapped) continue;
    for (QuestionMark* m : {&mx, &my})
      if (m->verdict == Verdict::wrong && m->mistake.empty()) m->mistake = kSwapped;
  }
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
  // Points marked as a whole: right when the given point is within the distance.
  for (std::size_t i = 0; i < n; ++i) {
    const int j = key.hot[i].partner;
    if (j < 0 || static_cast<std::size_t>(j) < i) continue;
    QuestionMark &a = out[i], &b = out[static_cast<std::size_t>(j)];
    if (a.verdict != Verdict::wrong && b.verdict != Verdict::wrong) continue;  // neither readable
    const HotQuestion& qa = key.hot[i];
    const HotQuestion& qb = key.hot[static_cast<std::size_t>(j)];
    const bool both = a.given.readable() && b.given.readable();
    const double abs = std::max(qa.abs, qb.abs);
    if (both && std::hypot(a.given.number - qa.number, b.given.number - qb.number) <= abs) {
      a.verdict = b.verdict = Verdict::right;
      a.points = qa.points;
      b.points = qb.points;
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
