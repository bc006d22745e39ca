// The ray/cube grader: the ray/square's figure in space (grading/kinds/ray_square_test.cpp).
// A(3, 0.5, 0.2), u = (−4, −1, 0): the only candidate face is +x (x ≥ 1 holds A, |y|, |z| ≤ 1);
// t = (1 − 3)/û_x = √17/2 ≈ 2.0616, I = (1, 0, 0.2), N = (1, 0, 0). The direction heads into
// +x and +y.
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const char* kInstance = R"({"kind":"ray_cube","A":[3,0.5,0.2],"u":[-4,-1,0]})";
const std::vector<std::string> kFields = {"faces", "inside", "hit", "t", "I.x", "I.y", "I.z", "N.x", "N.y", "N.z"};
}  // namespace

TEST_CASE("ray_cube: right answers earn every point") {
  const auto key = exercise(kInstance, kFields);
  const auto m = mark(key, {{"faces", "+x"}, {"inside", "no"}, {"hit", "yes"}, {"t", "2.06"}, {"I.x", "1"},
                            {"I.y", "0"}, {"I.z", "0.2"}, {"N.x", "1"}, {"N.y", "0"}, {"N.z", "0"}});
  CHECK(m.total() == doctest::Approx(10));
}

TEST_CASE("ray_cube: candidate faces from the wrong half-spaces, as the square's sides") {
  const auto key = exercise(kInstance, kFields);
  SUBCASE("the opposite face") { CHECK(mark(key, {{"faces", "-x"}})["faces"].mistake == "faces_wrong_half_planes"); }
  SUBCASE("the faces whose inner half-space holds A (the square's twin mistake, now the cube's too)") {
    CHECK(mark(key, {{"faces", "-x +y -y +z -z"}})["faces"].mistake == "faces_inner_half_planes");
  }
  SUBCASE("read from the direction") {
    CHECK(mark(key, {{"faces", "+x +y"}})["faces"].mistake == "faces_from_direction");
  }
}

TEST_CASE("ray_cube: a normal pointing inward; u not normalised; I follows from a wrong t") {
  const auto key = exercise(kInstance, kFields);
  CHECK(mark(key, {{"N.x", "-1"}, {"N.y", "0"}, {"N.z", "0"}})["N.x"].mistake == "normal_inward");
  // t = (1 − 3)/(u·n) = −2/−4 = 0.5 with u itself
  CHECK(mark(key, {{"t", "0.5"}})["t"].mistake == "direction_not_unit");
  // t = 2.5: I = A + 2.5·û = (3 − 2.4254, 0.5 − 0.6063, 0.2)
  const auto m = mark(key, {{"t", "2.5"}, {"I.x", "0.57"}, {"I.y", "-0.11"}, {"I.z", "0.2"}});
  CHECK(m["I.x"].verdict == Verdict::follow_through);
  CHECK(m["I.y"].verdict == Verdict::follow_through);
}
