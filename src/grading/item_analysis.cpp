#include "grading/item_analysis.h"

#include <algorithm>
#include <cmath>

#include "grading/welch_test.h"

namespace epure::grading {

void Moments::add(double x, double y) {
  n += 1;
  const double dx = x - mean_x, dy = y - mean_y;
  mean_x += dx / n;
  mean_y += dy / n;
  m2_x += dx * (x - mean_x);
  m2_y += dy * (y - mean_y);
  c_xy += dx * (y - mean_y);
}

void Moments::merge(const Moments& o) {
  if (o.n == 0) return;
  if (n == 0) {
    *this = o;
    return;
  }
  const double total = n + o.n;
  const double dx = o.mean_x - mean_x, dy = o.mean_y - mean_y;
  m2_x += o.m2_x + dx * dx * n * o.n / total;
  m2_y += o.m2_y + dy * dy * n * o.n / total;
  c_xy += o.c_xy + dx * dy * n * o.n / total;
  mean_x += dx * o.n / total;
  mean_y += dy * o.n / total;
  n = total;
}

std::optional<double> Moments::correlation() const {
  // a stream that does not vary has no correlation: its second moment is 0 up to the rounding of
  // the updates, which is far below any real variation of marks (quarter points)
  constexpr double kConstant = 1e-12;
  if (n < 3 || m2_x <= kConstant * n || m2_y <= kConstant * n) return std::nullopt;
  return std::clamp(c_xy / std::sqrt(m2_x * m2_y), -1.0, 1.0);
}

ItemAccumulator::ItemAccumulator(std::vector<std::string> question_ids)
    : ids_(std::move(question_ids)), questions_(ids_.size()) {}

void ItemAccumulator::add(const Submission& s) {
  if (!s.marked()) return;
  ++submissions_;
  if (s.to_check > 0) provisional_ = true;
  score_.add(s.score);
  if (exercises_.empty()) exercises_.resize(s.marks.size());
  if (exercises_.size() != s.marks.size()) same_shape_ = false;
  for (std::size_t e = 0; e < s.marks.size(); ++e) {
    const ExerciseKey& ex = s.sheet->exercises[e];
    const ExerciseMarks& marks = s.marks[e];
    const auto& index = s.report_index[e];
    double earned = 0, worth = 0;
    Exercise* X = e < exercises_.size() ? &exercises_[e] : nullptr;
    for (std::size_t q = 0; q < marks.size(); ++q) {
      const QuestionMark& m = marks[q];
      const double full = ex.hot[q].points;
      earned += m.points;
      worth += full;
      Question& Q = questions_[static_cast<std::size_t>(index[q])];
      Q.exercise = e;
      if (m.verdict == Verdict::to_check) {
        ++Q.to_check;
        continue;
      }
      const double x = full > 0 ? m.points / full : 0;
      Q.xr.add(x, s.score - m.points);
      if (m.verdict == Verdict::follow_through) {
        ++Q.follow_through;
        Q.follow_through_points += m.points;
        if (X) {
          ++X->follow_through;
          X->follow_through_points += m.points;
        }
      }
      if (X && first_naming(marks, q)) ++X->mistakes[m.mistake];
    }
    if (!X) continue;
    if (X->kind.empty()) {
      X->kind = ex.kind;
      X->n = ex.n;
      X->number = ex.number;
    }
    X->y.add(earned);
    X->max_points = std::max(X->max_points, worth);
    const double share = worth > 0 ? earned / worth : 0;
    X->share.add(share);
    if (!X->last_branch || *X->last_branch != ex.branch) {
      auto it = X->branches.find(ex.branch);
      if (it == X->branches.end()) it = X->branches.emplace(ex.branch, Moments{}).first;
      X->last_branch = &ex.branch;
      X->last_moments = &it->second;
    }
    X->last_moments->add(share);
  }
}

ItemAnalysis ItemAccumulator::result() const {
  ItemAnalysis a;
  a.submissions = submissions_;
  a.provisional = provisional_;
  for (std::size_t i = 0; i < questions_.size(); ++i) {
    const Question& Q = questions_[i];
    if (Q.xr.n == 0 && Q.to_check == 0) continue;
    QuestionItem item;
    item.id = ids_[i];
    item.exercise = Q.exercise;
    item.answers = static_cast<int>(Q.xr.n);
    item.facility = Q.xr.mean_x;
    item.discrimination = Q.xr.correlation();
    item.follow_through = Q.follow_through;
    item.follow_through_points = Q.follow_through_points;
    item.to_check = Q.to_check;
    a.questions.push_back(std::move(item));
    a.follow_through += Q.follow_through;
    a.follow_through_points += Q.follow_through_points;
  }
  std::map<std::string_view, MistakeTotal> totals;
  double item_variances = 0;
  for (std::size_t e = 0; e < exercises_.size(); ++e) {
    const Exercise& X = exercises_[e];
    ExerciseItem item;
    item.index = e;
    item.n = X.n;
    item.number = X.number;
    item.kind = X.kind;
    item.submissions = static_cast<int>(X.y.n);
    item.max_points = X.max_points;
    item.facility = X.share.mean_x;
    item.variance = X.y.variance_x();
    item.follow_through = X.follow_through;
    item.follow_through_points = X.follow_through_points;
    item.mistakes = X.mistakes;
    item_variances += item.variance;
    for (const auto& [code, count] : X.mistakes) {
      MistakeTotal& t = totals[code];
      t.code = code;
      t.count += count;
      t.by_exercise.emplace_back(e, count);
    }
    a.exercises.push_back(std::move(item));
    // each branch against the others of its exercise
    const std::size_t first = a.branches.size();
    int tested = 0;
    for (const auto& [name, m] : X.branches) {
      BranchItem b;
      b.exercise = e;
      b.branch = name;
      b.submissions = static_cast<int>(m.n);
      b.facility = m.mean_x;
      b.sd = std::sqrt(m.variance_x());
      Moments others;
      for (const auto& [other, o] : X.branches)
        if (other != name) others.merge(o);
      if (others.n > 0) b.others_facility = others.mean_x;
      if (auto w = welch_lower(m.n, m.mean_x, m.variance_x(), others.n, others.mean_x, others.variance_x())) {
        b.t = w->t;
        b.df = w->df;
        b.p = w->p;
        ++tested;
      }
      a.branches.push_back(std::move(b));
    }
    for (std::size_t i = first; i < a.branches.size(); ++i) {
      BranchItem& b = a.branches[i];
      b.tested = b.p ? tested : 0;
      b.harder = b.p && *b.p < kBranchAlpha / tested;
    }
  }
  a.alpha_items = static_cast<int>(exercises_.size());
  a.score_variance = score_.variance_x();
  // the score's variance is 0 up to rounding when every student has the same score
  if (same_shape_ && submissions_ >= 2 && a.alpha_items >= 2 && a.score_variance > 1e-12) {
    const double k = a.alpha_items;
    a.alpha = k / (k - 1) * (1 - item_variances / a.score_variance);
  }
  for (auto& [code, t] : totals) a.mistakes.push_back(std::move(t));
  std::stable_sort(a.mistakes.begin(), a.mistakes.end(),
                   [](const MistakeTotal& x, const MistakeTotal& y) { return x.count > y.count; });
  return a;
}

}  // namespace epure::grading
