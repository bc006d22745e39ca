// Exact rationals and surds: arithmetic, normal forms, and the text forms the key prints.
#include <doctest/doctest.h>

#include <cmath>

#include "exercises/exact.h"
#include "exercises/rng.h"

using epure::exact::Rational;
using epure::exact::Surd;

TEST_CASE("rationals stay reduced with a positive denominator") {
  CHECK(Rational(6, -4) == Rational(-3, 2));
  CHECK(Rational(0, 5) == Rational(0));
  CHECK((Rational(1, 3) + Rational(1, 6)) == Rational(1, 2));
  CHECK((Rational(2, 3) * Rational(9, 4)) == Rational(3, 2));
  CHECK((Rational(1, 2) / Rational(-1, 4)) == Rational(-2));
  CHECK(Rational(9, 4).sqrt() == Rational(3, 2));
  CHECK_FALSE(Rational(2).sqrt());
  CHECK_THROWS_AS(Rational(1, 0), std::domain_error);
  CHECK_THROWS_AS(Rational(1) / Rational(0), std::domain_error);
}

TEST_CASE("overflow is reported, never wrapped") {
  const Rational big(INT64_MAX / 2);
  CHECK_THROWS_AS(big * big, epure::exact::ExactOverflow);
}

TEST_CASE("surds reduce their radicand and print for people and machines") {
  const Surd s(Rational(5), Rational(-1), 8);  // 5 − √8 = 5 − 2√2
  CHECK(s.c() == 2);
  CHECK(s.b() == Rational(-2));
  CHECK(s.machine() == "5-2*sqrt(2)");
  CHECK(s.pretty() == "5 − 2√2");
  CHECK(s.value() == doctest::Approx(5 - 2 * std::sqrt(2.0)).epsilon(1e-15));
  CHECK(Surd(Rational(1, 4)).machine() == "1/4");
  CHECK(Surd(Rational(-3, 2)).pretty() == "−3/2");
  CHECK((Surd(Rational(0), Rational(-1, 2), 3)).machine() == "-sqrt(3)/2");
  CHECK((Surd(Rational(5, 3), Rational(-2, 3), 2)).machine() == "(5-2*sqrt(2))/3");
  CHECK(Surd::sqrt(Rational(16, 9)).machine() == "4/3");
  CHECK(Surd::sqrt(Rational(12)).pretty() == "2√3");
  CHECK(Surd(Rational(0), Rational(1), 9).machine() == "3");  // √9 is rational
}

TEST_CASE("surd arithmetic matches doubles") {
  epure::Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    CAPTURE(i);
    const std::int64_t c = rng.integer(2, 30);
    Surd x(Rational(rng.integer(-20, 20), rng.integer(1, 9)), Rational(rng.integer(-20, 20), rng.integer(1, 9)), c);
    Surd y(Rational(rng.integer(-20, 20), rng.integer(1, 9)), Rational(rng.integer(-20, 20), rng.integer(1, 9)), c);
    CHECK((x + y).value() == doctest::Approx(x.value() + y.value()).epsilon(1e-12));
    CHECK((x - y).value() == doctest::Approx(x.value() - y.value()).epsilon(1e-12));
    CHECK((x * y).value() == doctest::Approx(x.value() * y.value()).epsilon(1e-12));
    const Rational r(rng.integer(1, 9), rng.integer(1, 9));
    CHECK((x / r).value() == doctest::Approx(x.value() / r.value()).epsilon(1e-12));
  }
  // different radicands do not combine: the caller drops the exact form
  CHECK_THROWS_AS(Surd(Rational(0), Rational(1), 2) + Surd(Rational(0), Rational(1), 3), std::domain_error);
}
