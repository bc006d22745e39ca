// Student's t tail and Welch's test against closed forms, table values and an independent
// quadrature (mpmath's, for ν = 3.5), and a small case worked by hand.
#include <doctest/doctest.h>

#include <cmath>

#include "grading/welch_test.h"

using namespace epure::grading;

TEST_CASE("the t distribution's upper tail against closed forms") {
  // ν = 1 (Cauchy): P(T ≥ t) = ½ − atan(t)/π; ν = 2: ½ − t / (2√(2 + t²))
  for (double t : {0.0, 0.1, 0.5, 1.0, 2.0, 5.0, 30.0, -1.5}) {
    CAPTURE(t);
    CHECK(student_t_upper(t, 1) == doctest::Approx(0.5 - std::atan(t) / M_PI).epsilon(1e-12));
    CHECK(student_t_upper(t, 2) == doctest::Approx(0.5 - t / (2 * std::sqrt(2 + t * t))).epsilon(1e-12));
  }
  // large ν: the normal tail, P(Z ≥ 1.96) = 0.0249979
  CHECK(student_t_upper(1.959963984540054, 1e7) == doctest::Approx(0.025).epsilon(1e-5));
}

TEST_CASE("the t distribution's upper tail against the usual table (critical values)") {
  const struct {
    double df, t, p;
  } table[] = {{10, 2.228138851986274, 0.025}, {10, 1.812461122811676, 0.05}, {5, 4.032142983557536, 0.005},
               {30, 2.042272456301238, 0.025}, {3.5, 2.0, 0.06306926128795677}};
  for (const auto& row : table) {
    CAPTURE(row.df);
    CHECK(student_t_upper(row.t, row.df) == doctest::Approx(row.p).epsilon(1e-9));
  }
}

TEST_CASE("Welch's one-sided test of a lower mean") {
  SUBCASE("1. a small class by hand: {0, 0.25, 0.5} against {0.75, 1, 1, 0.5}") {
    // m₁ = 0.25, v₁ = 0.0625; m₂ = 0.8125, v₂ = 0.0572917; e₁ = 0.0208333, e₂ = 0.0143229
    // t = 0.5625 / √0.0351562 = 3.0, ν = 0.0351562² / (e₁²/2 + e₂²/3) = 4.3307
    const auto w = welch_lower(3, 0.25, 0.0625, 4, 0.8125, 0.0572916666666667);
    REQUIRE(w);
    CHECK(w->t == doctest::Approx(3.0).epsilon(1e-9));
    CHECK(w->df == doctest::Approx(4.330693069306931).epsilon(1e-9));
    CHECK(w->p == doctest::Approx(student_t_upper(3.0, 4.330693069306931)).epsilon(1e-12));
    CHECK(w->p < 0.025);
  }
  SUBCASE("2. fewer than two values in a group: no test") {
    CHECK_FALSE(welch_lower(1, 0, 0, 5, 1, 0.1));
    CHECK_FALSE(welch_lower(5, 0, 0.1, 1, 1, 0));
  }
  SUBCASE("3. both groups constant: certain when lower, never when not") {
    CHECK(welch_lower(3, 0, 0, 3, 1, 0)->p == 0);
    CHECK(welch_lower(3, 1, 0, 3, 1, 0)->p == 1);
    CHECK(welch_lower(3, 1, 0, 3, 0, 0)->p == 1);
  }
  SUBCASE("4. a group higher than the other: p above one half") { CHECK(welch_lower(5, 0.9, 0.01, 5, 0.5, 0.02)->p > 0.5); }
}
