// Pins geometry/vectors.h, the course's preamble: dot, cross, norms, cos and sin of the signed
// angle u→v and that angle in degrees, in (−180, 180] (opposite vectors give 180, never −180).
// Zero vectors are refused with the field named. Property tests against quadruple-precision
// references: cos² + sin² = 1, dot = ‖u‖‖v‖cos and cross = ‖u‖‖v‖sin, the angle is atan2's,
// it changes sign when u and v swap, and nothing changes when u and v are scaled or the pair is
// rotated — from subnormal to 1e300 lengths.
#include "geometry/vectors.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/degenerate.h"
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

void check_pair(const VectorPair& got, Vec2 u, Vec2 v) {
  const epure::test::R2 U = epure::test::real(u), V = epure::test::real(v);
  const Real nu = epure::test::norm(U), nv = epure::test::norm(V);
  const Real cos = epure::test::dot(U, V) / (nu * nv), sin = epure::test::cross(U, V) / (nu * nv);
  CHECK(got.dot == doctest::Approx(d(epure::test::dot(U, V))).epsilon(4 * kEps));
  CHECK(got.cross == doctest::Approx(d(epure::test::cross(U, V))).epsilon(4 * kEps));
  CHECK(got.norm_u == doctest::Approx(d(nu)).epsilon(2 * kEps));
  CHECK(got.norm_v == doctest::Approx(d(nv)).epsilon(2 * kEps));
  // cos and sin to a few ε of their own size: the sine of nearly parallel vectors keeps its
  // digits (scale 0 makes Approx purely relative)
  CHECK(got.cos == doctest::Approx(d(cos)).epsilon(8 * kEps).scale(0));
  CHECK(got.sin == doctest::Approx(d(sin)).epsilon(8 * kEps).scale(0));
  CHECK(got.cos * got.cos + got.sin * got.sin == doctest::Approx(1).epsilon(8 * kEps));
  CHECK(got.angle_deg > -180.0);
  CHECK(got.angle_deg <= 180.0);
  const double expected_deg =
      std::atan2(static_cast<long double>(sin), static_cast<long double>(cos)) *
      (180 / std::numbers::pi_v<long double>);
  // at ±180 the two ends of the interval are the same angle
  if (std::abs(expected_deg) > 179.9 && got.angle_deg * expected_deg < 0)
    CHECK(std::abs(got.angle_deg) + std::abs(expected_deg) == doctest::Approx(360).epsilon(1e-14));
  else
    CHECK(got.angle_deg == doctest::Approx(expected_deg).epsilon(1e-14).scale(0));
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/vectors: the contract's worked examples") {
  SUBCASE("1. (3,4) and (−4,3): a quarter turn counter-clockwise") {
    const VectorPair p = compare_vectors({3, 4}, {-4, 3});
    CHECK(exactly(p.dot, 0));
    CHECK(exactly(p.cross, 25));
    CHECK(exactly(p.norm_u, 5));
    CHECK(exactly(p.norm_v, 5));
    CHECK(p.cos == doctest::Approx(0).epsilon(1e-16));
    CHECK(p.sin == doctest::Approx(1).epsilon(1e-16));
    CHECK(p.angle_deg == doctest::Approx(90).epsilon(1e-15));
  }
  SUBCASE("2. opposite vectors: 180, not −180") {
    const VectorPair p = compare_vectors({1, 0}, {-1, 0});
    CHECK(exactly(p.dot, -1));
    CHECK(exactly(p.cos, -1));
    CHECK(exactly(p.angle_deg, 180));
  }
}

TEST_CASE("geometry/vectors: hand-computed angles") {
  SUBCASE("1. same direction, any lengths: 0°") {
    const VectorPair p = compare_vectors({2, 2}, {1e-8, 1e-8});
    CHECK(p.cos == doctest::Approx(1).epsilon(2 * kEps));
    CHECK(p.angle_deg == doctest::Approx(0).epsilon(1e-15).scale(1e-14));
  }
  SUBCASE("2. clockwise quarter turn: −90°") {
    CHECK(compare_vectors({0, 1}, {1, 0}).angle_deg == doctest::Approx(-90).epsilon(1e-15));
  }
  SUBCASE("3. 3-4-5 against the x-axis") {
    const VectorPair p = compare_vectors({1, 0}, {-3, -4});
    CHECK(p.cos == doctest::Approx(-0.6).epsilon(2 * kEps));
    CHECK(p.sin == doctest::Approx(-0.8).epsilon(2 * kEps));
    CHECK(p.angle_deg == doctest::Approx(-126.86989764584402).epsilon(1e-14));
  }
  SUBCASE("4. opposite with a negative zero anywhere: still 180") {
    for (Vec2 v : {Vec2{-1, -0.0}, Vec2{-1, 0.0}, Vec2{-5, -0.0}}) {
      CAPTURE(v.y);
      CHECK(exactly(compare_vectors({1, 0}, v).angle_deg, 180));
      CHECK(exactly(compare_vectors({1, -0.0}, v).angle_deg, 180));
      CHECK(exactly(compare_vectors({-3, 0}, {3, -0.0}).angle_deg, 180));
    }
  }
  SUBCASE("5. 45° steps") {
    CHECK(compare_vectors({1, 0}, {1, 1}).angle_deg == doctest::Approx(45).epsilon(1e-15));
    CHECK(compare_vectors({1, 0}, {-1, 1}).angle_deg == doctest::Approx(135).epsilon(1e-15));
    CHECK(compare_vectors({1, 0}, {-1, -1}).angle_deg == doctest::Approx(-135).epsilon(1e-15));
  }
}

TEST_CASE("geometry/vectors: angle_degrees folds atan2 into (−180, 180]") {
  CHECK(exactly(angle_degrees(-1, -0.0), 180));
  CHECK(exactly(angle_degrees(-1, 0.0), 180));
  // a negative sine whose angle rounds to −180: the interval's nearest double, of the sine's sign
  // (180 would say the turn is counter-clockwise)
  CHECK(exactly(angle_degrees(-1, -1e-300), std::nextafter(-180.0, 0.0)));
  CHECK(exactly(angle_degrees(-1, -1e-17), -179.99999999999997));
  CHECK(exactly(angle_degrees(-1, 1e-300), 180));
  // the case the exact reference found: −0.4 is not −0.4 in binary, so u ∧ v = −1.1e-16 < 0
  const VectorPair nearly_opposite = compare_vectors({5, 2}, {-1, -0.4});
  CHECK(nearly_opposite.sin < 0);
  CHECK(exactly(nearly_opposite.angle_deg, -179.99999999999997));
  // just below the negative axis: the far end of the interval, not folded
  CHECK(angle_degrees(-1, -1e-10) > -180);
  CHECK(angle_degrees(-1, -1e-10) < -179.9999999);
  CHECK(angle_degrees(0, -1) == doctest::Approx(-90).epsilon(1e-15));
  CHECK(exactly(angle_degrees(1, 0), 0));
}

TEST_CASE("geometry/vectors: zero vectors are refused, naming the field") {
  SUBCASE("1. zero u") {
    try {
      compare_vectors({0, 0}, {1, 0});
      FAIL("no exception");
    } catch (const DegenerateFigure& e) {
      CHECK(e.field() == "u");
    }
  }
  SUBCASE("2. zero v") {
    try {
      compare_vectors({1, 0}, {0, -0.0});
      FAIL("no exception");
    } catch (const DegenerateFigure& e) {
      CHECK(e.field() == "v");
    }
  }
  SUBCASE("3. a subnormal vector is not zero") {
    const VectorPair p = compare_vectors({5e-324, 5e-324}, {1, 0});
    CHECK(p.cos == doctest::Approx(std::sqrt(0.5)).epsilon(4 * kEps));
    CHECK(p.sin == doctest::Approx(-std::sqrt(0.5)).epsilon(4 * kEps));
    CHECK(p.angle_deg == doctest::Approx(-45).epsilon(1e-14));
  }
}

TEST_CASE("geometry/vectors: extreme lengths keep the angle") {
  // powers of two, so that (3, 4)·k is exact down to the smallest subnormal
  for (int e : {-1074, -1060, -1030, -500, -27, 27, 500, 1020}) {
    const double k = std::ldexp(1.0, e);
    CAPTURE(e);
    const VectorPair p = compare_vectors(Vec2{3, 4} * k, Vec2{-4, 3});
    CHECK(p.cos == doctest::Approx(0).epsilon(4 * kEps).scale(1));
    CHECK(p.sin == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(p.angle_deg == doctest::Approx(90).epsilon(1e-14));
  }
}

TEST_CASE("geometry/vectors: random pairs against quadruple precision") {
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Vec2 u = epure::test::direction2(rng);
    Vec2 v = epure::test::direction2(rng);
    // a third of the pairs nearly parallel or antiparallel: the angle's ends
    if (seed % 3 == 0)
      v = epure::test::sign(rng) *
          (u + epure::test::decades(rng, -15, -3) * epure::test::sign(rng) * perp(u));
    CAPTURE(u.x);
    CAPTURE(u.y);
    CAPTURE(v.x);
    CAPTURE(v.y);
    const VectorPair p = compare_vectors(u, v);
    check_pair(p, u, v);

    // swapping u and v turns the angle the other way (but 180 stays 180)
    const VectorPair q = compare_vectors(v, u);
    CHECK(exactly(q.cos, p.cos));
    CHECK(q.sin == doctest::Approx(-p.sin).epsilon(2 * kEps).scale(1));
    if (p.angle_deg < 180)
      CHECK(q.angle_deg == doctest::Approx(-p.angle_deg).epsilon(1e-15).scale(1e-13));

    // scaling by powers of two changes nothing at all; by other factors, the last bits
    const VectorPair s = compare_vectors(std::ldexp(1.0, 40) * u, std::ldexp(1.0, -60) * v);
    CHECK(exactly(s.cos, p.cos));
    CHECK(exactly(s.sin, p.sin));
    const double k = epure::test::decades(rng, -8, 8);
    const VectorPair t = compare_vectors(k * u, v);
    CHECK(t.cos == doctest::Approx(p.cos).epsilon(4 * kEps).scale(1));
    CHECK(t.sin == doctest::Approx(p.sin).epsilon(4 * kEps).scale(1));

    // a quarter turn of the pair, or a general rotation, moves the angle by rounding only
    const VectorPair r = compare_vectors(perp(u), perp(v));
    CHECK(r.cos == doctest::Approx(p.cos).epsilon(2 * kEps).scale(1));
    CHECK(r.sin == doctest::Approx(p.sin).epsilon(2 * kEps).scale(1));
    const double a = rng.uniform(-std::numbers::pi, std::numbers::pi);
    const double c = std::cos(a), sn = std::sin(a);
    const VectorPair w = compare_vectors({c * u.x - sn * u.y, sn * u.x + c * u.y},
                                         {c * v.x - sn * v.y, sn * v.x + c * v.y});
    CHECK(w.cos == doctest::Approx(p.cos).epsilon(8 * kEps).scale(1));
    CHECK(w.sin == doctest::Approx(p.sin).epsilon(8 * kEps).scale(1));
  }
}

TEST_SUITE_END();
