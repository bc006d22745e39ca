#include "grading/statistics.h"

#include <algorithm>
#include <cmath>

namespace epure::grading {

namespace {

std::int64_t thousandths(double score) { return std::llround(score * 1000); }

// The median of values counted in thousandths: the mean of the two middle ones when the count
// is even.
double median_of(const std::map<std::int64_t, int>& counted, int total) {
  if (total == 0) return 0;
  const int lo = (total - 1) / 2, hi = total / 2;
  int seen = 0;
  double a = 0, b = 0;
  bool have_a = false;
  for (const auto& [value, count] : counted) {
    if (!have_a && seen + count > lo) {
      a = value / 1000.0;
      have_a = true;
    }
    if (seen + count > hi) {
      b = value / 1000.0;
      break;
    }
    seen += count;
  }
  return (a + b) / 2;
}

}  // namespace

ClassStatistics::ClassStatistics(std::vector<std::string> question_ids) : items_(question_ids) {
  for (auto& id : question_ids) questions_.push_back(QuestionRate{std::move(id)});
}

void ClassStatistics::add(const Submission& s) {
  ++rows_;
  if (!s.marked()) return;
  ++marked_;
  items_.add(s);
  if (s.to_check > 0) ++to_check_rows_;
  sum_ += s.score;
  max_points_ = std::max(max_points_, s.max);
  ++scores_[thousandths(s.score)];
  const double percent = s.max > 0 ? 100 * s.score / s.max : 0;
  percent_sum_ += percent;
  ++percents_[thousandths(percent)];
  for (std::size_t e = 0; e < s.marks.size(); ++e) {
    const auto& marks = s.marks[e];
    const auto& index = s.report_index[e];
    for (std::size_t q = 0; q < marks.size(); ++q) {
      QuestionRate& r = questions_[static_cast<std::size_t>(index[q])];
      const QuestionMark& m = marks[q];
      ++r.asked;
      const double full = s.sheet->exercises[e].hot[q].points;
      if (m.points >= full && (m.verdict == Verdict::right || m.verdict == Verdict::follow_through)) ++r.credited;
      if (m.verdict == Verdict::follow_through) ++r.follow_through;
      if (m.verdict == Verdict::unanswered) ++r.unanswered;
      if (first_naming(marks, q)) ++mistakes_[{index[q], m.mistake}];  // where it was first named
    }
  }
}

double ClassStatistics::median() const { return median_of(scores_, marked_); }
double ClassStatistics::median_percent() const { return median_of(percents_, marked_); }

double ClassStatistics::min() const { return scores_.empty() ? 0 : scores_.begin()->first / 1000.0; }
double ClassStatistics::max() const { return scores_.empty() ? 0 : scores_.rbegin()->first / 1000.0; }
double ClassStatistics::min_percent() const { return percents_.empty() ? 0 : percents_.begin()->first / 1000.0; }
double ClassStatistics::max_percent() const { return percents_.empty() ? 0 : percents_.rbegin()->first / 1000.0; }

std::vector<MistakeCount> ClassStatistics::mistakes(std::size_t limit) const {
  std::vector<MistakeCount> out;
  for (const auto& [at, count] : mistakes_) out.push_back({at.second, questions_[at.first].id, count});
  std::stable_sort(out.begin(), out.end(), [](const MistakeCount& a, const MistakeCount& b) { return a.count > b.count; });
  if (limit && out.size() > limit) out.resize(limit);
  return out;
}

std::vector<HistogramBin> ClassStatistics::mark_histogram(double out_of, int bins) const {
  const int n = std::max(1, bins);
  const double width = out_of / n;
  std::vector<HistogramBin> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = {i * width, (i + 1) * width, 0};
  for (const auto& [percent, count] : percents_) {
    const double mark = percent / 1000.0 / 100 * out_of;
    // a mark on a bin's upper edge belongs to the next bin (the last one closed); the rounding
    // of the percent's thousandths must not push 10/20 into [9, 10)
    int i = static_cast<int>(std::floor(mark / width + 1e-9));
    i = std::clamp(i, 0, n - 1);
    out[static_cast<std::size_t>(i)].count += count;
  }
  return out;
}

std::vector<HistogramBin> ClassStatistics::histogram(int bins) const {
  const double top = std::max(1.0, std::ceil(max_points_));
  const int n = std::max(1, std::min(bins, static_cast<int>(top)));
  const double width = top / n;
  std::vector<HistogramBin> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[i] = {i * width, (i + 1) * width, 0};
  for (const auto& [score, count] : scores_) {
    const double s = score / 1000.0;
    int i = static_cast<int>(std::floor(s / width));
    i = std::clamp(i, 0, n - 1);
    out[static_cast<std::size_t>(i)].count += count;
  }
  return out;
}

}  // namespace epure::grading
