// Class statistics from counts: mean, exact median, histogram bins, mistakes by frequency.
#include <doctest/doctest.h>

#include <utility>
#include <vector>

#include "grading/statistics.h"

using namespace epure::grading;

namespace {
SheetKey one_question_sheet() {
  SheetKey s;
  ExerciseKey e;
  e.n = 1;
  QuestionKey q;
  q.id = "1.t";
  q.points = 10;
  e.questions.push_back(q);
  HotQuestion h;
  h.points = 10;
  e.hot.push_back(h);
  s.exercises.push_back(e);
  s.max_points = 10;
  return s;
}
}  // namespace

TEST_CASE("mean, median, range and histogram of scores") {
  const SheetKey sheet = one_question_sheet();
  ClassStatistics stats({"1.t"});
  std::vector<int> index = {0};
  std::vector<std::vector<int>> report_index = {index};
  for (double score : {2.0, 10.0, 4.0, 7.5}) {
    ExerciseMarks marks(1);
    marks[0].verdict = score == 10 ? Verdict::right : Verdict::wrong;
    marks[0].points = score;
    if (score == 2) marks[0].mistake = "far_intersection";
    std::vector<ExerciseMarks> all = {marks};
    Submission s;
    s.sheet = &sheet;
    s.marks = all;
    s.report_index = report_index;
    s.score = score;
    s.max = 10;
    stats.add(s);
  }
  Submission unmarked;
  stats.add(unmarked);
  CHECK(stats.rows() == 5);
  CHECK(stats.marked() == 4);
  CHECK(stats.mean() == doctest::Approx(5.875).epsilon(1e-12));
  CHECK(stats.median() == doctest::Approx(5.75).epsilon(1e-12));  // (4 + 7.5)/2
  CHECK(stats.min() == doctest::Approx(2).epsilon(1e-12));
  CHECK(stats.max() == doctest::Approx(10).epsilon(1e-12));
  // out of 10: the same in percent
  CHECK(stats.mean_percent() == doctest::Approx(58.75).epsilon(1e-12));
  CHECK(stats.median_percent() == doctest::Approx(57.5).epsilon(1e-12));
  CHECK(stats.min_percent() == doctest::Approx(20).epsilon(1e-12));
  CHECK(stats.max_percent() == doctest::Approx(100).epsilon(1e-12));
  CHECK(stats.questions()[0].asked == 4);
  CHECK(stats.questions()[0].credited == 1);
  const auto bins = stats.histogram(5);
  REQUIRE(bins.size() == 5);
  CHECK(bins[1].count == 1);  // 2 in [2, 4)
  CHECK(bins[2].count == 1);  // 4
  CHECK(bins[3].count == 1);  // 7.5
  CHECK(bins[4].count == 1);  // 10, the last bin closed
  const auto mistakes = stats.mistakes();
  REQUIRE(mistakes.size() == 1);
  CHECK(mistakes[0].count == 1);
  CHECK(mistakes[0].code == "far_intersection");
  CHECK(mistakes[0].question == "1.t");
}

TEST_CASE("percent of the maximum: each score against its own sheet's maximum") {
  // two sheets of different maxima (a key from before every sheet was worth the same): the
  // percentages are compared, not the raw points
  const SheetKey sheet = one_question_sheet();
  ClassStatistics stats({"1.t"});
  std::vector<std::vector<int>> report_index = {{0}};
  for (auto [score, max] : {std::pair{5.0, 10.0}, std::pair{3.0, 4.0}, std::pair{0.0, 0.0}}) {
    ExerciseMarks marks(1);
    marks[0].points = score;
    std::vector<ExerciseMarks> all = {marks};
    Submission s;
    s.sheet = &sheet;
    s.marks = all;
    s.report_index = report_index;
    s.score = score;
    s.max = max;
    stats.add(s);
  }
  CHECK(stats.mean_percent() == doctest::Approx((50.0 + 75.0 + 0.0) / 3).epsilon(1e-12));  // a sheet worth 0: 0 %
  CHECK(stats.median_percent() == doctest::Approx(50).epsilon(1e-12));
  CHECK(stats.max_percent() == doctest::Approx(75).epsilon(1e-12));
}
