// Item analysis on a class small enough to work by hand: facility, item–rest discrimination,
// Cronbach's α over the exercises, branches compared by Welch's test, mistakes and
// follow-through counted. (tests/cli/grade_class.sh checks a French class of 10 against an
// independent Python reference, tests/tools/item_analysis.py.)
#include <doctest/doctest.h>

#include <cmath>

#include "grading/item_analysis.h"
#include "grading/statistics.h"
#include "grading/welch_test.h"

using namespace epure::grading;

namespace {
SheetKey sheet(const std::string& branch) {
  SheetKey s;
  for (int n : {1, 2}) {
    ExerciseKey e;
    e.n = n;
    e.kind = n == 1 ? "projection" : "segments";
    e.branch = n == 1 ? branch : "intersects";
    for (const char* f : {"a", "b"}) {
      QuestionKey q;
      q.id = std::to_string(n) + "." + f;
      q.points = 1;
      e.questions.push_back(q);
      HotQuestion h;
      h.points = 1;
      e.hot.push_back(h);
    }
    s.exercises.push_back(e);
  }
  s.max_points = 4;
  return s;
}
}  // namespace

TEST_CASE("item analysis of four students, worked by hand") {
  // points on 1.a 1.b 2.a 2.b; exercise 1 drew branch "a" for S1, S2 and "b" for S3, S4
  //   S1  1 1 1 1 = 4     S2  1 0 1 0 = 2     S3  0 0 1 1 = 2     S4  0 0 0 0 = 0
  const SheetKey A = sheet("a"), B = sheet("b");
  const std::vector<std::string> ids = {"1.a", "1.b", "2.a", "2.b"};
  ClassStatistics stats(ids);
  const std::vector<std::vector<int>> index = {{0, 1}, {2, 3}};
  const int points[4][4] = {{1, 1, 1, 1}, {1, 0, 1, 0}, {0, 0, 1, 1}, {0, 0, 0, 0}};
  for (int i = 0; i < 4; ++i) {
    std::vector<ExerciseMarks> marks(2, ExerciseMarks(2));
    double score = 0;
    for (int q = 0; q < 4; ++q) {
      QuestionMark& m = marks[static_cast<std::size_t>(q / 2)][static_cast<std::size_t>(q % 2)];
      m.points = points[i][q];
      m.verdict = m.points > 0 ? Verdict::right : Verdict::wrong;
      score += m.points;
    }
    if (i == 1) marks[0][1].mistake = "t_unsquared_norm";
    if (i == 2) marks[1][1].verdict = Verdict::follow_through;
    if (i == 3) marks[1][0].mistake = "t_swapped";
    Submission s;
    s.sheet = i < 2 ? &A : &B;
    s.marks = marks;
    s.report_index = index;
    s.score = score;
    s.max = 4;
    stats.add(s);
  }
  const ItemAnalysis a = stats.items();
  CHECK(a.submissions == 4);
  CHECK_FALSE(a.provisional);
  REQUIRE(a.questions.size() == 4);
  SUBCASE("1. facility: the share of the class that earned it") {
    CHECK(a.questions[0].facility == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(a.questions[1].facility == doctest::Approx(0.25).epsilon(1e-12));
    CHECK(a.questions[2].facility == doctest::Approx(0.75).epsilon(1e-12));
  }
  SUBCASE("2. discrimination: 1.a against the rest 3, 1, 2, 0 gives r = 1/√5") {
    REQUIRE(a.questions[0].discrimination);
    CHECK(*a.questions[0].discrimination == doctest::Approx(1 / std::sqrt(5.0)).epsilon(1e-12));
    // 1.b (1, 0, 0, 0) against 3, 2, 2, 0: Σdxdr = 0.75·1.25 − 0.25·(0.25 + 0.25 − 1.75) = 1.25,
    // Σdx² = 0.75, Σdr² = 4.75: r = 1.25 / √(0.75 · 4.75)
    CHECK(*a.questions[1].discrimination == doctest::Approx(1.25 / std::sqrt(0.75 * 4.75)).epsilon(1e-12));
  }
  SUBCASE("3. Cronbach's α: exercises 2, 1, 0, 0 and 2, 1, 2, 0, scores 4, 2, 2, 0") {
    // s² = 11/12 each, s²(S) = 8/3: α = 2 · (1 − (11/6) / (8/3)) = 0.625
    REQUIRE(a.alpha);
    CHECK(*a.alpha == doctest::Approx(0.625).epsilon(1e-12));
    CHECK(a.alpha_items == 2);
  }
  SUBCASE("4. branches: b (0, 0) against a (1, 0.5): t = 3, ν = 1, p = ½ − atan(3)/π, not below 0.05/2") {
    REQUIRE(a.branches.size() == 3);  // exercise 1: a, b; exercise 2: intersects (alone: not tested)
    const BranchItem& b = a.branches[1];
    CHECK(b.branch == "b");
    CHECK(b.facility == 0);
    CHECK(*b.others_facility == doctest::Approx(0.75).epsilon(1e-12));
    CHECK(*b.t == doctest::Approx(3).epsilon(1e-12));
    CHECK(*b.df == doctest::Approx(1).epsilon(1e-12));
    CHECK(*b.p == doctest::Approx(0.5 - std::atan(3.0) / M_PI).epsilon(1e-12));
    CHECK(b.tested == 2);
    CHECK_FALSE(b.harder);
    CHECK(*a.branches[0].p == doctest::Approx(0.5 + std::atan(3.0) / M_PI).epsilon(1e-12));
    CHECK_FALSE(a.branches[2].p);
  }
  SUBCASE("5. mistakes per code and exercise, follow-through in answers and points") {
    REQUIRE(a.mistakes.size() == 2);
    CHECK(a.mistakes[0].count == 1);
    CHECK(a.follow_through == 1);
    CHECK(a.follow_through_points == doctest::Approx(1).epsilon(1e-12));
    CHECK(a.exercises[0].mistakes.at("t_unsquared_norm") == 1);
    CHECK(a.exercises[1].follow_through == 1);
  }
}

TEST_CASE("a branch significantly harder than the others is flagged") {
  // exercise 1: 6 sheets of branch "a" all right, 6 of branch "b" mostly wrong
  const SheetKey A = sheet("a"), B = sheet("b");
  ClassStatistics stats({"1.a", "1.b", "2.a", "2.b"});
  const std::vector<std::vector<int>> index = {{0, 1}, {2, 3}};
  for (int i = 0; i < 12; ++i) {
    std::vector<ExerciseMarks> marks(2, ExerciseMarks(2));
    const bool hard = i >= 6;
    marks[0][0].points = hard ? (i == 6 ? 1 : 0) : 1;
    marks[0][1].points = hard ? 0 : (i == 0 ? 0 : 1);
    marks[1][0].points = i % 2;
    marks[1][1].points = 1;
    double score = 0;
    for (auto& e : marks)
      for (auto& m : e) {
        m.verdict = m.points > 0 ? Verdict::right : Verdict::wrong;
        score += m.points;
      }
    Submission s;
    s.sheet = hard ? &B : &A;
    s.marks = marks;
    s.report_index = index;
    s.score = score;
    s.max = 4;
    stats.add(s);
  }
  const ItemAnalysis a = stats.items();
  const BranchItem& b = a.branches[1];
  REQUIRE(b.branch == "b");
  CHECK(b.harder);
  CHECK(*b.p < kBranchAlpha / 2);
  CHECK_FALSE(a.branches[0].harder);
}

TEST_CASE("answers to check: left out of their question, the statistics provisional") {
  const SheetKey A = sheet("a");
  ClassStatistics stats({"1.a", "1.b", "2.a", "2.b"});
  const std::vector<std::vector<int>> index = {{0, 1}, {2, 3}};
  std::vector<ExerciseMarks> marks(2, ExerciseMarks(2));
  marks[0][0].verdict = Verdict::to_check;
  Submission s;
  s.sheet = &A;
  s.marks = marks;
  s.report_index = index;
  s.to_check = 1;
  s.held = 1;
  s.max = 4;
  stats.add(s);
  const ItemAnalysis a = stats.items();
  CHECK(a.provisional);
  CHECK(a.questions[0].answers == 0);
  CHECK(a.questions[0].to_check == 1);
  CHECK(a.questions[1].answers == 1);
  CHECK(stats.to_check_rows() == 1);
}

TEST_CASE("questions belong to their exercise by place, whatever the exercises' numbers") {
  // the course numbers its exercises "3" and "3.3": 3.3.t starts with "3." and is still not
  // exercise 3's (the class report's tables and plots group questions by this place)
  SheetKey A = sheet("a");
  const std::vector<std::string> numbers = {"3", "3.3"};
  std::vector<std::string> ids;
  for (std::size_t e = 0; e < 2; ++e) {
    A.exercises[e].number = numbers[e];
    for (auto& q : A.exercises[e].questions) {
      q.id = numbers[e] + q.id.substr(q.id.find('.'));
      ids.push_back(q.id);
    }
  }
  // the report's order as the key gives it: 3.3's questions first, as a key may sort them
  ClassStatistics stats({ids[2], ids[3], ids[0], ids[1]});
  const std::vector<std::vector<int>> index = {{2, 3}, {0, 1}};
  const std::vector<ExerciseMarks> marks(2, ExerciseMarks(2));
  Submission s;
  s.sheet = &A;
  s.marks = marks;
  s.report_index = index;
  s.max = 4;
  stats.add(s);
  const ItemAnalysis a = stats.items();
  REQUIRE(a.questions.size() == 4);
  CHECK(a.questions[0].id == "3.3.a");
  CHECK(a.questions[0].exercise == 1);
  CHECK(a.questions[1].exercise == 1);
  CHECK(a.questions[2].id == "3.a");
  CHECK(a.questions[2].exercise == 0);
  CHECK(a.questions[3].exercise == 0);
  REQUIRE(a.exercises.size() == 2);
  CHECK(a.exercises[0].number == "3");
  CHECK(a.exercises[1].number == "3.3");
  CHECK(a.exercises[1].n == 2);
}

TEST_CASE("running moments: merged halves equal the whole") {
  Moments all, left, right;
  const double xs[] = {0.1, 2.5, -3, 4, 4, 0.25, 7.75};
  for (int i = 0; i < 7; ++i) {
    all.add(xs[i], xs[6 - i]);
    (i < 3 ? left : right).add(xs[i], xs[6 - i]);
  }
  left.merge(right);
  CHECK(left.n == all.n);
  CHECK(left.mean_x == doctest::Approx(all.mean_x).epsilon(1e-12));
  CHECK(left.variance_x() == doctest::Approx(all.variance_x()).epsilon(1e-12));
  CHECK(*left.correlation() == doctest::Approx(*all.correlation()).epsilon(1e-12));
}
