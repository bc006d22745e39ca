#pragma once
// Class statistics, gathered as submissions stream past in memory that does not grow with
// their number: scores are counted by value (a sheet's scores take few distinct values), so
// the median is exact; questions and mistakes are counted by report column.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grading/item_analysis.h"
#include "grading/submission.h"

namespace epure::grading {

struct QuestionRate {
  std::string id;
  int asked = 0;     // marked submissions whose sheet asks it
  int credited = 0;  // full points (right, or follow-through credited)
  int follow_through = 0;
  int unanswered = 0;
  double rate() const { return asked ? double(credited) / asked : 0; }
};

struct MistakeCount {
  std::string_view code;
  std::string question;  // the question id it was seen on
  int count = 0;
};

struct HistogramBin {
  double from = 0, to = 0;  // [from, to), the last bin closed
  int count = 0;
};

class ClassStatistics {
 public:
  explicit ClassStatistics(std::vector<std::string> question_ids);

  void add(const Submission& s);

  int rows() const { return rows_; }
  int marked() const { return marked_; }
  double mean() const { return marked_ ? sum_ / marked_ : 0; }
  double median() const;
  double min() const;
  double max() const;
  // The most points a sheet of the key offers (every sheet of one spec offers the same).
  double max_points() const { return max_points_; }
  // The same, each score in percent of its own sheet's maximum: what a class's marks are
  // compared by (a sheet worth 0 points counts as 0 %).
  double mean_percent() const { return marked_ ? percent_sum_ / marked_ : 0; }
  double median_percent() const;
  double min_percent() const;
  double max_percent() const;

  const std::vector<QuestionRate>& questions() const { return questions_; }
  // Most frequent first (ties by question, then code); `limit` 0 for all.
  std::vector<MistakeCount> mistakes(std::size_t limit = 0) const;
  // Scores in `bins` equal bins over [0, max_points()], or one per point when that is fewer.
  std::vector<HistogramBin> histogram(int bins = 10) const;
  // Marks out of `out_of` (each score / its sheet's maximum × out_of) in `bins` equal bins.
  std::vector<HistogramBin> mark_histogram(double out_of, int bins) const;
  // Facility, discrimination, Cronbach's α, branches compared, mistakes and follow-through
  // (item_analysis.h).
  ItemAnalysis items() const { return items_.result(); }
  // Marked rows with answers to check (their scores are provisional).
  int to_check_rows() const { return to_check_rows_; }

 private:
  int rows_ = 0, marked_ = 0;
  double sum_ = 0, max_points_ = 0, percent_sum_ = 0;
  std::map<std::int64_t, int> scores_;    // score in thousandths → count
  std::map<std::int64_t, int> percents_;  // percent of the maximum in thousandths → count
  std::vector<QuestionRate> questions_;
  std::map<std::pair<int, std::string_view>, int> mistakes_;  // (question, code) → count
  ItemAccumulator items_;
  int to_check_rows_ = 0;
};

}  // namespace epure::grading
