// The projection's grader: follow-through from t, the square forgotten, a position read from a
// wrong t. A(1,1), B(5,4), C(2,6): AB = (4,3), AC = (1,5), AB·AC = 19, ‖AB‖² = 25, t = 0.76,
// P = (4.04, 3.28), between A and B.
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const char* kInstance = R"({"kind":"projection","A":[1,1],"B":[5,4],"C":[2,6]})";
}

TEST_CASE("projection: right answers earn every point") {
  const auto key = exercise(kInstance, {"t", "P.x", "P.y", "position"});
  const auto m = mark(key, {{"t", "0,76"}, {"P.x", "4.04"}, {"P.y", "3.28"}, {"position", "entre A et B"}});
  CHECK(m.total() == doctest::Approx(4).epsilon(1e-12));
  CHECK(m["t"].verdict == Verdict::right);
  CHECK(m["position"].verdict == Verdict::right);
}

TEST_CASE("projection: t = AB·AC/‖AB‖ is named, P and the position follow from it") {
  const auto key = exercise(kInstance, {"t", "P.x", "P.y", "position"});
  // 19/5 = 3.8; P = A + 3.8·AB = (16.2, 12.4); 3.8 > 1: after B
  SUBCASE("follow-through on") {
    const auto m = mark(key, {{"t", "3.8"}, {"P.x", "16.2"}, {"P.y", "12.4"}, {"position", "after"}});
    CHECK(m["t"].verdict == Verdict::wrong);
    CHECK(m["t"].mistake == "t_unsquared_norm");
    CHECK(m["t"].points == doctest::Approx(0).epsilon(1e-12));
    CHECK(m["P.x"].verdict == Verdict::follow_through);
    CHECK(m["P.y"].verdict == Verdict::follow_through);
    CHECK(m["P.x"].from == "t");
    CHECK(m["P.x"].detail == "t = 3.8");
    CHECK(m["position"].verdict == Verdict::follow_through);
    CHECK(m["position"].from == "t");
    CHECK(m.total() == doctest::Approx(3).epsilon(1e-12));
  }
  SUBCASE("follow-through off: recognised, not credited") {
    const auto m = mark(key, {{"t", "3.8"}, {"P.x", "16.2"}, {"P.y", "12.4"}, {"position", "after"}}, false);
    CHECK(m["P.x"].verdict == Verdict::wrong);
    CHECK(m["P.x"].from == "t");
    CHECK(m["position"].verdict == Verdict::wrong);
    CHECK(m["position"].from == "t");
    CHECK(m.total() == doctest::Approx(0).epsilon(1e-12));
  }
}

TEST_CASE("projection: t = AB·AC without the division") {
  const auto key = exercise(kInstance, {"t", "P.x", "P.y", "position"});
  const auto m = mark(key, {{"t", "19"}});
  CHECK(m["t"].mistake == "t_not_divided");
}

TEST_CASE("projection: a wrong P next to a right t is not excused") {
  const auto key = exercise(kInstance, {"t", "P.x", "P.y", "position"});
  const auto m = mark(key, {{"t", "0.76"}, {"P.x", "4.1"}, {"P.y", "3.28"}, {"position", "between"}});
  CHECK(m["P.x"].verdict == Verdict::wrong);
  CHECK(m["P.x"].from.empty());
  CHECK(m.total() == doctest::Approx(3).epsilon(1e-12));
}
