#include "grading/typed_cells.h"

#include <array>
#include <cmath>

#include "grading/answer_reading.h"
#include "support/agrees.h"

namespace epure::grading {

namespace {

bool within_hot(const HotQuestion& q, double given) {
  if (!std::isfinite(given)) return false;
  const double d = std::abs(given - q.number);
  switch (q.rule) {
    case ToleranceRule::Kind::isclose: return d <= std::max(q.rel * std::abs(q.number), q.abs);
    case ToleranceRule::Kind::distance: return d <= q.abs;
    case ToleranceRule::Kind::exact: break;
  }
  return agrees(given, q.number);
}

bool blank(std::string_view cell) { return trim_cell(cell).empty(); }

// Settles one coordinate read from a part of a cell.
void mark_read(const HotQuestion& q, QuestionMark& m) {
  m.points = 0;
  if (!m.given.readable()) {
    m.verdict = Verdict::to_check;
  } else if (q.partner >= 0) {
    m.verdict = Verdict::wrong;  // decided with its partner
  } else if (equal_by_rule(q, m.given)) {
    m.verdict = Verdict::right;
    m.points = q.points;
  } else {
    m.verdict = Verdict::wrong;
  }
}

}  // namespace

bool equal_by_rule(const HotQuestion& q, const Given& g) {
  switch (q.type) {
    case AnswerType::point:  // never a key's question: read as the number it would be
    case AnswerType::number: return within_hot(q, g.number);
    case AnswerType::boolean: return g.boolean == q.boolean;
    case AnswerType::choice: return g.word.data() == q.word;
    case AnswerType::faces: return g.faces == q.faces;
  }
  return false;
}

void read_points_in_one_cell(const ExerciseKey& key, std::span<const std::string_view> cells, bool decimal_comma,
                             ExerciseMarks& out) {
  const std::size_t n = key.questions.size();
  const auto cell = [&](int i) { return static_cast<std::size_t>(i) < cells.size() ? cells[static_cast<std::size_t>(i)] : std::string_view{}; };
  for (std::size_t i = 0; i < n; ++i) {
    const QuestionKey& first = key.questions[i];
    if (first.point.empty() || first.type != AnswerType::number || !first.field.ends_with(".x")) continue;
    const std::string_view group(first.field.data(), first.field.size() - 2);
    std::array<int, 3> at{static_cast<int>(i), -1, -1};
    int dims = 1;
    for (const char axis : {'y', 'z'}) {
      char name[32];
      if (group.size() + 2 > sizeof name) break;
      std::copy(group.begin(), group.end(), name);
      name[group.size()] = '.';
      name[group.size() + 1] = axis;
      const int k = key.find(std::string_view(name, group.size() + 2));
      if (k < 0) break;
      at[static_cast<std::size_t>(dims++)] = k;
    }
    if (dims < 2) continue;
    int holder = -1, filled = 0;
    for (int d = 0; d < dims; ++d)
      if (!blank(cell(at[static_cast<std::size_t>(d)]))) holder = at[static_cast<std::size_t>(d)], ++filled;
    if (filled != 1) continue;
    std::array<std::string_view, 3> parts{};
    const PointCell read = read_point_cell(cell(holder), dims, decimal_comma, parts);
    if (read == PointCell::not_a_point) continue;
    for (int d = 0; d < dims; ++d) {
      const auto k = static_cast<std::size_t>(at[static_cast<std::size_t>(d)]);
      QuestionMark& m = out[k];
      m.mistake = {};
      m.note = {};
      if (read == PointCell::ambiguous) {
        m.given = Given{};
        m.given.state = Given::State::unreadable;
        m.given.raw = trim_cell(cell(holder));
        m.given.why = "ambiguous_point";
        m.verdict = Verdict::to_check;
        m.points = 0;
        continue;
      }
      read_answer(parts[static_cast<std::size_t>(d)], AnswerType::number, m.given);
      m.note = "point_in_one_cell";
      mark_read(key.hot[k], m);
    }
  }
}

void read_swapped_cells(const ExerciseKey& key, std::span<const std::string_view> cells, ExerciseMarks& out) {
  const std::size_t n = key.questions.size();
  const auto open = [&](std::size_t i) {
    const Verdict v = out[i].verdict;
    return (v == Verdict::wrong || v == Verdict::to_check) && out[i].mistake.empty() && out[i].note.empty() &&
           i < cells.size() && !blank(cells[i]);
  };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const std::size_t j = i + 1;
    if (!open(i) || !open(j)) continue;
    const QuestionKey &qi = key.questions[i], &qj = key.questions[j];
    if (!qi.point.empty() && qi.point == qj.point) continue;
    if (qi.type == AnswerType::boolean && qj.type == AnswerType::boolean) continue;
    const HotQuestion &hi = key.hot[i], &hj = key.hot[j];
    Given as_i, as_j;  // cell j read for question i, cell i for question j
    read_answer(cells[j], qi.type, as_i);
    read_answer(cells[i], qj.type, as_j);
    if (!as_i.readable() || !as_j.readable() || !equal_by_rule(hi, as_i) || !equal_by_rule(hj, as_j)) continue;
    for (auto [m, given, q, other] : {std::tuple{&out[i], &as_i, &hi, &qj}, std::tuple{&out[j], &as_j, &hj, &qi}}) {
      m->given = *given;
      m->verdict = Verdict::right;
      m->points = q->points;
      m->mistake = {};
      m->note = "swapped_cells";
      m->note_field = other->id;
    }
    ++i;
  }
}

}  // namespace epure::grading
