#pragma once
// Item analysis of a class: how each question and each exercise worked, gathered as the
// submissions stream past (running moments, memory that does not grow with the class). The
// formulas, also in README.md ("Item analysis"):
//
// - facility of a question: the mean of x = points earned / the question's points over the
//   settled answers to it (a right answer or follow-through credit is 1, anything else 0);
// - discrimination: the item–rest correlation, Pearson's r between x and the rest score
//   R = S − points earned on the question (S the submission's score), over the same answers:
//   does a student who gets this question tend to do well on the rest? (rest, not total, so
//   that the question does not correlate with itself); none below 3 answers or when x or R
//   does not vary;
// - Cronbach's α over the k exercises of the sheet (every sheet has the same exercises, while
//   the questions asked depend on the branch drawn, so the exercise is the item):
//   α = k/(k−1) · (1 − Σ_j s²(Y_j) / s²(S)), Y_j the points of exercise j, S the score (sample
//   variances); none below 2 submissions, 2 exercises, or when S does not vary;
// - facility of a branch: the mean of Y_j / exercise j's points over the submissions that drew
//   that branch; a branch is flagged harder when Welch's one-sided t-test (welch_test.h) of its
//   mean against the pooled other branches of the exercise gives p < 0.05 / m, m the number of
//   branches of the exercise tested (Bonferroni: a class's many branches would otherwise flag
//   one by chance now and then); only branches with 2 submissions or more, and others with 2 or
//   more, are tested;
// - named mistakes counted per code and per exercise, each once per exercise of a submission, follow-through credit counted in answers
//   and in points, per question and per exercise.
//
// Scores with answers still to check count their held points as not earned (the statistics are
// then provisional, and the outputs say so); answers to check are left out of their question's
// facility and discrimination.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grading/submission.h"

namespace epure::grading {

// Mean, variance and covariance of a stream of pairs, by Welford's updates (stable where sums
// of squares cancel).
struct Moments {
  double n = 0, mean_x = 0, mean_y = 0, m2_x = 0, m2_y = 0, c_xy = 0;
  void add(double x, double y = 0);
  // Merges another stream's moments into this one (Chan et al.'s pairwise formulas).
  void merge(const Moments& o);
  double variance_x() const { return n > 1 ? m2_x / (n - 1) : 0; }
  double variance_y() const { return n > 1 ? m2_y / (n - 1) : 0; }
  // Pearson's r; nothing when n < 3 or either stream is constant.
  std::optional<double> correlation() const;
};

// Significance of "this branch is harder than the others of its exercise".
inline constexpr double kBranchAlpha = 0.05;

struct QuestionItem {
  std::string id;
  // its exercise's place on the sheet (0-based, ExerciseItem::index): an id starts with the
  // exercise's number ("3.3.t", "P.dot"), which says nothing of its place
  std::size_t exercise = 0;
  int answers = 0;          // settled answers (to check ones left out)
  double facility = 0;      // 0..1
  std::optional<double> discrimination;
  int follow_through = 0;   // answers credited by follow-through
  double follow_through_points = 0;
  int to_check = 0;
};

struct BranchItem {
  std::size_t exercise = 0;  // 0-based place on the sheet
  std::string branch;
  int submissions = 0;
  double facility = 0;       // mean share of the exercise's points
  double sd = 0;             // their standard deviation
  std::optional<double> others_facility;  // the other branches of the exercise, pooled
  std::optional<double> t, df, p;         // Welch's test of this branch below the others
  int tested = 0;            // m: branches of the exercise tested
  bool harder = false;       // p < kBranchAlpha / m
};

struct ExerciseItem {
  std::size_t index = 0;     // 0-based place on the sheet
  int n = 0;                 // its place on the sheet, 1-based (key.json's "n")
  std::string number;        // what its question ids start with ("3.3", "P")
  std::string kind;
  int submissions = 0;
  double max_points = 0;     // the most it is worth on a sheet
  double facility = 0;       // mean share of its points
  double variance = 0;       // of its points
  int follow_through = 0;
  double follow_through_points = 0;
  std::map<std::string_view, int> mistakes;  // code → times named
};

struct MistakeTotal {
  std::string_view code;
  int count = 0;
  std::vector<std::pair<std::size_t, int>> by_exercise;  // exercise index → count
};

struct ItemAnalysis {
  int submissions = 0;
  bool provisional = false;  // some answers are still to check
  std::vector<QuestionItem> questions;  // in report order; those never asked are left out
  std::vector<ExerciseItem> exercises;
  std::vector<BranchItem> branches;     // by exercise, then branch name
  std::optional<double> alpha;          // Cronbach's α over the exercises
  int alpha_items = 0;                  // k
  double score_variance = 0;            // s²(S)
  std::vector<MistakeTotal> mistakes;   // most frequent first
  int follow_through = 0;
  double follow_through_points = 0;
};

class ItemAccumulator {
 public:
  explicit ItemAccumulator(std::vector<std::string> question_ids);
  void add(const Submission& s);
  ItemAnalysis result() const;

 private:
  struct Question {
    Moments xr;  // x and the rest score
    std::size_t exercise = 0;  // the place of the exercise that asks it
    int follow_through = 0, to_check = 0;
    double follow_through_points = 0;
  };
  struct Exercise {
    int n = 0;
    std::string number;
    std::string kind;
    Moments y;  // its points
    double max_points = 0;
    Moments share;  // its points / its maximum
    int follow_through = 0;
    double follow_through_points = 0;
    std::map<std::string_view, int> mistakes;
    std::map<std::string, Moments, std::less<>> branches;  // share, by branch
    // the last row's branch and its moments: a short string compared before a map is searched
    const std::string* last_branch = nullptr;
    Moments* last_moments = nullptr;
  };
  std::vector<std::string> ids_;
  std::vector<Question> questions_;
  std::vector<Exercise> exercises_;
  Moments score_;
  int submissions_ = 0;
  bool same_shape_ = true;  // every submission has the same number of exercises
  bool provisional_ = false;
};

}  // namespace epure::grading
