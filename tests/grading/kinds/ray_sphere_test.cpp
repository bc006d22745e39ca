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

TEST_CASE("ray_sphere: a point in space gets the plane's rules") {
  SUBCASE("two coordinates typed in each other's cells") {
    const auto key = exercise(kInstance, kFields);
    const auto m = mark(key, {{"I.x", "3.27"}, {"I.y", "1"}, {"I.z", "0"}});
    CHECK(m["I.x"].verdict == Verdict::right);
    CHECK(m["I.y"].mistake == "swapped_coordinates");
    CHECK(m["I.z"].mistake == "swapped_coordinates");
  }
  SUBCASE("typed whole in one cell") {
    const auto key = exercise(kInstance, kFields);
    const auto m = mark(key, {{"I.x", "(3.27, 0, 1)"}});
    for (const char* c : {"I.x", "I.y", "I.z"}) CHECK(m[c].verdict == Verdict::right);
    CHECK(m["I.x"].note == "point_in_one_cell");
  }
  SUBCASE("a mistake names the whole point, never one coordinate that happens to fit") {
    const auto key = exercise(kInstance, kFields);
    // N inward is (0.87, 0.5, 0): N.z = 0 fits it and the right N alike; N.x and N.y are inward
    const auto inward = mark(key, {{"N.x", "0.87"}, {"N.y", "0.5"}, {"N.z", "0"}});
    CHECK(inward["N.x"].mistake == "normal_inward");
    CHECK(inward["N.y"].mistake == "normal_inward");
    CHECK(inward["N.z"].verdict == Verdict::right);
    // (0.87, −0.5, 0) is the normal at the far point J: that mistake, on the whole point
    CHECK(mark(key, {{"N.x", "0.87"}, {"N.y", "-0.5"}, {"N.z", "0"}})["N.x"].mistake == "far_intersection");
    // only N.x fits a mistake (inward, or at J): its N.y says neither
    const auto half = mark(key, {{"N.x", "0.87"}, {"N.y", "0.2"}, {"N.z", "0"}});
    CHECK(half["N.x"].verdict == Verdict::wrong);
    CHECK(half["N.x"].mistake.empty());
  }
  SUBCASE("marked as a whole, by its distance, when the key says so") {
    // every coordinate within 0.02, the point 0.021 away: wrong as a whole, as in the plane
    const auto key = exercise(kInstance, kFields, {}, "distance");
    const auto off = mark(key, {{"I.x", "3.283"}, {"I.y", "0.015"}, {"I.z", "1"}});
    for (const char* c : {"I.x", "I.y", "I.z"}) CHECK(off[c].verdict == Verdict::wrong);
    const auto near = mark(key, {{"I.x", "3.278"}, {"I.y", "0.01"}, {"I.z", "1.005"}});
    for (const char* c : {"I.x", "I.y", "I.z"}) CHECK(near[c].verdict == Verdict::right);
  }
}
