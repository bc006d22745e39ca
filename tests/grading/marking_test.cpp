// The key's rules, question by question: relative with an absolute floor (isclose), a point's
// coordinates earning their points separately, and a point marked as a whole (rule distance).
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
// A(0,0), B(1000,0), C(500,7): t = 0.5, P = (500, 0). Fixture tolerance: rel 0.001, abs 0.02.
const char* kFar = R"({"kind":"projection","A":[0,0],"B":[1000,0],"C":[500,7]})";
}  // namespace

TEST_CASE("isclose: relative for large values, the absolute floor near zero") {
  const auto key = exercise(kFar, {"t", "P.x", "P.y"});
  SUBCASE("1. P.x = 500: 0.001 × 500 = 0.5 allowed") {
    CHECK(mark(key, {{"P.x", "500.4"}})["P.x"].verdict == Verdict::right);
    CHECK(mark(key, {{"P.x", "500,6"}})["P.x"].verdict != Verdict::right);
  }
  SUBCASE("2. P.y = 0: the floor 0.02 applies") {
    CHECK(mark(key, {{"P.y", "0.019"}})["P.y"].verdict == Verdict::right);
    CHECK(mark(key, {{"P.y", "-0,03"}})["P.y"].verdict != Verdict::right);
  }
}

TEST_CASE("a point's coordinates earn their points separately unless the key marks it whole") {
  SUBCASE("1. per coordinate (isclose): one right, one wrong: one point") {
    const auto key = exercise(kFar, {"P.x", "P.y"});
    const auto m = mark(key, {{"P.x", "500"}, {"P.y", "3"}});
    CHECK(m["P.x"].verdict == Verdict::right);
    CHECK(m["P.y"].verdict != Verdict::right);
    CHECK(m.total() == doctest::Approx(1).epsilon(1e-12));
  }
  // rule distance, abs 0.02 for the point P = (500, 0)
  const auto key = exercise(kFar, {"P.x", "P.y"}, {}, "distance");
  SUBCASE("2. whole: within the distance, both coordinates right") {
    const auto m = mark(key, {{"P.x", "500.01"}, {"P.y", "0.01"}});  // √2 × 0.01 ≈ 0.014
    CHECK(m["P.x"].verdict == Verdict::right);
    CHECK(m["P.y"].verdict == Verdict::right);
    CHECK(m.total() == doctest::Approx(2).epsilon(1e-12));
  }
  SUBCASE("3. whole: each coordinate close, the point too far: both wrong") {
    const auto m = mark(key, {{"P.x", "500.015"}, {"P.y", "0.015"}});  // √2 × 0.015 ≈ 0.021 > 0.02
    CHECK(m["P.x"].verdict != Verdict::right);
    CHECK(m["P.y"].verdict != Verdict::right);
    CHECK(m.total() == doctest::Approx(0).epsilon(1e-12));
  }
  SUBCASE("4. whole: one coordinate right, the other far: no point") {
    const auto m = mark(key, {{"P.x", "500"}, {"P.y", "3"}});
    CHECK(m.total() == doctest::Approx(0).epsilon(1e-12));
  }
  SUBCASE("5. whole: one coordinate blank: not right, the blank one not answered") {
    const auto m = mark(key, {{"P.x", "500"}});
    CHECK(m["P.x"].verdict != Verdict::right);
    CHECK(m["P.y"].verdict == Verdict::unanswered);
    CHECK(m.total() == doctest::Approx(0).epsilon(1e-12));
  }
}

TEST_CASE("coordinates typed the wrong way round are named, for any point") {
  // P = (500, 0): swapped, it reads (0, 500)
  const auto key = exercise(kFar, {"t", "P.x", "P.y"});
  SUBCASE("1. swapped: both wrong, the mistake named on both") {
    const auto m = mark(key, {{"t", "0.5"}, {"P.x", "0"}, {"P.y", "500"}});
    CHECK(m["P.x"].verdict == Verdict::wrong);
    CHECK(m["P.x"].mistake == "swapped_coordinates");
    CHECK(m["P.y"].mistake == "swapped_coordinates");
    CHECK(m.total() == doctest::Approx(1).epsilon(1e-12));
  }
  SUBCASE("2. swapped within the tolerance of the values they stand for") {
    const auto m = mark(key, {{"P.x", "0,01"}, {"P.y", "499.8"}});
    CHECK(m["P.x"].mistake == "swapped_coordinates");
  }
  SUBCASE("3. right, or merely wrong: no swap named") {
    CHECK(mark(key, {{"P.x", "500"}, {"P.y", "0"}})["P.x"].mistake.empty());
    const auto m = mark(key, {{"P.x", "3"}, {"P.y", "500"}});
    CHECK(m["P.x"].mistake.empty());
    CHECK(m["P.y"].mistake.empty());
  }
  SUBCASE("4. one coordinate blank: nothing to compare") {
    CHECK(mark(key, {{"P.y", "500"}})["P.y"].mistake.empty());
  }
  SUBCASE("5. a point marked as a whole") {
    const auto whole = exercise(kFar, {"P.x", "P.y"}, {}, "distance");
    const auto m = mark(whole, {{"P.x", "0.01"}, {"P.y", "500"}});
    CHECK(m["P.x"].mistake == "swapped_coordinates");
    CHECK(m["P.y"].mistake == "swapped_coordinates");
    CHECK(m.total() == doctest::Approx(0).epsilon(1e-12));
  }
}
