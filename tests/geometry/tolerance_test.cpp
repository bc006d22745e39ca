// Pins geometry/tolerance.h: the named tolerances are what their comments say (a few ε, far
// below the 1e-9 at which answers are graded), Scale is the largest absolute coordinate and
// scales every tolerance linearly (areas quadratically), and Near's three answers split the line
// at bound ± tolerance with the edges counting as "on".
#include "geometry/tolerance.h"

#include <doctest/doctest.h>

#include <limits>

#include "support/exactly.h"

using namespace epure::geo;
using epure::test::exactly;

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/tolerance: the named constants") {
  const double eps = std::numeric_limits<double>::epsilon();
  CHECK(exactly(kEpsilon, eps));
  CHECK(exactly(kRoundoff, 32 * eps));
  CHECK(exactly(kCoincident, 4 * eps));
  // rounding is told from data: six orders of magnitude below the grading tolerance
  CHECK(kRoundoff < 1e-13);
  CHECK(kCoincident < kRoundoff);
}

TEST_CASE("geometry/tolerance: Scale") {
  SUBCASE("1. the largest absolute coordinate") {
    CHECK(exactly(Scale::of({1, -7, 3}).value, 7));
    CHECK(exactly(Scale::of({-0.5}).value, 0.5));
  }
  SUBCASE("2. no coordinate, or all zero: scale 0, every tolerance 0") {
    CHECK(exactly(Scale::of({}).value, 0));
    const Scale zero = Scale::of({0, -0.0});
    CHECK(exactly(zero.length(), 0));
    CHECK(exactly(zero.area(), 0));
    CHECK(zero.negligible(0));
    CHECK_FALSE(zero.negligible(1e-300));
  }
  SUBCASE("3. tolerances follow the figure: lengths linearly, areas quadratically") {
    for (double k : {1e-8, 0.5, 1.0, 3.0, 1e8}) {
      CAPTURE(k);
      const Scale s = Scale::of({2.0 * k, -k});
      CHECK(s.length() == doctest::Approx(kRoundoff * 2 * k).epsilon(1e-15));
      CHECK(s.area() == doctest::Approx(kRoundoff * 4 * k * k).epsilon(1e-15));
      // a length of a few ε of the figure is rounding; a thousand times more is data
      CHECK(s.negligible(kEpsilon * k));
      CHECK_FALSE(s.negligible(1000 * kEpsilon * k));
    }
  }
  SUBCASE("4. negligible is inclusive at its bound, and a NaN length is never data") {
    const Scale s{1.0};
    CHECK(s.negligible(kCoincident));
    CHECK_FALSE(s.negligible(2 * kCoincident));
    CHECK(s.negligible(std::numeric_limits<double>::quiet_NaN()));
  }
}

TEST_CASE("geometry/tolerance: Near splits the line in three") {
  const Near near{0.25};
  SUBCASE("1. far below, on, far above") {
    CHECK(near.below(0.0, 1.0));
    CHECK(near.on(1.1, 1.0));
    CHECK(near.above(2.0, 1.0));
  }
  SUBCASE("2. the edges bound ± tolerance count as on") {
    CHECK(near.on(0.75, 1.0));
    CHECK_FALSE(near.below(0.75, 1.0));
    CHECK(near.on(1.25, 1.0));
    CHECK_FALSE(near.above(1.25, 1.0));
    CHECK(near.below(0.7499, 1.0));
    CHECK(near.above(1.2501, 1.0));
  }
  SUBCASE("3. a zero tolerance is an exact comparison") {
    const Near exact{0.0};
    CHECK(exact.on(1.0, 1.0));
    CHECK(exact.below(std::nextafter(1.0, 0.0), 1.0));
    CHECK(exact.above(std::nextafter(1.0, 2.0), 1.0));
  }
  SUBCASE("4. exactly one of the three answers, whatever x") {
    for (double x : {-1e300, -1.0, 0.74, 0.75, 0.76, 1.0, 1.24, 1.25, 1.26, 1e300}) {
      CAPTURE(x);
      CHECK(int(near.below(x, 1.0)) + int(near.on(x, 1.0)) + int(near.above(x, 1.0)) == 1);
    }
  }
}

TEST_SUITE_END();
