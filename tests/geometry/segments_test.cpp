// Pins geometry/segments.h, exercise 2 of the course: [AB] ∩ [CD] by cross products,
// t_ab = AC∧CD / AB∧CD, t_cd = AC∧AB / AB∧CD, and the relation: intersects (an end touching
// counts, t snapped to exactly 0 or 1 and I the end itself), outside (both t given, no I),
// parallel, collinear (overlapping or not: no parameters). A = B and C = D refused as fields
// "B" and "D". Property tests against a quadruple-precision reference, including nearly
// parallel lines down to 1e-13 rad, where t keeps its digits: I lies on both segments and
// equals A + t_ab·AB = C + t_cd·CD; swapping or reversing the segments permutes the answer;
// translating, rotating and scaling the figure leaves it.
#include "geometry/segments.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

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
  Real cross;  // AB∧CD
  Real t_ab, t_cd;
  Real sine;  // of the angle between the lines
};
Expected reference(Point2 A, Point2 B, Point2 C, Point2 D) {
  const T::R2 ab = T::real(B) - T::real(A), cd = T::real(D) - T::real(C),
              ac = T::real(C) - T::real(A);
  const Real den = T::cross(ab, cd);
  return {den, T::cross(ac, cd) / den, T::cross(ac, ab) / den, den / (T::norm(ab) * T::norm(cd))};
}

void check_point(Point2 got, Point2 expected) {
  CHECK(exactly(got.x, expected.x));
  CHECK(exactly(got.y, expected.y));
}

template <class F>
void check_refused(F&& call, const std::string& field) {
  try {
    call();
    FAIL("no exception");
  } catch (const DegenerateFigure& e) {
    CHECK(e.field() == field);
  }
}

// The whole answer against the reference, for a figure away from the ambiguous edges (lines
// parallel to rounding, a t within rounding of an end): those are pinned case by case.
void check_against_reference(Point2 A, Point2 B, Point2 C, Point2 D) {
  const Expected e = reference(A, B, C, D);
  const SegmentIntersection s = intersect_segments(A, B, C, D);
  CAPTURE(d(e.t_ab));
  CAPTURE(d(e.t_cd));
  CAPTURE(d(e.sine));
  REQUIRE(s.t_ab.has_value());
  // the parameters keep their digits however close to parallel the lines are
  CHECK(*s.t_ab == T::within(d(e.t_ab), 16 * kEps, 1e-300));
  CHECK(*s.t_cd == T::within(d(e.t_cd), 16 * kEps, 1e-300));
  CHECK(s.ab_cross_cd == T::within(d(e.cross), 4 * kEps, 1e-300));
  const bool inside = e.t_ab >= 0 && e.t_ab <= 1 && e.t_cd >= 0 && e.t_cd <= 1;
  CHECK(s.intersects() == inside);
  CHECK(s.relation == (inside ? SegmentRelation::intersects : SegmentRelation::outside));
  CHECK(s.I.has_value() == inside);
  if (!s.I) return;
  // I = A + t_ab·AB = C + t_cd·CD: on both segments, to the rounding of its coordinates
  const T::R2 I = T::real(*s.I);
  const T::R2 on_ab = T::real(A) + e.t_ab * (T::real(B) - T::real(A));
  const T::R2 on_cd = T::real(C) + e.t_cd * (T::real(D) - T::real(C));
  const double size = std::max({std::abs(A.x), std::abs(A.y), std::abs(B.x), std::abs(B.y),
                                std::abs(C.x), std::abs(C.y), std::abs(D.x), std::abs(D.y)});
  CHECK(d(T::distance(I, on_ab)) <= 8 * kEps * size);
  CHECK(d(T::distance(I, on_cd)) <= 8 * kEps * size);
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/segments: the contract's worked examples") {
  SUBCASE("1. an X: both halves") {
    const SegmentIntersection s = intersect_segments({0, 0}, {4, 4}, {0, 4}, {4, 0});
    CHECK(s.intersects());
    CHECK(exactly(*s.t_ab, 0.5));
    CHECK(exactly(*s.t_cd, 0.5));
    check_point(*s.I, {2, 2});
    CHECK(exactly(s.ab_cross_cd, -32));
    CHECK(std::string(to_string(s.relation)) == "intersects");
  }
  SUBCASE("2. the lines cross beyond B: outside, both parameters, no point") {
    const SegmentIntersection s = intersect_segments({0, 0}, {1, 1}, {0, 4}, {4, 0});
    CHECK(s.relation == SegmentRelation::outside);
    CHECK(exactly(*s.t_ab, 2));
    CHECK(exactly(*s.t_cd, 0.5));
    CHECK_FALSE(s.I.has_value());
    CHECK(std::string(to_string(s.relation)) == "outside");
  }
  SUBCASE("3. parallel") {
    const SegmentIntersection s = intersect_segments({0, 0}, {2, 0}, {0, 1}, {2, 1});
    CHECK(s.relation == SegmentRelation::parallel);
    CHECK_FALSE(s.t_ab.has_value());
    CHECK_FALSE(s.t_cd.has_value());
    CHECK_FALSE(s.I.has_value());
    CHECK(std::string(to_string(s.relation)) == "parallel");
  }
  SUBCASE("4. collinear and overlapping: no parameters") {
    const SegmentIntersection s = intersect_segments({0, 0}, {2, 0}, {1, 0}, {3, 0});
    CHECK(s.relation == SegmentRelation::collinear);
    CHECK_FALSE(s.t_ab.has_value());
    CHECK_FALSE(s.I.has_value());
    CHECK(std::string(to_string(s.relation)) == "collinear");
  }
  SUBCASE("5. touching at an end: intersects, t exactly 1 and 0, I = B = C") {
    const SegmentIntersection s = intersect_segments({0, 0}, {2, 0}, {2, 0}, {2, 3});
    CHECK(s.intersects());
    CHECK(exactly(*s.t_ab, 1));
    CHECK(exactly(*s.t_cd, 0));
    check_point(*s.I, {2, 0});
  }
}

TEST_CASE("geometry/segments: every branch") {
  SUBCASE("1. A = B is refused as B, C = D as D (A = B first)") {
    check_refused([] { intersect_segments({1, 1}, {1, 1}, {0, 0}, {1, 0}); }, "B");
    check_refused([] { intersect_segments({0, 0}, {1, 0}, {2, 2}, {2, 2}); }, "D");
    check_refused([] { intersect_segments({1, 1}, {1, 1}, {2, 2}, {2, 2}); }, "B");
    // a rounding apart is the same point
    check_refused(
        [] {
          intersect_segments({0, 0}, {1, 0}, {3, 1}, {3, std::nextafter(1.0, 2.0)});
        },
        "D");
  }
  SUBCASE("2. crossing in the middle, slanted: hand computed") {
    // AB = (4,2), CD = (−1,3), AC = (2,−1): AB∧CD = 14, t_ab = AC∧CD/14 = 5/14, t_cd = AC∧AB/14 =
    // 8/14
    const SegmentIntersection s = intersect_segments({1, 1}, {5, 3}, {3, 0}, {2, 3});
    CHECK(s.intersects());
    CHECK(*s.t_ab == doctest::Approx(5.0 / 14).epsilon(2 * kEps));
    CHECK(*s.t_cd == doctest::Approx(8.0 / 14).epsilon(2 * kEps));
    CHECK(s.I->x == doctest::Approx(1 + 20.0 / 14).epsilon(2 * kEps));
    CHECK(s.I->y == doctest::Approx(1 + 10.0 / 14).epsilon(2 * kEps));
    CHECK(exactly(s.ab_cross_cd, 14));
    CHECK(exactly(s.ac_cross_cd, 5));
    CHECK(exactly(s.ac_cross_ab, 8));
  }
  SUBCASE("3. outside: beyond D, before A, beyond both") {
    const SegmentIntersection s1 = intersect_segments({0, 0}, {4, 0}, {2, 3}, {2, 1});
    CHECK(s1.relation == SegmentRelation::outside);
    CHECK(exactly(*s1.t_ab, 0.5));
    CHECK(exactly(*s1.t_cd, 1.5));
    const SegmentIntersection s2 = intersect_segments({0, 0}, {4, 0}, {-2, 1}, {-2, -1});
    CHECK(exactly(*s2.t_ab, -0.5));
    CHECK(exactly(*s2.t_cd, 0.5));
    CHECK(s2.relation == SegmentRelation::outside);
    const SegmentIntersection s3 = intersect_segments({0, 0}, {1, 0}, {2, 1}, {2, 2});
    CHECK(s3.relation == SegmentRelation::outside);
    CHECK(exactly(*s3.t_ab, 2));
    CHECK(exactly(*s3.t_cd, -1));
  }
  SUBCASE("4. parallel: same direction, opposite, slanted, far apart") {
    CHECK(intersect_segments({0, 0}, {2, 0}, {3, 1}, {1, 1}).relation == SegmentRelation::parallel);
    CHECK(intersect_segments({0, 0}, {1, 2}, {1, 0}, {3, 4}).relation == SegmentRelation::parallel);
    CHECK(intersect_segments({0, 0}, {1, 1}, {1e6, 0}, {1e6 + 2, 2}).relation ==
          SegmentRelation::parallel);
    // parallel as decimals, not as doubles: CD = (1.1, 1.3) − (1, 1) is not exactly (0.1, 0.3)
    CHECK(intersect_segments({0, 0}, {0.1, 0.3}, {1, 1}, {1.1, 1.3}).relation ==
          SegmentRelation::parallel);
    // the parallel branch still reports the cross products a worksheet shows
    const SegmentIntersection s = intersect_segments({0, 0}, {2, 0}, {0, 1}, {2, 1});
    CHECK(exactly(s.ab_cross_cd, 0));
    CHECK(exactly(s.ac_cross_ab, -2));
  }
  SUBCASE("5. collinear: overlapping, contained, identical, reversed, disjoint, end to end") {
    const Point2 A{0, 0}, B{3, 3};
    for (auto [C, D] :
         {std::pair{Point2{1, 1}, Point2{4, 4}}, std::pair{Point2{1, 1}, Point2{2, 2}},
          std::pair{A, B}, std::pair{B, A}, std::pair{Point2{5, 5}, Point2{7, 7}},
          std::pair{Point2{-2, -2}, Point2{-1, -1}}, std::pair{B, Point2{5, 5}}}) {
      CAPTURE(C.x);
      CAPTURE(D.x);
      const SegmentIntersection s = intersect_segments(A, B, C, D);
      CHECK(s.relation == SegmentRelation::collinear);
      CHECK_FALSE(s.intersects());
      CHECK_FALSE(s.t_ab.has_value());
      CHECK_FALSE(s.I.has_value());
    }
    // collinear as decimals: 0.1, 0.2, 0.3 on y = 2x
    CHECK(intersect_segments({0.1, 0.2}, {0.3, 0.6}, {0.7, 1.4}, {0.9, 1.8}).relation ==
          SegmentRelation::collinear);
  }
  SUBCASE("6. touching at each end: t snapped, I the end point itself") {
    // T shapes: one segment's end on the other's interior
    const SegmentIntersection a = intersect_segments({1, 0}, {1, 2}, {0, 0}, {2, 0});  // A on CD
    CHECK(a.intersects());
    CHECK(exactly(*a.t_ab, 0));
    CHECK(exactly(*a.t_cd, 0.5));
    check_point(*a.I, {1, 0});
    const SegmentIntersection b = intersect_segments({0, 0}, {2, 0}, {1, -1}, {1, 0});  // D on AB
    CHECK(b.intersects());
    CHECK(exactly(*b.t_cd, 1));
    check_point(*b.I, {1, 0});
    // V shape: the segments share an end
    const SegmentIntersection v = intersect_segments({0, 0}, {2, 1}, {0, 0}, {-1, 3});
    CHECK(v.intersects());
    CHECK(exactly(*v.t_ab, 0));
    CHECK(exactly(*v.t_cd, 0));
    check_point(*v.I, {0, 0});
    // an end on the other's end, the other way round
    const SegmentIntersection w = intersect_segments({0, 0}, {2, 1}, {5, 5}, {2, 1});
    CHECK(exactly(*w.t_ab, 1));
    CHECK(exactly(*w.t_cd, 1));
    check_point(*w.I, {2, 1});
  }
  SUBCASE("7. touching as decimals: C on [AB] only up to rounding still touches") {
    // C = (0.3, 0.6) lies on y = 2x as decimals; in doubles it is a hair off
    const SegmentIntersection s =
        intersect_segments({0.1, 0.2}, {0.5, 1.0}, {0.3, 0.6}, {0.7, -0.1});
    CHECK(s.intersects());
    CHECK(exactly(*s.t_cd, 0));
    check_point(*s.I, {0.3, 0.6});
    CHECK(*s.t_ab == doctest::Approx(0.5).epsilon(1e-14));
  }
  SUBCASE("8. missing an end by more than rounding: outside, not touching") {
    const SegmentIntersection s = intersect_segments({0, 0}, {2, 0}, {1, 1e-12}, {1, 1});
    CHECK(s.relation == SegmentRelation::outside);
    CHECK(*s.t_cd == doctest::Approx(-1e-12 / (1 - 1e-12)).epsilon(4 * kEps));
  }
  SUBCASE("9. nearly parallel, not parallel: the crossing far away, to the last digits") {
    // CD turned 1e-10 rad from AB: the lines cross near t_ab = 1e10, t_cd = 5e9
    const Point2 A{0, 0}, B{1, 0}, C{0, 1}, D{2, 1 - 2e-10};
    const SegmentIntersection s = intersect_segments(A, B, C, D);
    const Expected e = reference(A, B, C, D);
    CHECK(s.relation == SegmentRelation::outside);
    CHECK(*s.t_ab == T::within(d(e.t_ab), 4 * kEps, 0));
    CHECK(*s.t_cd == T::within(d(e.t_cd), 4 * kEps, 0));
    // and crossing inside both: an X with a 2e-12 angle
    const SegmentIntersection x = intersect_segments({0, 0}, {1, 1e-12}, {0, 1e-12}, {1, 0});
    CHECK(x.intersects());
    CHECK(*x.t_ab == doctest::Approx(0.5).epsilon(4 * kEps));
    CHECK(x.I->y == doctest::Approx(0.5e-12).epsilon(8 * kEps));
  }
  SUBCASE("10. the X at every scale, and 1e-8 far from the origin") {
    for (double k : {1e-200, 1e-8, 1e8, 1e200}) {
      CAPTURE(k);
      const SegmentIntersection s =
          intersect_segments({0, 0}, {4 * k, 4 * k}, {0, 4 * k}, {4 * k, 0});
      CHECK(s.intersects());
      CHECK(*s.t_ab == doctest::Approx(0.5).epsilon(2 * kEps));
      CHECK(s.I->x == doctest::Approx(2 * k).epsilon(2 * kEps));
      CHECK(intersect_segments({0, 0}, {2 * k, 0}, {0, k}, {2 * k, k}).relation ==
            SegmentRelation::parallel);
      CHECK(intersect_segments({0, 0}, {2 * k, 0}, {k, 0}, {3 * k, 0}).relation ==
            SegmentRelation::collinear);
    }
    const Point2 A{1e8, 1e8}, B{1e8 + 1e-6, 1e8 + 1e-6}, C{1e8, 1e8 + 1e-6}, D{1e8 + 1e-6, 1e8};
    const SegmentIntersection s = intersect_segments(A, B, C, D);
    const Expected e = reference(A, B, C, D);
    CHECK(s.intersects());
    CHECK(*s.t_ab == T::within(d(e.t_ab), 4 * kEps, 0));
  }
}

TEST_CASE("geometry/segments: random segments against quadruple precision") {
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const double size = T::decades(rng, -8, 8);
    const Point2 A = T::point2(rng, size), B = T::point2(rng, size), C = T::point2(rng, size);
    Point2 D = T::point2(rng, size);
    // half the figures nearly parallel: CD turned from AB by 1e-13 to 1e-3 rad
    if (seed % 2 == 1) {
      const double angle = T::decades(rng, -13, -3) * T::sign(rng),
                   k = T::decades(rng, -1, 1) * T::sign(rng);
      const Vec2 ab = B - A, cd{std::cos(angle) * ab.x - std::sin(angle) * ab.y,
                                std::sin(angle) * ab.x + std::cos(angle) * ab.y};
      D = C + k * cd;
    }
    CAPTURE(A.x);
    CAPTURE(A.y);
    CAPTURE(B.x);
    CAPTURE(B.y);
    CAPTURE(C.x);
    CAPTURE(C.y);
    CAPTURE(D.x);
    CAPTURE(D.y);
    const Expected e = reference(A, B, C, D);
    if (T::abs(e.sine) < 1e-12) continue;  // parallel to rounding: pinned case by case
    const SegmentIntersection s = intersect_segments(A, B, C, D);
    // away from the ends (where t is snapped by design), the whole answer is the reference's
    const Real margin = 1e-12 * (1 + 1 / T::abs(e.sine));
    if (T::abs(e.t_ab) > margin && T::abs(e.t_ab - 1) > margin && T::abs(e.t_cd) > margin &&
        T::abs(e.t_cd - 1) > margin)
      check_against_reference(A, B, C, D);

    // the same segments the other way round permute the answer
    const SegmentIntersection swapped = intersect_segments(C, D, A, B);
    CHECK(swapped.relation == s.relation);
    REQUIRE(swapped.t_ab.has_value() == s.t_ab.has_value());
    if (s.t_ab) {
      CHECK(*swapped.t_ab == T::within(*s.t_cd, 16 * kEps, 1e-300));
      CHECK(*swapped.t_cd == T::within(*s.t_ab, 16 * kEps, 1e-300));
      const SegmentIntersection reversed = intersect_segments(B, A, C, D);
      CHECK(*reversed.t_ab == T::within(1 - *s.t_ab, 16 * kEps, 16 * kEps));
      CHECK(*reversed.t_cd == T::within(*s.t_cd, 16 * kEps, 1e-300));
    }

    // a power of two changes no bit; a general similarity only the data's rounding
    const double two = std::ldexp(1.0, static_cast<int>(rng.integer(-60, 60)));
    auto twice = [two](Point2 p) { return to_point(two * to_vec(p)); };
    const SegmentIntersection scaled = intersect_segments(twice(A), twice(B), twice(C), twice(D));
    CHECK(scaled.relation == s.relation);
    if (s.t_ab) {
      CHECK(exactly(*scaled.t_ab, *s.t_ab));
      CHECK(exactly(*scaled.t_cd, *s.t_cd));
    }
  }
}

TEST_CASE("geometry/segments: invariant under translating, rotating and scaling the figure") {
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    Rng rng(seed, 1);
    CAPTURE(seed);
    // well-conditioned figures: a clear angle, ends away from the other segment
    const Point2 A = T::point2(rng, 1), B = T::point2(rng, 1), C = T::point2(rng, 1),
                 D = T::point2(rng, 1);
    const Expected e = reference(A, B, C, D);
    if (T::abs(e.sine) < 0.05) continue;
    if (T::abs(e.t_ab) < 1e-6 || T::abs(e.t_ab - 1) < 1e-6 || T::abs(e.t_cd) < 1e-6 ||
        T::abs(e.t_cd - 1) < 1e-6)
      continue;
    const SegmentIntersection s = intersect_segments(A, B, C, D);
    const double angle = rng.uniform(-std::numbers::pi, std::numbers::pi),
                 k = T::decades(rng, -8, 8);
    const Vec2 shift = k * Vec2{rng.uniform(-100, 100), rng.uniform(-100, 100)};
    const double c = k * std::cos(angle), sn = k * std::sin(angle);
    auto move = [&](Point2 p) { return Point2{c * p.x - sn * p.y, sn * p.x + c * p.y} + shift; };
    const SegmentIntersection m = intersect_segments(move(A), move(B), move(C), move(D));
    CHECK(m.relation == s.relation);
    // rounding the moved data (ε of the shift, 100 times the figure) moves t by ~ε·100 / sine
    const double tolerance =
        1e-12 / d(T::abs(e.sine)) * (1 + std::abs(*s.t_ab) + std::abs(*s.t_cd));
    CHECK(*m.t_ab == T::within(*s.t_ab, tolerance, tolerance));
    CHECK(*m.t_cd == T::within(*s.t_cd, tolerance, tolerance));
    if (m.I) {
      const Point2 I = move(*s.I);
      CHECK(m.I->x == T::within(I.x, 1e-12, 1e-12 * k * 100));
      CHECK(m.I->y == T::within(I.y, 1e-12, 1e-12 * k * 100));
    }
  }
}

TEST_SUITE_END();

TEST_CASE("geometry/segments_exact: issue 15's lines, decided exactly") {
  SUBCASE("1. near the parallel cut-off: outside, t_ab = 1, t_cd = −1 (no snapping window)") {
    const SegmentIntersection s = intersect_segments_exact(Point2{0, 0}, Point2{1, 0}, Point2{2, 1e-14}, Point2{3, 2e-14});
    CHECK(s.relation == SegmentRelation::outside);
    CHECK(*s.t_ab == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(*s.t_cd == doctest::Approx(-1).epsilon(4 * kEps));
  }
  SUBCASE("2. I = D = (4.5, 5), on both segments") {
    const SegmentIntersection s =
        intersect_segments_exact(Point2{7, 5}, Point2{4, 5}, Point2{7.5, 4.999999999999943}, Point2{4.5, 5});
    CHECK(s.intersects());
    check_point(*s.I, {4.5, 5});
  }
  SUBCASE("3. 1e-14 off the line is not collinear: they meet at C") {
    const SegmentIntersection s = intersect_segments_exact(Point2{0, 0}, Point2{4, 0}, Point2{1, 0}, Point2{3, 1e-14});
    CHECK(s.intersects());
    CHECK(exactly(*s.t_cd, 0));
    check_point(*s.I, {1, 0});
  }
}

TEST_CASE("geometry/segments_exact: at 1, 2 and 3 ulps from a boundary, the relation is the exact one") {
  // On a binary grid (far from the origin or not): CD's end C on [AB] (at an end or inside),
  // or CD exactly parallel to AB, then one coordinate of C or D moved by k ulps. The exact
  // relation follows from the sign of the cross product that the move changes.
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const double unit = std::ldexp(1.0, static_cast<int>(rng.integer(-10, 4)));
    const double far = std::ldexp(1.0, static_cast<int>(rng.integer(0, 40)));
    auto grid = [&](double extent) { return unit * std::round(rng.uniform(-extent, extent)); };
    auto small = [&] { return unit * static_cast<double>(rng.integer(-16, 16)); };
    const Point2 A{grid(far), grid(far)};
    Vec2 AB{small(), small()};
    if (AB.y == 0) AB.y = unit;
    const Point2 B = A + AB;
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    auto nudge = [k](double x) {
      for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? INFINITY : -INFINITY);
      return x;
    };
    if (rng.chance(0.5)) {
      // C on [AB] at s ∈ {0, 1/2, 1}, D off the line; C.x moved by δ: AC∧AB = δ·AB_y
      const double at = static_cast<double>(rng.integer(0, 2)) / 2;
      const Point2 C0 = A + at * AB;
      Vec2 CD{small(), small()};
      if (cross(AB, CD) == 0) CD = perp(AB);
      if (C0.x == 0) continue;  // a zero moved by an ulp is subnormal: outside the contract
      const Point2 C{nudge(C0.x), C0.y}, D = C0 + CD;
      // the exact relation, in quadruple precision: exact here (grid data and ulp moves need
      // at most 107 bits per cross product)
      CAPTURE(A.x);
      CAPTURE(A.y);
      CAPTURE(B.x);
      CAPTURE(B.y);
      CAPTURE(C.x);
      CAPTURE(C.y);
      CAPTURE(D.x);
      CAPTURE(D.y);
      const Expected e = reference(A, B, C, D);
      const bool inside = e.t_ab >= 0 && e.t_ab <= 1 && e.t_cd >= 0 && e.t_cd <= 1;
      const SegmentIntersection s = intersect_segments_exact(A, B, C, D);
      CHECK(s.relation == (inside ? SegmentRelation::intersects : SegmentRelation::outside));
      if (k == 0) CHECK(exactly(*s.t_cd, 0));
      if (s.intersects()) {
        CHECK(*s.t_ab >= 0);
        CHECK(*s.t_ab <= 1);
      } else {
        CHECK((*s.t_ab < 0 || *s.t_ab > 1 || *s.t_cd < 0 || *s.t_cd > 1));
      }
    } else {
      // CD parallel to AB (or on its line), D.x moved by δ: AB∧CD = −AB_y·δ
      const bool same_line = rng.chance(0.5);
      const Point2 C = same_line ? A + static_cast<double>(rng.integer(-2, 3)) * AB
                                 : A + perp(AB) + static_cast<double>(rng.integer(-2, 3)) * AB;
      const Point2 D0 = C + static_cast<double>(rng.chance(0.5) ? 1 : -2) * AB;
      if (D0.x == 0) continue;
      const Point2 D{nudge(D0.x), D0.y};
      const SegmentIntersection s = intersect_segments_exact(A, B, C, D);
      if (k == 0)
        CHECK(s.relation == (same_line ? SegmentRelation::collinear : SegmentRelation::parallel));
      else
        CHECK((s.relation == SegmentRelation::outside || s.relation == SegmentRelation::intersects));
    }
  }
}
