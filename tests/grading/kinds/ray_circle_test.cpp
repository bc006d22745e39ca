// The ray/circle grader. A(0,0), u = (2,0) so û = (1,0), C(5,1), r = 2: t_proj = 5, d² = 1,
// √(r² − d²) = √3, t = 5 − √3 ≈ 3.268, I ≈ (3.268, 0), N = (I − C)/r ≈ (−0.866, −0.5); the
// far point J is at t = 5 + √3 ≈ 6.732.
#include <doctest/doctest.h>

#include <cmath>

#include "exercises/exercise.h"
#include "grading/exercise_fixture.h"

using epure::ExerciseKind;
using epure::find_kind;
using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const char* kInstance = R"({"kind":"ray_circle","A":[0,0],"u":[2,0],"C":[5,1],"r":2})";
const std::vector<std::string> kFields = {"t_proj", "d2", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"};
}

TEST_CASE("ray_circle: the far intersection J instead of I; I follows from it") {
  const auto key = exercise(kInstance, kFields);
  const auto m = mark(key, {{"t_proj", "5"}, {"d2", "1"}, {"inside", "no"}, {"hit", "yes"}, {"t", "6.73"},
                            {"I.x", "6.73"}, {"I.y", "0"}});
  CHECK(m["t"].mistake == "far_intersection");
  CHECK(m["I.x"].verdict == Verdict::follow_through);
  CHECK(m["I.x"].from == "t");
}

TEST_CASE("ray_circle: J given directly as I is the far root only when t does not say otherwise") {
  const auto key = exercise(kInstance, kFields);
  // t left blank: nothing the student wrote contradicts the far root
  CHECK(mark(key, {{"I.x", "6.73"}, {"I.y", "0"}})["I.x"].mistake == "far_intersection");
  // t right (the near root): the student did not take the far one; I is wrong, unexplained
  const auto m = mark(key, {{"t", "3.27"}, {"I.x", "6.73"}, {"I.y", "0"}});
  CHECK(m["t"].verdict == Verdict::right);
  CHECK(m["I.x"].verdict == Verdict::wrong);
  CHECK(m["I.x"].mistake.empty());
}

TEST_CASE("ray_circle: a normal not normalised, or pointing inward") {
  const auto key = exercise(kInstance, kFields);
  SUBCASE("not unit: I − C") {
    const auto m = mark(key, {{"I.x", "3.27"}, {"I.y", "0"}, {"N.x", "-1.73"}, {"N.y", "-1"}});
    CHECK(m["N.x"].mistake == "normal_not_unit");
    CHECK(m["N.y"].mistake == "normal_not_unit");
  }
  SUBCASE("inward: (C − I)/r") {
    const auto m = mark(key, {{"I.x", "3.27"}, {"I.y", "0"}, {"N.x", "0.87"}, {"N.y", "0.5"}});
    CHECK(m["N.x"].mistake == "normal_inward");
  }
  SUBCASE("from a wrong I: N = (I − C)/r follows") {
    // I = (3, 0) (wrong): (I − C)/r = (−1, −0.5)
    const auto m = mark(key, {{"I.x", "3"}, {"I.y", "0"}, {"N.x", "-1"}, {"N.y", "-0.5"}});
    CHECK(m["N.x"].verdict == Verdict::follow_through);
    CHECK(m["N.y"].verdict == Verdict::right);
  }
}

TEST_CASE("ray_circle: u not normalised; d² and t follow from the wrong t_proj") {
  const auto key = exercise(kInstance, kFields);
  // t_proj = u·AC = 10; d² = ‖AC‖² − 10² = −74 is absurd, but t from t_proj = 4.5, d² = 1.5:
  const auto m = mark(key, {{"t_proj", "10"}});
  CHECK(m["t_proj"].mistake == "direction_not_unit");
  const auto m2 = mark(key, {{"t_proj", "4.5"}, {"d2", "5.75"}, {"t", "3.91"}});
  // d² = 26 − 4.5² = 5.75 follows; 5.75 > r² = 4: no hit by their values, t cannot follow
  CHECK(m2["d2"].verdict == Verdict::follow_through);
  CHECK(m2["t"].verdict == Verdict::wrong);
  const auto m3 = mark(key, {{"t_proj", "5"}, {"d2", "2"}, {"t", "3.59"}});
  // their d² = 2: t = 5 − √2 ≈ 3.586
  CHECK(m3["t"].verdict == Verdict::follow_through);
  CHECK(m3["t"].from == "t_proj d2");
}

TEST_CASE("ray_circle: A inside, the root behind A") {
  // A(5,1) is the centre: t_proj = 0, d² = 0, t = +2 (leaving), the other root −2
  const auto key = exercise(R"({"kind":"ray_circle","A":[5,0.5],"u":[1,0],"C":[5,1],"r":2})", kFields);
  const double behind = 0 - std::sqrt(4 - 0.25);
  const auto m = mark(key, {{"t", fmt::format("{:.2f}", behind)}});
  CHECK(m["t"].mistake == "near_root_inside");
}

// Issue 31's sheet 1000-0005-000S (French set, seed 5): A(1,8), u = (2,−4), C(4,5), r = 2; the
// key's t_proj = û·AC = 18/√20 ≈ 4.02 and d² = 1.8. The course computes d² = (û∧AC)². A student
// who forgot to normalise u writes t_proj = u·AC = 18 and, by the course's formula with u,
// d² = (u∧AC)² = 6² = 36 (the usual road, CP² with P = A + t·u, gives 5,850): one slip (û left
// as u), named once, on t_proj; d² carries it on by the course's road, although that road does
// not go through t_proj.
TEST_CASE("ray_circle: u not normalised, then d² by the course's cross product: one slip, carried on") {
  const auto key = exercise(R"({"kind":"ray_circle","A":[1,8],"u":[2,-4],"C":[4,5],"r":2})",
                            {"t_proj", "d2", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"});
  const auto m = mark(key, {{"t_proj", "18"}, {"d2", "36"}});
  CHECK(m["t_proj"].mistake == "direction_not_unit");
  CHECK(m["d2"].verdict == Verdict::follow_through);
  CHECK(m["d2"].from == "t_proj");
  // the right û and the course's formula: (û∧AC)² = 36/20, the key's d²
  CHECK(mark(key, {{"t_proj", "4.02"}, {"d2", "1.8"}})["d2"].verdict == Verdict::right);
  // d² alone, t_proj left blank: the slip is named on d², on either road
  CHECK(mark(key, {{"d2", "36"}})["d2"].mistake == "direction_not_unit");
  CHECK(mark(key, {{"d2", "5850"}})["d2"].mistake == "direction_not_unit");
  // 36 next to a right t_proj is not that slip: the student's own û was right
  const auto against = mark(key, {{"t_proj", "4.02"}, {"d2", "36"}});
  CHECK(against["d2"].verdict == Verdict::wrong);
  CHECK(against["d2"].mistake.empty());
}

// Sheet 1000-0005-001Q: A(4,8), u = (4,1), C(1,3): A is outside and t_proj = û·AC = −17/√17 < 0,
// the ray points away. "Si t ≤ 0, on arrête": the key asks nothing past t_proj (the student of
// the issue, u left unnormalised, wrote t_proj = −17 and d² = (u∧AC)² = 289 and got 0 for d²;
// d² is no longer asked, and the slip is named once, on t_proj).
TEST_CASE("ray_circle: behind, the course stops at t_proj; the sheet asks no d²") {
  const ExerciseKind* circle = find_kind("ray_circle");
  const auto data = circle->read_instance(nlohmann::json::parse(R"({"kind":"ray_circle","A":[4,8],"u":[4,1],"C":[1,3],"r":2})"));
  std::vector<std::string_view> asked;
  for (const auto& a : circle->evaluate(data, nullptr, {}, 2)) asked.push_back(a.id);
  CHECK(asked == std::vector<std::string_view>{"inside", "t_proj", "hit", "reason"});
  const auto key = exercise(R"({"kind":"ray_circle","A":[4,8],"u":[4,1],"C":[1,3],"r":2})",
                            {"t_proj", "inside", "hit", "reason"});
  const auto m = mark(key, {{"t_proj", "-17"}, {"inside", "no"}, {"hit", "no"}, {"reason", "behind"}});
  CHECK(m["t_proj"].mistake == "direction_not_unit");
  CHECK(m["hit"].verdict == Verdict::right);
  CHECK(m["reason"].verdict == Verdict::right);
  CHECK(m.total() == doctest::Approx(3).epsilon(1e-12));
}
