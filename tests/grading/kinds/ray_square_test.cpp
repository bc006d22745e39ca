// The ray/square grader. A(3, 0.5), u = (−4, −1): the only candidate side is +x (x ≥ 1 holds
// A, |y| ≤ 1); t = (1 − 3)/û_x = 2·√17/4 ≈ 2.0616, I = (1, 0), N = (1, 0). The direction points
// at +x and −y... û·n < 0 for +x and +y.
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const char* kInstance = R"({"kind":"ray_square","A":[3,0.5],"u":[-4,-1]})";
const std::vector<std::string> kFields = {"faces", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"};
}

TEST_CASE("ray_square: faces in any order and separator") {
  const auto key = exercise(R"({"kind":"ray_square","A":[3,3],"u":[-1,-1.5]})", kFields);
  for (const char* cell : {"+x +y", "+y;+x", "+y, +x", "x=1 y=1", "+X+Y"}) {
    CAPTURE(cell);
    CHECK(mark(key, {{"faces", cell}})["faces"].verdict == Verdict::right);
  }
}

TEST_CASE("ray_square: candidate sides from the wrong half-planes") {
  const auto key = exercise(kInstance, kFields);
  SUBCASE("the opposite side") { CHECK(mark(key, {{"faces", "-x"}})["faces"].mistake == "faces_wrong_half_planes"); }
  SUBCASE("the sides whose inner half-plane holds A") {
    CHECK(mark(key, {{"faces", "-x +y -y"}})["faces"].mistake == "faces_inner_half_planes");
  }
  SUBCASE("read from the direction") { CHECK(mark(key, {{"faces", "+x +y"}})["faces"].mistake == "faces_from_direction"); }
}

TEST_CASE("ray_square: a normal pointing inward; u not normalised") {
  const auto key = exercise(kInstance, kFields);
  CHECK(mark(key, {{"N.x", "-1"}, {"N.y", "0"}})["N.x"].mistake == "normal_inward");
  // t = (1 − 3)/(u·n) = −2/−4 = 0.5 with u itself
  CHECK(mark(key, {{"t", "0.5"}})["t"].mistake == "direction_not_unit");
}

TEST_CASE("ray_square: I follows from a wrong t") {
  const auto key = exercise(kInstance, kFields);
  // t = 2.5: I = A + 2.5·û = (3 − 2.4254, 0.5 − 0.6063)
  const auto m = mark(key, {{"t", "2.5"}, {"I.x", "0.57"}, {"I.y", "-0.11"}});
  CHECK(m["I.x"].verdict == Verdict::follow_through);
  CHECK(m["I.y"].verdict == Verdict::follow_through);
}
