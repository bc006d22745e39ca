// Pins geometry/expansion.h: sums and products of expansions are exact, so that the sign of a
// polynomial of doubles is its true sign, however much it cancels. Checked on values whose exact
// result is known by construction (a product minus itself moved by one ulp, huge and tiny terms
// that cancel), and against quadruple precision where that is exact.
#include "geometry/expansion.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "exercises/rng.h"
#include "support/real.h"

using epure::Rng;
using epure::geo::exact::Expansion;
namespace T = epure::test;

TEST_CASE("expansion: zero, a double, a product and a difference are held exactly") {
  CHECK(Expansion().sign() == 0);
  CHECK(Expansion(0.0).size() == 0);
  CHECK(Expansion(-2.5).sign() == -1);
  CHECK(Expansion(-2.5).estimate() == -2.5);
  // (1 + ε)² = 1 + 2ε + ε²: two components
  const double x = 1 + std::numeric_limits<double>::epsilon();
  const Expansion p = Expansion::product(x, x);
  CHECK(p.size() == 2);
  CHECK((p - Expansion(x * x)).estimate() == std::ldexp(1.0, -104));
  CHECK(Expansion::difference(1.0, 1e-300).sign() == 1);
  CHECK((Expansion::difference(1.0, 1e-300) - Expansion(1.0)).estimate() == -1e-300);
}

TEST_CASE("expansion: a cancelling sum keeps the sign of what is left") {
  // 1e100 + 1 − 1e100 − 1 + 2^-60 = 2^-60, whatever the order
  const Expansion e = Expansion(1e100) + Expansion(1.0) - Expansion(1e100) - Expansion(1.0) +
                      Expansion(std::ldexp(1.0, -60));
  CHECK(e.sign() == 1);
  CHECK(e.estimate() == std::ldexp(1.0, -60));
  const Expansion zero = Expansion(1e100) + Expansion(1.0) - Expansion(1.0) - Expansion(1e100);
  CHECK(zero.sign() == 0);
  CHECK(zero.estimate() == 0);
}

TEST_CASE("expansion: a·b − c·d is exact, one ulp from zero included (property, 2000 seeds)") {
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    const double a = rng.uniform(-1, 1) * std::ldexp(1.0, static_cast<int>(rng.integer(-30, 30)));
    const double b = rng.uniform(-1, 1);
    const int k = static_cast<int>(rng.integer(-3, 3));
    // c·d = a·b moved by k ulps of b: the exact difference is −a·(d − b)
    double d = b;
    for (int i = 0; i < std::abs(k); ++i) d = std::nextafter(d, k > 0 ? 2.0 : -2.0);
    const Expansion e = Expansion::product(a, b) - Expansion::product(a, d);
    const int expected = (a == 0 || k == 0) ? 0 : ((a > 0) == (k < 0) ? 1 : -1);
    CHECK(e.sign() == expected);
    // the estimate is within an ulp of a·(b − d), which is exact in quadruple precision
    const double exact = static_cast<double>(T::Real(a) * (T::Real(b) - T::Real(d)));
    CHECK(std::abs(e.estimate() - exact) <= (exact == 0 ? 0.0 : std::abs(std::nextafter(exact, 0.0) - exact)));
    // and the product of two expansions: (a·b − a·d)·(a·b − a·d) ≥ 0, zero only with e
    const Expansion square = e * e;
    CHECK(square.sign() == (expected == 0 ? 0 : 1));
  }
}
