// Pins geometry/predicates.h: each filtered predicate's sign is the exact sign of its polynomial
// of the given doubles, on the boundary and at 1, 2 and 3 ulps from it (where the filter cannot
// tell and the exact expansion decides), and its value keeps that sign and its digits. The
// expected signs come from the construction (a boundary on a binary grid, one number moved by k
// ulps changes the polynomial by a known product), not from the code under test.
#include "geometry/predicates.h"

#include <doctest/doctest.h>

#include <cmath>

#include "support/draw.h"
#include "support/real.h"

using namespace epure::geo;
using epure::Rng;
namespace T = epure::test;

namespace {

double nudged(double x, int k) {
  for (int i = 0; i < std::abs(k); ++i)
    x = std::nextafter(x, k > 0 ? INFINITY : -INFINITY);
  return x;
}
int sign(double x) { return (x > 0) - (x < 0); }

// A grid step near unit size and an offset far from the origin on it: the points are exact.
struct Grid {
  double unit;
  Point2 offset;
};
Grid draw_grid(Rng& rng) {
  const double unit = std::ldexp(1.0, static_cast<int>(rng.integer(-8, 0)));
  const double far = std::ldexp(1.0, static_cast<int>(rng.integer(0, 30)));
  return {unit, {unit * std::round(rng.uniform(-far, far)), unit * std::round(rng.uniform(-far, far))}};
}
Vec2 grid_vec(Rng& rng, double unit) {
  for (;;) {
    const Vec2 v{unit * static_cast<double>(rng.integer(-16, 16)),
                 unit * static_cast<double>(rng.integer(-16, 16))};
    if (v.x != 0 && v.y != 0) return v;
  }
}

}  // namespace

TEST_CASE("predicates: the cross of exactly parallel differences moved by k ulps (1000 seeds)") {
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    const Grid g = draw_grid(rng);
    const Vec2 u = grid_vec(rng, g.unit);
    const Point2 P0 = g.offset, P1 = P0 + u;
    const Point2 Q0 = P0 + grid_vec(rng, g.unit);
    const double m = static_cast<double>(rng.integer(1, 4)) * (rng.chance(0.5) ? 1 : -1);
    Point2 Q1 = Q0 + m * u;
    // a zero moved by an ulp is subnormal, and its products underflow (outside the contract)
    if (Q1.x == 0) continue;
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    Q1.x = nudged(Q1.x, k);
    // u ∧ (m·u + δ·e_x) = −u_y·δ
    const Certain c = certain_cross(exact_difference(P1, P0), exact_difference(Q1, Q0));
    const int expected = -sign(u.y) * sign(k);
    CHECK(c.sign == expected);
    CHECK(sign(c.value) == expected);
    const double delta = Q1.x - (Q0 + m * u).x;  // exact: neighbours
    CHECK(c.value == -u.y * delta);
  }
}

TEST_CASE("predicates: the dot of exactly perpendicular differences moved by k ulps (1000 seeds)") {
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    const Grid g = draw_grid(rng);
    const Vec2 u = grid_vec(rng, g.unit);
    const Point2 P0 = g.offset, P1 = P0 + u;
    const double m = static_cast<double>(rng.integer(1, 4));
    Point2 Q1 = P0 + m * perp(u);
    if (Q1.x == 0) continue;  // a subnormal after the move: outside the contract
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    Q1.x = nudged(Q1.x, k);
    const Certain d = certain_dot(exact_difference(P1, P0), exact_difference(Q1, P0));
    CHECK(d.sign == sign(u.x) * sign(k));
    CHECK(sign(d.value) == d.sign);
  }
}

TEST_CASE("predicates: on, inside and outside a circle, and tangent, at k ulps (1000 seeds)") {
  static constexpr int kTriples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}};
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    const auto& t = kTriples[rng.integer(0, 3)];
    const double k2 = std::ldexp(1.0, static_cast<int>(rng.integer(-6, 6)));
    const Grid g = draw_grid(rng);
    const Point2 C = g.offset, A = C + Vec2{k2 * t[0], k2 * t[1]};
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    const double r = nudged(k2 * t[2], k);
    // ‖AC‖² − r²: below zero (inside) exactly when r grew
    const Certain excess = certain_excess(exact_difference(C, A), r);
    CHECK(excess.sign == -sign(k));
    CHECK(sign(excess.value) == excess.sign);
    // the line along ±x through C + (0, k2·t2): tangent to the circle of radius k2·t2 about C,
    // a chord when r grew, a miss when it shrank; seen from far along the line
    const Point2 far{C.x - std::ldexp(1.0, static_cast<int>(rng.integer(0, 20))) * g.unit,
                     C.y + k2 * t[2]};
    const Vec2 u{rng.chance(0.5) ? 1.0 : 0.25, 0.0};
    const Certain disc = certain_discriminant(u, exact_difference(C, far), r);
    CHECK(disc.sign == sign(k));
    CHECK(sign(disc.value) == disc.sign);
    if (k != 0) {
      // and its value to its digits: ‖u‖²(r² − R²), R = k2·t2, in quadruple precision
      const T::Real R = k2 * t[2], rr = r;
      const double expected = static_cast<double>(T::Real(u.x) * u.x * (rr * rr - R * R));
      CHECK(std::abs(disc.value - expected) <= 4 * std::abs(std::nextafter(expected, 0.0) - expected));
    }
  }
}

TEST_CASE("predicates: a sum of two products of exact gaps at k ulps from zero (1000 seeds)") {
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    // (1 − a)·y − (1 − b)·y with b = a moved by k ulps: y·(b − a)
    const double a = rng.uniform(-4, 4);
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    const double b = nudged(a, k), y = rng.uniform(0.5, 2);
    const exact::TwoTerm ga = exact::two_difference(1.0, a), gb = exact::two_difference(1.0, b);
    const Certain s = certain_sum_of_products(ga, y, {-gb.hi, -gb.lo}, y);
    CHECK(s.sign == sign(k));
  }
}

TEST_CASE("predicates: far from a boundary the filter answers, with the compensated value") {
  const ExactVec2 u = exact_difference(Point2{3, 1}, Point2{1, 0});
  const ExactVec2 v = exact_difference(Point2{0, 5}, Point2{1, 0});
  CHECK(certain_cross(u, v).sign == 1);
  CHECK(certain_cross(u, v).value == cross(u, v));
  CHECK(certain_dot(u, v).value == dot(u, v));
  CHECK(certain_dot(u, v).sign == 1);  // (2, 1)·(−1, 5) = 3
}

TEST_CASE("predicates: quotient of double-doubles is the correctly rounded one for exact doubles") {
  Rng rng(7);
  for (int i = 0; i < 1000; ++i) {
    const double n = rng.uniform(-10, 10), d = rng.uniform(0.1, 10);
    CHECK(quotient(Certain{sign(n), n, 0}, d, 0) == n / d);
  }
}
