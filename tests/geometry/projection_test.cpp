// Pins geometry/projection.h, exercise 1 of the course: the projection P of C on (AB) by the dot
// product, t = AB·AC / AB·AB, P = A + t·AB, and where P falls (before / between / after).
// The course's and the contract's worked examples; A = B refused as field "B"; P on an end
// snapped to exactly t = 0 or 1 (the end point itself); property tests against a
// quadruple-precision reference: t correct to a few ε of itself (also for C nearly above A,
// t ≈ 0), CP ⟂ AB, invariance under translating, rotating and scaling the figure, from 1e-200
// to 1e200.
#include "geometry/projection.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/degenerate.h"
#include "support/approx.h"
#include "support/draw.h"
#include "support/exactly.h"
#include "support/real.h"

using namespace epure::geo;
using epure::Rng;
using epure::test::d;
using epure::test::exactly;
using epure::test::Real;
namespace T = epure::test;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Expected {
  Real t;
  T::R2 P;
};
Expected reference(Point2 A, Point2 B, Point2 C) {
  const T::R2 a = T::real(A), ab = T::real(B) - a, ac = T::real(C) - a;
  const Real t = T::dot(ab, ac) / T::dot(ab, ab);
  return {t, a + t * ab};
}

void check_against_reference(Point2 A, Point2 B, Point2 C) {
  const Projection p = project(A, B, C);
  const Expected e = reference(A, B, C);
  const double size = std::max(
      {std::abs(A.x), std::abs(A.y), std::abs(B.x), std::abs(B.y), std::abs(C.x), std::abs(C.y)});
  const double ratio = norm(C - A) / norm(B - A);
  CAPTURE(d(e.t));
  CAPTURE(p.t);
  // near an end the result is snapped by design: exactness is pinned elsewhere
  if (T::abs(e.t) < 1e-13 * (ratio + 1) || T::abs(e.t - 1) < 1e-13 * (ratio + 1)) return;
  CHECK(p.t == doctest::Approx(d(e.t)).epsilon(8 * kEps).scale(0));
  CHECK(p.P.x ==
        doctest::Approx(d(e.P.x)).epsilon(4 * kEps).scale(size + std::abs(p.t) * norm(B - A)));
  CHECK(p.P.y ==
        doctest::Approx(d(e.P.y)).epsilon(4 * kEps).scale(size + std::abs(p.t) * norm(B - A)));
  CHECK(p.position == (e.t < 0 ? Position::before : e.t > 1 ? Position::after : Position::between));
  // the construction data say what they are
  CHECK(p.ab_dot_ab == doctest::Approx(d(T::dot(T::real(B) - T::real(A), T::real(B) - T::real(A))))
                           .epsilon(4 * kEps));
  CHECK(p.t == doctest::Approx(p.ab_dot_ac / p.ab_dot_ab).epsilon(4 * kEps).scale(0));
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/projection: the contract's worked examples") {
  SUBCASE("1. between: t = 1/4") {
    const Projection p = project({0, 0}, {4, 0}, {1, 3});
    CHECK(exactly(p.t, 0.25));
    CHECK(exactly(p.P.x, 1));
    CHECK(exactly(p.P.y, 0));
    CHECK(p.position == Position::between);
    CHECK(exactly(p.ab_dot_ac, 4));
    CHECK(exactly(p.ab_dot_ab, 16));
  }
  SUBCASE("2. before A: t = −1/2") {
    const Projection p = project({0, 0}, {4, 0}, {-2, 1});
    CHECK(exactly(p.t, -0.5));
    CHECK(exactly(p.P.x, -2));
    CHECK(p.position == Position::before);
    CHECK(std::string(to_string(p.position)) == "before");
  }
  SUBCASE("3. after B: t = 3/2") {
    const Projection p = project({0, 0}, {4, 0}, {6, -1});
    CHECK(exactly(p.t, 1.5));
    CHECK(exactly(p.P.x, 6));
    CHECK(p.position == Position::after);
    CHECK(std::string(to_string(p.position)) == "after");
    CHECK(std::string(to_string(Position::between)) == "between");
  }
}

TEST_CASE("geometry/projection: hand-computed cases") {
  SUBCASE("1. a slanted line: A(1,1) B(3,5), C(6,2)") {
    // AB = (2,4), AC = (5,1): t = 14/20, P = (1 + 1.4, 1 + 2.8)
    const Projection p = project({1, 1}, {3, 5}, {6, 2});
    CHECK(p.t == doctest::Approx(0.7).epsilon(2 * kEps));
    CHECK(p.P.x == doctest::Approx(2.4).epsilon(2 * kEps));
    CHECK(p.P.y == doctest::Approx(3.8).epsilon(2 * kEps));
    CHECK(p.position == Position::between);
    CHECK(exactly(p.AB.x, 2));
    CHECK(exactly(p.AC.y, 1));
  }
  SUBCASE("2. C on the line already: P = C") {
    const Projection p = project({0, 0}, {2, 2}, {3, 3});
    CHECK(exactly(p.t, 1.5));
    CHECK(exactly(p.P.x, 3));
    CHECK(exactly(p.P.y, 3));
  }
  SUBCASE("3. the course's unit-vector form: t = u·AC when AB is unit") {
    const Projection p = project({2, -1}, {2.6, -0.2}, {5, 3});  // AB = (0.6, 0.8)
    CHECK(p.t == doctest::Approx(0.6 * 3 + 0.8 * 4).epsilon(4 * kEps));
  }
}

TEST_CASE("geometry/projection: degenerate and boundary branches") {
  SUBCASE("1. A = B: no line, field B") {
    try {
      project({1, 1}, {1, 1}, {0, 0});
      FAIL("no exception");
    } catch (const DegenerateFigure& e) {
      CHECK(e.field() == "B");
    }
  }
  SUBCASE("2. A and B a rounding apart are the same point") {
    CHECK_THROWS_AS(project({1, 1}, {std::nextafter(1.0, 2.0), 1}, {0, 0}), DegenerateFigure);
    CHECK_THROWS_AS(project({1e8, -1e8}, {1e8, std::nextafter(-1e8, 0.0)}, {0, 0}),
                    DegenerateFigure);
  }
  SUBCASE("3. a short segment is still a segment, at any scale") {
    CHECK(project({1, 1}, {1 + 1e-9, 1}, {2, 5}).t == doctest::Approx(1e9).epsilon(1e-6));
    const double tiny = std::ldexp(1.0, -1000);
    CHECK(exactly(project({tiny, 0}, {2 * tiny, 0}, {3 * tiny, 7 * tiny}).t, 2));
  }
  SUBCASE("4. C = A: exactly t = 0, P = A") {
    const Projection p = project({0.1, 0.7}, {0.3, -0.2}, {0.1, 0.7});
    CHECK(exactly(p.t, 0));
    CHECK(exactly(p.P.x, 0.1));
    CHECK(exactly(p.P.y, 0.7));
    CHECK(p.position == Position::between);
  }
  SUBCASE("5. C = B: exactly t = 1, P = B") {
    const Projection p = project({0.1, 0.7}, {0.3, -0.2}, {0.3, -0.2});
    CHECK(exactly(p.t, 1));
    CHECK(exactly(p.P.x, 0.3));
    CHECK(exactly(p.P.y, -0.2));
    CHECK(p.position == Position::between);
  }
  SUBCASE("6. C meant above B, off by decimal rounding: snapped onto B") {
    // AB = (0.3, 0.1) and BC = (−0.1, 0.3) are perpendicular as decimals, not as doubles
    const Projection p = project({0.1, 0.2}, {0.4, 0.3}, {0.3, 0.6});
    CHECK(exactly(p.t, 1));
    CHECK(exactly(p.P.x, 0.4));
    CHECK(p.position == Position::between);
  }
  SUBCASE("7. just past an end by more than rounding: not snapped") {
    const Projection p = project({0, 0}, {1, 0}, {1 + 1e-12, 5});
    CHECK(p.t == doctest::Approx(1 + 1e-12).epsilon(kEps));
    CHECK(p.t > 1);
    CHECK(p.position == Position::after);
    const Projection q = project({0, 0}, {1, 0}, {-1e-12, 5});
    CHECK(q.position == Position::before);
  }
  SUBCASE("8. huge and tiny figures: the same t, no overflow or underflow") {
    for (double k : {1e-200, 1e-8, 1e8, 1e200}) {
      CAPTURE(k);
      const Projection p = project({0, 0}, {4 * k, 0}, {1 * k, 3 * k});
      CHECK(p.t == doctest::Approx(0.25).epsilon(2 * kEps));
      CHECK(p.P.x == doctest::Approx(k).epsilon(2 * kEps));
      CHECK(p.position == Position::between);
    }
  }
  SUBCASE("9. a small figure far from the origin: 1e-8 at 1e8") {
    const Projection p = project({1e8, 1e8}, {1e8 + 4e-6, 1e8}, {1e8 + 1e-6, 1e8 + 3e-6});
    const Expected e = reference({1e8, 1e8}, {1e8 + 4e-6, 1e8}, {1e8 + 1e-6, 1e8 + 3e-6});
    CHECK(p.t == doctest::Approx(d(e.t)).epsilon(4 * kEps));
  }
}

TEST_CASE("geometry/projection: random figures against quadruple precision") {
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const double size = T::decades(rng, -8, 8);
    const Point2 A = T::point2(rng, size), B = T::point2(rng, size);
    Point2 C = T::point2(rng, size);
    // a third of the figures have C nearly above A or B: t near 0 or 1, at a random distance
    if (seed % 3 == 1) {
      const Point2 end = rng.chance(0.5) ? A : B;
      const double off = T::decades(rng, -12, -4) * T::sign(rng);
      C = end + (T::decades(rng, -2, 2) * perp(B - A) + off * (B - A));
    }
    CAPTURE(A.x);
    CAPTURE(A.y);
    CAPTURE(B.x);
    CAPTURE(B.y);
    CAPTURE(C.x);
    CAPTURE(C.y);
    check_against_reference(A, B, C);

    const Projection p = project(A, B, C);
    // CP ⟂ AB, to the rounding of P (unless P was snapped onto an end)
    const T::R2 cp = T::real(p.P) - T::real(C), ab = T::real(B) - T::real(A);
    if (!exactly(p.t, 0) && !exactly(p.t, 1))
      CHECK(d(T::abs(T::dot(cp, ab))) <=
            16 * kEps * (size + std::abs(p.t) * norm(B - A)) * d(T::norm(ab)));

    // scaling by a power of two changes no bit of t; translating, rotating and scaling by any
    // factor changes t by the data's rounding only
    const double two = std::ldexp(1.0, static_cast<int>(rng.integer(-60, 60)));
    CHECK(exactly(
        project(to_point(two * to_vec(A)), to_point(two * to_vec(B)), to_point(two * to_vec(C))).t,
        p.t));
    const double angle = rng.uniform(-std::numbers::pi, std::numbers::pi),
                 k = T::decades(rng, -3, 3);
    const Vec2 shift = k * size * Vec2{rng.uniform(-3, 3), rng.uniform(-3, 3)};
    const double c = k * std::cos(angle), s = k * std::sin(angle);
    auto move = [&](Point2 q) { return Point2{c * q.x - s * q.y, s * q.x + c * q.y} + shift; };
    const Projection m = project(move(A), move(B), move(C));
    // the moved data are rounded: t moves by a few ε of the figure over ‖AB‖
    const double figure =
        (std::max({norm(to_vec(A)), norm(to_vec(B)), norm(to_vec(C))}) + 3 * size) / norm(B - A);
    CHECK(m.t == T::within(p.t, 64 * kEps, 64 * kEps * figure * (1 + figure)));
  }
}

TEST_SUITE_END();

TEST_CASE("geometry/projection_exact: no snapping, the doubles as they are") {
  SUBCASE("1. issue 15: C 1e-15 before A is before, t < 0") {
    const Projection p = project_exact(Point2{0, 0}, Point2{1, 0}, Point2{-1e-15, 5});
    CHECK(p.position == Position::before);
    CHECK(p.t < 0);
    CHECK(p.t == doctest::Approx(-1e-15).epsilon(kEps));
  }
  SUBCASE("2. C above B as decimals, not as doubles: decided as the doubles lie") {
    // AB = (0.3, 0.1) and BC = (−0.1, 0.3) are perpendicular as decimals, not as doubles: the
    // sign of AB·BC of the doubles (exact in quadruple precision) places t
    const Point2 A{0.1, 0.2}, B{0.4, 0.3}, C{0.3, 0.6};
    const Projection p = project_exact(A, B, C);
    const Real ab_bc = T::dot(T::real(B) - T::real(A), T::real(C) - T::real(B));
    REQUIRE(ab_bc != 0);
    CHECK(p.position == (ab_bc > 0 ? Position::after : Position::between));
    CHECK(!exactly(p.t, 1));
    CHECK(p.t == doctest::Approx(1).epsilon(8 * kEps));
    // the worksheet semantics snaps it onto B
    CHECK(exactly(project(A, B, C).t, 1));
  }
  SUBCASE("3. the exact ends: t exactly 0 at A's foot, 1 at B's, P the end itself") {
    const Projection a = project_exact(Point2{1, 2}, Point2{5, 2}, Point2{1, 7});
    CHECK(exactly(a.t, 0));
    CHECK(exactly(a.P.x, 1));
    const Projection b = project_exact(Point2{1, 2}, Point2{5, 2}, Point2{5, -7});
    CHECK(exactly(b.t, 1));
    CHECK(exactly(b.P.x, 5));
    CHECK(b.position == Position::between);
  }
  SUBCASE("4. A = B exactly is refused; an ulp apart is a segment") {
    CHECK_THROWS_AS(project_exact(Point2{1, 1}, Point2{1, 1}, Point2{0, 0}), DegenerateFigure);
    CHECK(project_exact(Point2{1, 1}, Point2{1, std::nextafter(1.0, 2.0)}, Point2{0, 0}).position == Position::before);
  }
}

TEST_CASE("geometry/projection_exact: at 1, 2 and 3 ulps from an end, the position is the exact one") {
  // C above A or B exactly (a binary grid, far from the origin or not), then one coordinate of C
  // moved by k ulps: AB·AC (or AB·BC) becomes AB_x·δ, whose sign is known.
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const double unit = std::ldexp(1.0, static_cast<int>(rng.integer(-10, 4)));
    const double far = std::ldexp(1.0, static_cast<int>(rng.integer(0, 40)));
    auto grid = [&](double extent) { return unit * std::round(rng.uniform(-extent, extent)); };
    const Point2 A{grid(far), grid(far)};
    Vec2 AB{unit * static_cast<double>(rng.integer(-32, 32)), unit * static_cast<double>(rng.integer(-32, 32))};
    if (AB.x == 0) AB.x = unit;
    const Point2 B = A + AB;
    const bool at_b = rng.chance(0.5);
    Point2 C = (at_b ? B : A) + static_cast<double>(rng.integer(-4, 4)) * perp(AB);
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    const double x0 = C.x;
    if (x0 == 0) continue;  // a zero moved by an ulp is subnormal: outside the contract
    for (int i = 0; i < std::abs(k); ++i) C.x = std::nextafter(C.x, k > 0 ? INFINITY : -INFINITY);
    const double delta = C.x - x0;  // exact: neighbours
    const double s = AB.x * delta;  // AB·AC at A, AB·BC at B
    const Projection p = project_exact(A, B, C);
    if (!at_b) {
      CHECK(p.position == (s < 0 ? Position::before : Position::between));
      CHECK((s < 0 ? p.t < 0 : p.t >= 0));
      if (k == 0) CHECK(exactly(p.t, 0));
    } else {
      CHECK(p.position == (s > 0 ? Position::after : Position::between));
      CHECK((s > 0 ? p.t > 1 : p.t <= 1));
      if (k == 0) CHECK(exactly(p.t, 1));
    }
  }
}
