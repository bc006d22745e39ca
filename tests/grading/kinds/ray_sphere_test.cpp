// The ray/sphere grader: the ray/circle's figure in space (grading/kinds/ray_circle_test.cpp).
// A(0,0,1), u = (2,0,0) so û = (1,0,0), C(5,1,1), r = 2: t_proj = 5, d² = 1, t = 5 − √3 ≈ 3.268,
// I ≈ (3.268, 0, 1), N = (I − C)/r ≈ (−0.866, −0.5, 0); the far point J at t = 5 + √3 ≈ 6.732.
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const char* kInstance = R"({"kind":"ray_sphere","A":[0,0,1],"u":[2,0,0],"C":[5,1,1],"r":2})";
const std::vector<std::string> kFields = {"t_proj", "d2", "inside", "hit", "t",  "I.x",
                                          "I.y",    "I.z", "N.x",   "N.y", "N.z"};
}  // namespace

TEST_CASE("ray_sphere: right answers earn every point") {
  const auto key = exercise(kInstance, kFields);
  const auto m = mark(key, {{"t_proj", "5"}, {"d2", "1"}, {"inside", "no"}, {"hit", "yes"}, {"t", "3.27"},
                            {"I.x", "3.27"}, {"I.y", "0"}, {"I.z", "1"}, {"N.x", "-0.87"}, {"N.y", "-0.5"}, {"N.z", "0"}});
  CHECK(m.total() == doctest::Approx(11));
}

TEST_CASE("ray_sphere: the far intersection J instead of I; I follows from it") {
  const auto key = exercise(kInstance, kFields);
  const auto m = mark(key, {{"t_proj", "5"}, {"d2", "1"}, {"t", "6.73"}, {"I.x", "6.73"}, {"I.y", "0"}, {"I.z", "1"}});
  CHECK(m["t"].mistake == "far_intersection");
  CHECK(m["I.x"].verdict == Verdict::follow_through);
  CHECK(m["I.z"].verdict == Verdict::right);
}

TEST_CASE("ray_sphere: a normal pointing inward, or not normalised") {
  const auto key = exercise(kInstance, kFields);
  const auto inward = mark(key, {{"I.x", "3.27"}, {"I.y", "0"}, {"I.z", "1"}, {"N.x", "0.87"}, {"N.y", "0.5"}, {"N.z", "0"}});
  CHECK(inward["N.x"].mistake == "normal_inward");
  CHECK(inward["N.y"].mistake == "normal_inward");
  const auto long_n = mark(key, {{"I.x", "3.27"}, {"I.y", "0"}, {"I.z", "1"}, {"N.x", "-1.73"}, {"N.y", "-1"}});
  CHECK(long_n["N.x"].mistake == "normal_not_unit");
}

TEST_CASE("ray_sphere: u not normalised is named on t_proj; d² = AC² − t_proj² is the other road") {
  const auto key = exercise(kInstance, kFields);
  CHECK(mark(key, {{"t_proj", "10"}})["t_proj"].mistake == "direction_not_unit");
  // t_proj = 4.5 (wrong), d² by Pythagoras in A–P–C: 26 − 20.25 = 5.75, follows
  CHECK(mark(key, {{"t_proj", "4.5"}, {"d2", "5.75"}})["d2"].verdict == Verdict::follow_through);
}
