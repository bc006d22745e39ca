// The preamble in space. u = (1, 2, 3), v = (−2, 0, 1): u·v = 1, u∧v = (2, −7, 4),
// ‖u‖ = √14 ≈ 3.742, ‖v‖ = √5 ≈ 2.236. Computed as v∧u the cross product is (−2, 7, −4): one
// slip, which changes all three components (sheet 002K of issue 31 had it named twice).
#include <doctest/doctest.h>

#include <vector>

#include "grading/exercise_fixture.h"
#include "grading/statistics.h"
#include "grading/submission.h"

using epure::grading::Verdict;
using epure::test::exercise_in_space;
using epure::test::mark;

namespace {
const std::vector<std::string> kFields = {"dot", "cross.x", "cross.y", "cross.z", "norm_u",
                                          "norm_v", "cos", "sin", "angle_deg"};
epure::grading::ExerciseKey key() {
  return exercise_in_space("vectors_3d", R"({"kind":"vectors","u":[1,2,3],"v":[-2,0,1]})", kFields);
}
}  // namespace

TEST_CASE("vectors_3d: v∧u for u∧v is one mistake, named on the whole vector and counted once") {
  const auto k = key();
  const auto m = mark(k, {{"dot", "1"}, {"cross.x", "-2"}, {"cross.y", "7"}, {"cross.z", "-4"}});
  for (const char* c : {"cross.x", "cross.y", "cross.z"}) {
    CAPTURE(c);
    CHECK(m[c].verdict == Verdict::wrong);
    CHECK(m[c].mistake == "cross_sign");  // never "cross_middle_sign" for the middle one
  }
  // the class's count of mistakes: one slip, once
  epure::grading::SheetKey sheet;
  sheet.exercises.push_back(k);
  std::vector<std::string> ids;
  std::vector<int> index;
  for (const auto& q : k.questions) {
    index.push_back(static_cast<int>(ids.size()));
    ids.push_back(q.id);
  }
  epure::grading::ClassStatistics stats(ids);
  const std::vector<epure::grading::ExerciseMarks> marks = {m.marks};
  const std::vector<std::vector<int>> report_index = {index};
  epure::grading::Submission s;
  s.sheet = &sheet;
  s.marks = marks;
  s.report_index = report_index;
  s.score = m.total();
  s.max = static_cast<double>(k.questions.size());
  stats.add(s);
  const auto items = stats.items();
  REQUIRE(items.mistakes.size() == 1);
  CHECK(items.mistakes[0].code == "cross_sign");
  CHECK(items.mistakes[0].count == 1);
  CHECK(items.exercises.at(0).mistakes.at("cross_sign") == 1);
  const auto by_question = stats.mistakes();
  REQUIRE(by_question.size() == 1);
  CHECK(by_question[0].count == 1);
}

TEST_CASE("vectors_3d: v∧u where two components of u∧v are opposites is still one sign slip, not a swap") {
  // u = (0, 0, 1), v = (1, 1, 2): u∧v = (−1, 1, 0); as v∧u (1, −1, 0), which also reads as x and y
  // typed in each other's cells
  const auto k = exercise_in_space("vectors_3d", R"({"kind":"vectors","u":[0,0,1],"v":[1,1,2]})", kFields);
  const auto m = mark(k, {{"cross.x", "1"}, {"cross.y", "-1"}, {"cross.z", "0"}});
  for (const char* c : {"cross.x", "cross.y"}) {
    CAPTURE(c);
    CHECK(m[c].verdict == Verdict::wrong);
    CHECK(m[c].mistake == "cross_sign");
  }
}

TEST_CASE("vectors_3d: the middle component's sign alone is that mistake, on that component") {
  const auto k = key();
  const auto m = mark(k, {{"cross.x", "2"}, {"cross.y", "7"}, {"cross.z", "4"}});
  CHECK(m["cross.x"].verdict == Verdict::right);
  CHECK(m["cross.y"].mistake == "cross_middle_sign");
  CHECK(m["cross.z"].verdict == Verdict::right);
}

TEST_CASE("vectors_3d: two components typed in each other's cells (the plane's rule, in space)") {
  const auto k = key();
  const auto m = mark(k, {{"cross.x", "2"}, {"cross.y", "4"}, {"cross.z", "-7"}});
  CHECK(m["cross.x"].verdict == Verdict::right);
  CHECK(m["cross.y"].mistake == "swapped_coordinates");
  CHECK(m["cross.z"].mistake == "swapped_coordinates");
}
