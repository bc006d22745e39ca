// The segments' grader. A(0,0), B(4,0), C(1,−1), D(1,1): AB∧CD = 8, AC∧CD = 2, AC∧AB = 4, so
// t_ab = 0.25, t_cd = 0.5 and I = (1, 0).
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const char* kInstance = R"({"kind":"segments","A":[0,0],"B":[4,0],"C":[1,-1],"D":[1,1]})";
}

TEST_CASE("segments: t_ab and t_cd swapped, I from the swapped t_ab") {
  const auto key = exercise(kInstance, {"intersects", "t_ab", "t_cd", "I.x", "I.y"});
  const auto m = mark(key, {{"intersects", "yes"}, {"t_ab", "0.5"}, {"t_cd", "0.25"}, {"I.x", "2"}, {"I.y", "0"}});
  CHECK(m["t_ab"].mistake == "t_swapped");
  CHECK(m["t_cd"].mistake == "t_swapped");
  CHECK(m["I.x"].verdict == Verdict::follow_through);
  CHECK(m["I.y"].verdict == Verdict::right);
  CHECK(m.total() == doctest::Approx(3).epsilon(1e-12));
}

TEST_CASE("segments: a sign error in a cross product; 'intersects' follows from the wrong t") {
  const auto key = exercise(kInstance, {"intersects", "t_ab", "t_cd", "I.x", "I.y"});
  const auto m = mark(key, {{"intersects", "non"}, {"t_ab", "-0.25"}, {"t_cd", "0.5"}});
  CHECK(m["t_ab"].mistake == "cross_sign");
  CHECK(m["intersects"].verdict == Verdict::follow_through);
  CHECK(m["intersects"].from == "t_ab t_cd");
}
