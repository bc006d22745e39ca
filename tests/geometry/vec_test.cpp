// Pins geometry/vec.h and geometry/exact.h: the point/vector algebra, dot and cross (2D scalar,
// 3D vector) rounded once thanks to the fma (within 2 ulps of the exact value, sign always
// right), the error-free building blocks, and `normalized`: empty for zero or non-finite
// vectors, unit for every other one, from subnormal to near-overflow lengths.
#include "geometry/vec.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "geometry/exact.h"
#include "support/draw.h"
#include "support/exactly.h"
#include "support/real.h"

using namespace epure::geo;
using epure::Rng;
using epure::test::d;
using epure::test::exactly;
using epure::test::Real;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// |got − exact| in units of the exact value's last place (ulp of its magnitude).
double ulps(double got, Real exact) {
  const double e = d(exact);
  if (e == 0) return got == 0 ? 0 : std::numeric_limits<double>::infinity();
  const double ulp =
      std::nextafter(std::abs(e), std::numeric_limits<double>::infinity()) - std::abs(e);
  return d(epure::test::abs(Real(got) - exact)) / ulp;
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/vec: points and vectors") {
  const Point2 A{1, 2}, B{4, 6};
  const Vec2 AB = B - A;
  CHECK(exactly(AB.x, 3));
  CHECK(exactly(AB.y, 4));
  const Point2 back = A + AB;
  CHECK(exactly(back.x, B.x));
  CHECK(exactly(back.y, B.y));
  const Point2 before = B - AB;
  CHECK(exactly(before.x, A.x));
  CHECK(norm(AB) == doctest::Approx(5).epsilon(1e-16));
  CHECK(norm2(AB) == doctest::Approx(25).epsilon(1e-16));
  CHECK(exactly(dot(AB, Vec2{-4, 3}), 0));
  CHECK(exactly(cross(AB, Vec2{-4, 3}), 25));
  // perp turns a quarter counter-clockwise: u∧perp(u) = ‖u‖², u·perp(u) = 0
  CHECK(exactly(perp(AB).x, -4));
  CHECK(exactly(perp(AB).y, 3));
  CHECK(exactly(to_point(to_vec(A)).y, 2));

  const Point3 P{1, 2, 3}, Q{2, 4, 7};
  const Vec3 PQ = Q - P;
  CHECK(norm(PQ) == doctest::Approx(std::sqrt(21.0)).epsilon(1e-16));
  const Vec3 z = cross(Vec3{1, 0, 0}, Vec3{0, 1, 0});
  CHECK(exactly(z.x, 0));
  CHECK(exactly(z.y, 0));
  CHECK(exactly(z.z, 1));
  CHECK(exactly(dot(PQ, Vec3{1, 1, 1}), 7));
}

TEST_CASE("geometry/vec: cross is antisymmetric and dot symmetric") {
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Vec2 u = epure::test::direction2(rng), v = epure::test::direction2(rng);
    // Kahan's formula is not symmetric in its terms: equal to the last bit or two
    REQUIRE(cross(u, v) == doctest::Approx(-cross(v, u)).epsilon(2 * kEps));
    REQUIRE(exactly(dot(u, v), dot(v, u)));
  }
}

TEST_CASE("geometry/exact: difference and sum of products are rounded about once") {
  SUBCASE("1. hand case with total cancellation: a·b = c·d exactly gives 0") {
    CHECK(exactly(exact::difference_of_products(0.1, 0.3, 0.3, 0.1), 0));
  }
  SUBCASE("2. the part a naive a·b − c·d loses") {
    // (1 + 2⁻³⁰)² − (1 + 2⁻²⁹) = 2⁻⁶⁰ exactly; the naive products round it away.
    const double a = 1 + std::ldexp(1.0, -30), c = 1 + std::ldexp(1.0, -29);
    CHECK(exactly(exact::difference_of_products(a, a, c, 1.0), std::ldexp(1.0, -60)));
  }
  SUBCASE("3. random products, many nearly cancelling: within 2 ulps, sign exact") {
    for (std::uint64_t seed = 0; seed < 4000; ++seed) {
      Rng rng(seed);
      CAPTURE(seed);
      const double a = rng.uniform(-10, 10), b = rng.uniform(-10, 10);
      double c = rng.uniform(-10, 10);
      // half of the cases: c·d within a few ulps of a·b
      const double d_ =
          rng.chance(0.5) ? a * b / c * (1 + rng.uniform(-4, 4) * kEps) : rng.uniform(-10, 10);
      const Real exact = Real(a) * b - Real(c) * d_;
      const double got = exact::difference_of_products(a, b, c, d_);
      CAPTURE(got);
      CAPTURE(d(exact));
      REQUIRE(ulps(got, exact) <= 2);
      REQUIRE((got > 0) == (exact > 0));
      REQUIRE((got < 0) == (exact < 0));
      const double sum = exact::sum_of_products(a, b, c, d_);
      REQUIRE(ulps(sum, Real(a) * b + Real(c) * d_) <= 2);
    }
  }
}

TEST_CASE(
    "geometry/vec: dot and cross of nearly perpendicular / parallel vectors keep their sign") {
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Vec2 u = epure::test::direction2(rng);
    // v almost along perp(u) (dot ≈ 0) or almost along u (cross ≈ 0), off by a tiny angle
    const double tiny = epure::test::decades(rng, -15, -6) * epure::test::sign(rng);
    const Vec2 v1 = perp(u) + tiny * u, v2 = u + tiny * perp(u);
    REQUIRE(ulps(dot(u, v1), Real(u.x) * v1.x + Real(u.y) * v1.y) <= 2);
    REQUIRE(ulps(cross(u, v2), Real(u.x) * v2.y - Real(u.y) * v2.x) <= 2);
    const Vec3 p{u.x, u.y, 0.5}, q{v1.x, v1.y, 0};
    const Real exact3 = Real(p.x) * q.x + Real(p.y) * q.y + Real(p.z) * q.z;
    REQUIRE(d(epure::test::abs(Real(dot(p, q)) - exact3)) <= 4 * kEps * (norm(p) * norm(q)));
  }
}

TEST_CASE("geometry/vec: 3D cross is perpendicular to both and obeys Lagrange's identity") {
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Vec3 u = epure::test::direction3(rng), v = epure::test::direction3(rng);
    const Vec3 w = cross(u, v);
    const double size = norm(u) * norm(v);
    REQUIRE(std::abs(dot(w, u)) <= 8 * kEps * size * norm(u));
    REQUIRE(std::abs(dot(w, v)) <= 8 * kEps * size * norm(v));
    // ‖u×v‖² + (u·v)² = ‖u‖²‖v‖²
    const double lagrange = norm2(w) + dot(u, v) * dot(u, v);
    REQUIRE(lagrange == doctest::Approx(norm2(u) * norm2(v)).epsilon(16 * kEps));
    const Vec3 back = cross(v, u);
    REQUIRE(back.x == doctest::Approx(-w.x).epsilon(2 * kEps).scale(kEps * size));
    REQUIRE(back.z == doctest::Approx(-w.z).epsilon(2 * kEps).scale(kEps * size));
  }
}

TEST_CASE("geometry/vec: normalized") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SUBCASE("1. the zero vector has no direction") {
    CHECK_FALSE(normalized(Vec2{0, 0}).has_value());
    CHECK_FALSE(normalized(Vec2{-0.0, 0}).has_value());
    CHECK_FALSE(normalized(Vec3{0, 0, 0}).has_value());
  }
  SUBCASE("2. non-finite vectors have none either") {
    CHECK_FALSE(normalized(Vec2{inf, 0}).has_value());
    CHECK_FALSE(normalized(Vec2{nan, 1}).has_value());
    CHECK_FALSE(normalized(Vec3{0, 0, -inf}).has_value());
  }
  SUBCASE("3. a 3-4-5 vector") {
    const Vec2 u = *normalized(Vec2{3, 4});
    CHECK(u.x == doctest::Approx(0.6).epsilon(1e-16));
    CHECK(u.y == doctest::Approx(0.8).epsilon(1e-16));
  }
  SUBCASE("4. every length from subnormal to near overflow gives a unit vector") {
    for (double length : {5e-324, 1e-320, 1e-310, 1e-300, 1e-8, 1.0, 1e8, 1e300, 1e308}) {
      for (Vec2 dir : {Vec2{1, 1}, Vec2{3, -4}, Vec2{-1, 0}, Vec2{1e-3, 1}}) {
        CAPTURE(length);
        CAPTURE(dir.x);
        const Vec2 v = length / std::max(std::abs(dir.x), std::abs(dir.y)) * dir;
        if (!(norm(v) > 0) && !(std::abs(v.x) > 0 || std::abs(v.y) > 0))
          continue;  // underflowed to 0
        const auto u = normalized(v);
        REQUIRE(u.has_value());
        CHECK(norm(*u) == doctest::Approx(1).epsilon(4 * kEps));
        // and it points the way v does, as far as v's rounded coordinates tell
        CHECK(std::abs(cross(*u, v)) <= 4 * kEps * std::max(std::abs(v.x), std::abs(v.y)));
        CHECK(dot(*u, v) > 0);
      }
    }
  }
  SUBCASE("5. the same in 3D") {
    for (double length : {5e-324, 1e-310, 1e-8, 1.0, 1e300, 1e308}) {
      CAPTURE(length);
      const auto u = normalized(Vec3{length, length, length});
      REQUIRE(u.has_value());
      CHECK(norm(*u) == doctest::Approx(1).epsilon(4 * kEps));
      CHECK(u->x == doctest::Approx(1 / std::sqrt(3.0)).epsilon(4 * kEps));
    }
  }
  SUBCASE("6. random directions of any length are unit to 2 ulps") {
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
      Rng rng(seed);
      CAPTURE(seed);
      const Vec2 v = epure::test::direction2(rng);
      const Vec2 u = *normalized(v);
      REQUIRE(norm(u) == doctest::Approx(1).epsilon(3 * kEps));
      REQUIRE(std::abs(cross(u, v)) <= 2 * kEps * norm(v));
    }
  }
}

TEST_SUITE_END();
