// Pins geometry/ray_circle.h, exercise 3 of the course: ray/circle by projection and Pythagoras.
// The contract's worked examples; every branch in numbered cases: zero direction ("u"), r ≤ 0
// ("r"), behind tested before miss, tangent (a hit), start on the circle heading in (t = 0,
// I = A) or out (behind), start inside (the exit point, whichever way the ray points), the
// canonical circle, 1e-200 to 1e200 figures, a unit circle seen from 1e8, directions of any
// length. Property tests against an independent quadruple-precision quadratic (support/
// ball_reference.h), both as `epure solve` calls it (Ray2::unit) and with the direction as given
// (t then in units of it): the branch, t_proj, d², t, I, N; I on the circle, N unit and
// outward, t = |AI|; a ray from outside through the centre hits at |AC| − r; the answer moves
// with the figure when it is translated, rotated and scaled. Tolerances are stated where used,
// in units of ε and of the figure's conditioning (r/h grows as the ray nears tangency).
#include "geometry/ray_circle.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "geometry/degenerate.h"
#include "geometry/tolerance.h"
#include "support/approx.h"
#include "support/ball_reference.h"
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

void check_point(Point2 got, double x, double y, double tolerance) {
  CHECK(got.x == T::within(x, tolerance, tolerance));
  CHECK(got.y == T::within(y, tolerance, tolerance));
}
void check_vec(Vec2 got, double x, double y, double tolerance) {
  CHECK(got.x == T::within(x, tolerance, tolerance));
  CHECK(got.y == T::within(y, tolerance, tolerance));
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

// A figure and how it was drawn, for the property tests.
struct Figure {
  Point2 A;
  Vec2 u;
  Circle circle;
};

// Random figures of every kind: A anywhere, inside, far away and aimed, nearly tangent (hit or
// miss by a relative 1e-13 to 1e-3), through the centre; sizes from 1e-8 to 1e8; directions of
// any length.
Figure draw_figure(Rng& rng, int kind) {
  const double size = T::decades(rng, -8, 8);
  const Point2 C = T::point2(rng, size);
  const double r = size * T::decades(rng, -2, 0.5);
  const Vec2 along = *normalized(T::direction2(rng));
  const double length = T::decades(rng, -3, 3);
  switch (kind) {
    case 0:  // anywhere around
      return {T::point2(rng, 4 * size), T::direction2(rng), {C, r}};
    case 1: {  // inside, any direction
      const Vec2 at = rng.uniform(0, 0.999) * r * *normalized(T::direction2(rng));
      return {C + at, T::direction2(rng), {C, r}};
    }
    case 2: {  // far away (up to 1e6 radii), aimed at the circle, hitting it
      const double distance = r * T::decades(rng, 0.5, 6), offset = rng.uniform(-0.99, 0.99) * r;
      return {C - distance * along + offset * perp(along), length * along, {C, r}};
    }
    case 3: {  // nearly tangent, either side of tangency
      const double distance = r * T::decades(rng, -1, 4) * T::sign(rng);
      const double offset = r * (1 + T::decades(rng, -13, -3) * T::sign(rng)) * T::sign(rng);
      return {C - distance * along + offset * perp(along), length * along, {C, r}};
    }
    default: {  // from outside, through the centre
      const double distance = r * (1 + T::decades(rng, -3, 4));
      return {C - distance * along, length * along, {C, r}};
    }
  }
}

// Within the data's rounding of a branch boundary (on the circle, perpendicular, tangent) the
// reference and the tolerance policy may disagree by design: those figures are pinned case by
// case instead.
bool ambiguous(const T::BallExpected<T::R2>& e, Real r) {
  const Real band = 256 * kEps * T::max(r, e.ac);
  if (T::abs(e.ac - r) < band) return true;
  if (!e.inside && T::abs(e.t_proj) < band) return true;
  return T::abs(T::sqrt(e.d2) - r) < band;
}

// The whole answer against the reference. `unit_ray` is how `epure solve` calls it: the
// direction is first rounded to a unit vector, which turns the line by up to ε about A and so
// moves it by ε·|AC| at the circle; the direction as given leaves only the arithmetic's
// rounding. t is compared in lengths either way.
void check_against_reference(const Figure& f, bool unit_ray) {
  const Ray2 ray = unit_ray ? Ray2::unit(f.A, f.u) : Ray2{f.A, f.u};
  const double length_u = unit_ray ? 1.0 : norm(f.u);
  const RayCircle got = intersect(ray, f.circle);
  const auto e =
      T::ball_reference(T::real(f.A), T::real(f.u), T::real(f.circle.C), Real(f.circle.r));
  const double r = f.circle.r, ac = d(e.ac);
  CAPTURE(unit_ray);
  CAPTURE(d(e.t_proj));
  CAPTURE(d(e.d2));
  CAPTURE(got.t_proj * length_u);
  CAPTURE(got.d2);
  // the line's position is known to `wobble`: ε of |AC| when the direction was rounded
  const double wobble = unit_ray ? ac : r;
  CHECK(got.inside == e.inside);
  CHECK(got.t_proj * length_u == T::within(d(e.t_proj), 8 * kEps, 8 * kEps * wobble));
  CHECK(got.d2 ==
        T::within(d(e.d2), 8 * kEps, 8 * kEps * wobble * (std::sqrt(d(e.d2)) + kEps * wobble)));
  if (e.behind) {
    CHECK(got.reason == NoHit::behind);
    CHECK_FALSE(got.hit.has_value());
    return;
  }
  if (e.miss) {
    CHECK(got.reason == NoHit::miss);
    CHECK_FALSE(got.hit.has_value());
    return;
  }
  REQUIRE(got.hit.has_value());
  CHECK_FALSE(got.reason.has_value());
  const Hit2& hit = *got.hit;
  const double h = d(e.half_chord);
  // near tangency the hit point slides along the circle by r/h times the line's error
  const double slide = 16 * kEps * wobble * (1 + r / h);
  CHECK(*got.half_chord == T::within(h, 16 * kEps, slide));
  CHECK(hit.t * length_u == T::within(d(*e.t), 16 * kEps, slide + 16 * kEps * (unit_ray ? ac : 0)));
  // I is computed from A or from C, whichever is smaller beside the figure
  const double I_size = std::min(std::max(std::abs(f.A.x), std::abs(f.A.y)) + d(*e.t),
                                 std::max(std::abs(f.circle.C.x), std::abs(f.circle.C.y)) + r);
  const double I_tolerance = 16 * kEps * I_size + slide;
  CHECK(hit.I.x == T::within(d(e.I.x), 0, I_tolerance));
  CHECK(hit.I.y == T::within(d(e.I.y), 0, I_tolerance));
  CHECK(hit.N.x == T::within(d(e.N.x), 0, slide / r + 16 * kEps));
  CHECK(hit.N.y == T::within(d(e.N.y), 0, slide / r + 16 * kEps));
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/ray_circle: the contract's worked examples") {
  SUBCASE("1. straight at the centre from the left") {
    const RayCircle c = intersect(Ray2::unit({-5, 0}, {1, 0}), {{0, 0}, 3});
    CHECK(exactly(c.t_proj, 5));
    CHECK(exactly(c.d2, 0));
    CHECK_FALSE(c.inside);
    REQUIRE(c.hit.has_value());
    CHECK(exactly(c.hit->t, 2));
    check_point(c.hit->I, -3, 0, 0);
    check_vec(c.hit->N, -1, 0, 0);
    CHECK(exactly(*c.half_chord, 3));
    CHECK_FALSE(c.reason.has_value());
  }
  SUBCASE("2. off-centre, direction of length 2: t = 5 − 2√2") {
    const RayCircle c = intersect(Ray2::unit({-5, 1}, {2, 0}), {{0, 0}, 3});
    CHECK(exactly(c.t_proj, 5));
    CHECK(exactly(c.d2, 1));
    REQUIRE(c.hit.has_value());
    CHECK(c.hit->t == doctest::Approx(2.1715728752538097).epsilon(2 * kEps));
    check_point(c.hit->I, -2.8284271247461903, 1.0, 2 * kEps);
    check_vec(c.hit->N, -0.9428090415820634, 0.3333333333333333, 2 * kEps);
  }
  SUBCASE("3. pointing away: behind") {
    const RayCircle c = intersect(Ray2::unit({-5, 0}, {-1, 0}), {{0, 0}, 3});
    CHECK(exactly(c.t_proj, -5));
    CHECK(exactly(c.d2, 0));
    CHECK(c.reason == NoHit::behind);
    CHECK_FALSE(c.hit.has_value());
    CHECK_FALSE(c.half_chord.has_value());
    CHECK(std::string(to_string(NoHit::behind)) == "behind");
  }
  SUBCASE("4. passing by: miss") {
    const RayCircle c = intersect(Ray2::unit({-5, 4}, {1, 0}), {{0, 0}, 3});
    CHECK(exactly(c.t_proj, 5));
    CHECK(exactly(c.d2, 16));
    CHECK(c.reason == NoHit::miss);
    CHECK_FALSE(c.hit.has_value());
    CHECK(std::string(to_string(NoHit::miss)) == "miss");
  }
  SUBCASE("5. from inside: the exit point (the course's code would say miss)") {
    const RayCircle c = intersect(Ray2::unit({1, 0}, {1, 0}), {{0, 0}, 3});
    CHECK(exactly(c.t_proj, -1));
    CHECK(c.inside);
    REQUIRE(c.hit.has_value());
    CHECK(exactly(c.hit->t, 2));
    check_point(c.hit->I, 3, 0, 0);
    check_vec(c.hit->N, 1, 0, 0);
  }
  SUBCASE("6. from the circle, heading in: a hit at t = 0, I = A") {
    const RayCircle c = intersect(Ray2::unit({-3, 0}, {1, 0}), {{0, 0}, 3});
    CHECK_FALSE(c.inside);
    REQUIRE(c.hit.has_value());
    CHECK(exactly(c.hit->t, 0));
    check_point(c.hit->I, -3, 0, 0);
    check_vec(c.hit->N, -1, 0, 0);
  }
}

TEST_CASE("geometry/ray_circle: every branch") {
  const Circle circle{{1, 2}, 5};
  SUBCASE("1. zero direction: field u") {
    check_refused([&] { intersect(Ray2{{0, 0}, {0, 0}}, circle); }, "u");
    check_refused([&] { Ray2::unit({0, 0}, {0, -0.0}); }, "u");
    check_refused(
        [&] {
          intersect(Ray2{{0, 0}, {std::numeric_limits<double>::infinity(), 0}}, circle);
        },
        "u");
  }
  SUBCASE("2. r ≤ 0 or not finite: field r") {
    for (double r : {0.0, -0.0, -1.0, std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN()}) {
      CAPTURE(r);
      check_refused([&] { intersect(Ray2::unit({0, 0}, {1, 0}), Circle{{0, 0}, r}); }, "r");
    }
    // r is checked before u
    check_refused([&] { intersect(Ray2{{0, 0}, {0, 0}}, Circle{{0, 0}, -1}); }, "r");
  }
  SUBCASE("3. behind is tested before miss: away from the circle and wide of it") {
    const RayCircle c = intersect(Ray2::unit({-10, 8}, {-1, 0}), {{0, 0}, 3});
    CHECK(c.reason == NoHit::behind);
    CHECK(exactly(c.d2, 64));
  }
  SUBCASE("4. tangent from outside: a hit at P, half chord 0") {
    const RayCircle c = intersect(Ray2::unit({-5, 3}, {1, 0}), {{0, 0}, 3});
    REQUIRE(c.hit.has_value());
    CHECK(exactly(c.hit->t, 5));
    check_point(c.hit->I, 0, 3, 0);
    check_vec(c.hit->N, 0, 1, 0);
    CHECK(exactly(*c.half_chord, 0));
    CHECK(exactly(c.d2, 9));
    // tangent in a slanted direction: the 3-4-5 triangle around C = (1, 2), r = 5
    const RayCircle s = intersect(Ray2::unit({1 + 4 + 3 * 2, 2 - 3 + 4 * 2}, {-3, -4}), circle);
    REQUIRE(s.hit.has_value());
    CHECK(s.hit->t == doctest::Approx(10).epsilon(4 * kEps));
    check_point(s.hit->I, 5, -1, 8 * kEps);
    check_vec(s.hit->N, 0.8, -0.6, 4 * kEps);
  }
  SUBCASE("5. just wide of tangency (1e-9 r): miss; just inside: a hit with h = r·√(2e-9)") {
    const RayCircle miss = intersect(Ray2::unit({-5, 3 * (1 + 1e-9)}, {1, 0}), {{0, 0}, 3});
    CHECK(miss.reason == NoHit::miss);
    const RayCircle hit = intersect(Ray2::unit({-5, 3 * (1 - 1e-9)}, {1, 0}), {{0, 0}, 3});
    REQUIRE(hit.hit.has_value());
    const double y = 3 * (1 - 1e-9);
    CHECK(*hit.half_chord == doctest::Approx(std::sqrt((3 - y) * (3 + y))).epsilon(1e-7));
    CHECK(hit.hit->t == doctest::Approx(5 - std::sqrt((3 - y) * (3 + y))).epsilon(1e-15));
  }
  SUBCASE("6. from the circle: in at t = 0, out is behind, along the tangent a hit at t = 0") {
    const Point2 on{1 + 3, 2 + 4};  // on the circle
    const RayCircle in = intersect(Ray2::unit(on, {-1, -1}), circle);
    CHECK_FALSE(in.inside);
    REQUIRE(in.hit.has_value());
    CHECK(exactly(in.hit->t, 0));
    check_point(in.hit->I, on.x, on.y, 0);
    check_vec(in.hit->N, 0.6, 0.8, 2 * kEps);
    const RayCircle out = intersect(Ray2::unit(on, {1, 0}), circle);
    CHECK(out.reason == NoHit::behind);
    const RayCircle tangent = intersect(Ray2::unit(on, {-4, 3}), circle);
    REQUIRE(tangent.hit.has_value());
    CHECK(exactly(tangent.hit->t, 0));
    check_vec(tangent.hit->N, 0.6, 0.8, 2 * kEps);
    // and a start off by one ulp is still "on the circle" (the data's rounding)
    const RayCircle ulp = intersect(Ray2::unit({std::nextafter(4.0, 5.0), 6}, {1, 0}), circle);
    CHECK_FALSE(ulp.inside);
    CHECK(ulp.reason == NoHit::behind);
  }
  SUBCASE("7. from inside, every way: the exit point, N = (I − C)/r") {
    for (Vec2 u : {Vec2{1, 0}, Vec2{-1, 0}, Vec2{0, 1}, Vec2{3, -4}, Vec2{-1e-3, 2e-3}}) {
      CAPTURE(u.x);
      CAPTURE(u.y);
      const RayCircle c = intersect(Ray2::unit({2, 2}, u), circle);
      CHECK(c.inside);
      REQUIRE(c.hit.has_value());
      const Vec2 radial = c.hit->I - circle.C;
      CHECK(norm(radial) == doctest::Approx(5).epsilon(4 * kEps));
      check_vec(c.hit->N, radial.x / 5, radial.y / 5, 4 * kEps);
      CHECK(c.hit->t > 0);
    }
    // from the centre: t = r along any direction
    const RayCircle centre = intersect(Ray2::unit({1, 2}, {-2, 7}), circle);
    CHECK(centre.hit->t == doctest::Approx(5).epsilon(2 * kEps));
    CHECK(exactly(centre.d2, 0));
  }
  SUBCASE("8. the canonical circle is the unit circle at the origin") {
    const Ray2 ray = Ray2::unit({-3, 0.5}, {1, 0.1});
    const RayCircle a = intersect_canonical_circle(ray), b = intersect(ray, {{0, 0}, 1});
    REQUIRE(a.hit.has_value());
    CHECK(exactly(a.hit->t, b.hit->t));
    CHECK(exactly(a.hit->I.x, b.hit->I.x));
    CHECK(a.hit->N.x * a.hit->N.x + a.hit->N.y * a.hit->N.y ==
          doctest::Approx(1).epsilon(4 * kEps));
  }
  SUBCASE("9. the first example at every scale, 1e-200 to 1e200") {
    for (double k : {1e-200, 1e-8, 1e8, 1e200}) {
      CAPTURE(k);
      const RayCircle c = intersect(Ray2::unit({-5 * k, 1 * k}, {2, 0}), {{0, 0}, 3 * k});
      REQUIRE(c.hit.has_value());
      CHECK(c.hit->t == doctest::Approx(2.1715728752538097 * k).epsilon(4 * kEps));
      CHECK(c.t_proj == doctest::Approx(5 * k).epsilon(2 * kEps));
      check_vec(c.hit->N, -0.9428090415820634, 0.3333333333333333, 4 * kEps);
      CHECK(c.hit->I.x == doctest::Approx(-2.8284271247461903 * k).epsilon(4 * kEps));
    }
  }
  SUBCASE("10. a unit circle seen from 1e8: the hit point to the last digits") {
    const RayCircle c = intersect(Ray2::unit({1e8, 0.6}, {-1, 0}), {{0, 0}, 1});
    REQUIRE(c.hit.has_value());
    check_point(c.hit->I, 0.8, 0.6, 2 * kEps);
    check_vec(c.hit->N, 0.8, 0.6, 2 * kEps);
    CHECK(c.hit->t == doctest::Approx(1e8 - 0.8).epsilon(kEps));
    // aimed from a slant with the direction as given: the line is exact, so is I
    const Point2 A{3e7, -4e7};
    const Vec2 u =
        Point2{0.6, 0.8} - A;  // exact: (−29999999.4, 40000000.8) rounds, the line is what it is
    const RayCircle s = intersect(Ray2{A, u}, {{0, 0}, 1});
    const auto e = T::ball_reference(T::real(A), T::real(u), T::R2{0, 0}, Real(1));
    REQUIRE(s.hit.has_value());
    check_point(s.hit->I, d(e.I.x), d(e.I.y), 4 * kEps);
    check_vec(s.hit->N, d(e.N.x), d(e.N.y), 4 * kEps);
  }
  SUBCASE("11. directions far from unit length: t in units of the direction") {
    // (a subnormal direction would put t beyond the largest double: 1e-300 is the least)
    for (double k : {1e-300, 1e-8, 1e8, 1e300}) {
      CAPTURE(k);
      const RayCircle c = intersect(Ray2{{-5, 1}, {2 * k, 0}}, {{0, 0}, 3});
      REQUIRE(c.hit.has_value());
      CHECK(c.hit->t * 2 * k == doctest::Approx(2.1715728752538097).epsilon(4 * kEps));
      CHECK(c.t_proj * 2 * k == doctest::Approx(5).epsilon(2 * kEps));
      CHECK(c.hit->I.x == doctest::Approx(-2.8284271247461903).epsilon(4 * kEps));
      CHECK(exactly(c.d2, 1));
      // and normalised first, as `epure solve` does: t is a length
      const RayCircle n = intersect(Ray2::unit({-5, 1}, {2 * k, 0}), {{0, 0}, 3});
      CHECK(n.hit->t == doctest::Approx(2.1715728752538097).epsilon(4 * kEps));
    }
    const RayCircle sub = intersect(Ray2::unit({-5, 1}, {5e-324, 0}), {{0, 0}, 3});
    CHECK(sub.hit->t == doctest::Approx(2.1715728752538097).epsilon(4 * kEps));
  }
  SUBCASE("12. exact tangents whose direction was rounded to unit length stay tangent") {
    // (3,4)/5 is not a double: d is 5 to rounding only, and √(r² − d²) would be ~1e-7
    const RayCircle c = intersect(Ray2::unit({-8, -19}, {3, 4}), {{0, 0}, 5});
    REQUIRE(c.hit.has_value());
    CHECK(exactly(*c.half_chord, 0));
    CHECK(c.hit->t == doctest::Approx(20).epsilon(4 * kEps));
    check_point(c.hit->I, 4, -3, 4 * kEps);
    check_vec(c.hit->N, 0.8, -0.6, 4 * kEps);
    // and from the circle itself, along the tangent: t = 0 with the normal at A
    const RayCircle on =
        intersect(Ray2::unit({3 * 0x1p26, 4 * 0x1p26}, {4, -3}), {{0, 0}, 5 * 0x1p26});
    REQUIRE(on.hit.has_value());
    CHECK(exactly(on.hit->t, 0));
    check_vec(on.hit->N, 0.6, 0.8, 4 * kEps);
    // with the direction as given, the tangent is exact data: t_proj is exactly 0
    const RayCircle raw = intersect(Ray2{{3 * 0x1p26, 4 * 0x1p26}, {4, -3}}, {{0, 0}, 5 * 0x1p26});
    CHECK(exactly(raw.t_proj, 0));
  }
  SUBCASE("13. the construction data of a hit: P, AC, t_proj ± h") {
    const RayCircle c = intersect(Ray2::unit({-5, 1}, {1, 0}), {{0, 0}, 3});
    check_point(c.P, 0, 1, 0);
    check_vec(c.AC, 5, -1, 0);
    CHECK(c.hit->t == doctest::Approx(c.t_proj - *c.half_chord).epsilon(2 * kEps));
  }
}

TEST_CASE("geometry/ray_circle: random figures against quadruple precision") {
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 5000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Figure f = draw_figure(rng, static_cast<int>(seed % 5));
    CAPTURE(f.A.x);
    CAPTURE(f.A.y);
    CAPTURE(f.u.x);
    CAPTURE(f.u.y);
    CAPTURE(f.circle.C.x);
    CAPTURE(f.circle.C.y);
    CAPTURE(f.circle.r);
    const auto e =
        T::ball_reference(T::real(f.A), T::real(f.u), T::real(f.circle.C), Real(f.circle.r));
    if (ambiguous(e, f.circle.r)) continue;
    ++compared;
    check_against_reference(f, true);
    check_against_reference(f, false);
  }
  CHECK(compared > 4500);
}

TEST_CASE("geometry/ray_circle: the hit lies on the circle, N is unit and outward, t = |AI|") {
  for (std::uint64_t seed = 0; seed < 5000; ++seed) {
    Rng rng(seed, 1);
    CAPTURE(seed);
    const Figure f = draw_figure(rng, static_cast<int>(seed % 5));
    const RayCircle c = intersect(Ray2::unit(f.A, f.u), f.circle);
    if (!c.hit) continue;
    const Hit2& hit = *c.hit;
    const double r = f.circle.r, ac = norm(f.circle.C - f.A);
    const T::R2 CI = T::real(hit.I) - T::real(f.circle.C);
    const double size = std::min(std::max(std::abs(f.A.x), std::abs(f.A.y)) + hit.t,
                                 std::max(std::abs(f.circle.C.x), std::abs(f.circle.C.y)) + r);
    // on the circle to the rounding of I, or within the tangency tolerance (a line that misses
    // by less than the data's rounding touches at P, the foot of the perpendicular)
    CHECK(d(T::norm(CI)) == T::within(r, 0, 16 * kEps * (size + r) + kRoundoff * std::max(r, ac)));
    CHECK(norm(hit.N) == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(d(T::dot(T::real(hit.N), CI)) > 0);
    CHECK(hit.t >= 0);
    CHECK(norm(hit.I - f.A) == T::within(hit.t, 16 * kEps, 16 * kEps * (size + ac)));
    // t_proj ∓ h: the entry from outside, the exit from inside
    CHECK(hit.t == T::within(c.t_proj + (c.inside ? 1 : -1) * *c.half_chord, 16 * kEps,
                             16 * kEps * (ac + r)));
  }
}

TEST_CASE("geometry/ray_circle: from outside through the centre, the hit is at |AC| − r") {
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed, 2);
    CAPTURE(seed);
    const double size = T::decades(rng, -8, 8);
    const Point2 C = T::point2(rng, size), A = T::point2(rng, 4 * size);
    const double ac = norm(C - A);
    const double r = ac * rng.uniform(0.001, 0.999);
    const RayCircle c = intersect(Ray2::unit(A, T::decades(rng, -3, 3) * (C - A)), {C, r});
    REQUIRE(c.hit.has_value());
    CHECK(c.hit->t == T::within(ac - r, 8 * kEps, 8 * kEps * ac));
    CHECK(c.d2 == T::within(0, 0, 16 * kEps * ac * ac * kEps));
    // N points back at A
    const Vec2 back = *normalized(A - C);
    CHECK(c.hit->N.x == T::within(back.x, 0, 8 * kEps * ac / r));
    CHECK(c.hit->N.y == T::within(back.y, 0, 8 * kEps * ac / r));
  }
}

TEST_CASE(
    "geometry/ray_circle: translating, rotating and scaling the figure moves the answer with it") {
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed, 3);
    CAPTURE(seed);
    const Figure f = draw_figure(rng, static_cast<int>(seed % 5));
    const auto e =
        T::ball_reference(T::real(f.A), T::real(f.u), T::real(f.circle.C), Real(f.circle.r));
    const double r = f.circle.r, ac = d(e.ac);
    const double angle = rng.uniform(-std::numbers::pi, std::numbers::pi),
                 k = T::decades(rng, -4, 4);
    const double c = std::cos(angle), s = std::sin(angle);
    const double figure = std::max({norm(to_vec(f.A)), norm(to_vec(f.circle.C)), r});
    const Vec2 shift =
        k * figure * T::decades(rng, -3, 2) * Vec2{rng.uniform(-1, 1), rng.uniform(-1, 1)};
    // rounding the moved data moves the figure by ε of its coordinates: far below this margin
    // from every branch boundary, the branch cannot switch
    const double world = figure + norm(shift) / k + ac + r;
    if (d(T::abs(e.ac - Real(r))) < 1e-9 * world ||
        std::abs(std::sqrt(d(e.d2)) - r) < 1e-9 * world ||
        (!e.inside && std::abs(d(e.t_proj)) < 1e-9 * world))
      continue;
    const RayCircle before = intersect(Ray2::unit(f.A, f.u), f.circle);
    auto turn = [&](Vec2 v) { return Vec2{c * v.x - s * v.y, s * v.x + c * v.y}; };
    auto move = [&](Point2 p) { return to_point(k * turn(to_vec(p))) + shift; };
    const RayCircle after =
        intersect(Ray2::unit(move(f.A), turn(f.u)), Circle{move(f.circle.C), k * r});
    CHECK(after.inside == before.inside);
    CHECK(after.reason == before.reason);
    REQUIRE(after.hit.has_value() == before.hit.has_value());
    if (!before.hit) continue;
    const double h = *before.half_chord;
    const double tolerance = 64 * kEps * world * (1 + r / h);
    CHECK(after.hit->t == T::within(k * before.hit->t, 0, k * tolerance));
    const Vec2 N = turn(before.hit->N);
    CHECK(after.hit->N.x == T::within(N.x, 0, tolerance / r));
    CHECK(after.hit->N.y == T::within(N.y, 0, tolerance / r));
    const Point2 I = move(before.hit->I);
    CHECK(after.hit->I.x == T::within(I.x, 0, k * tolerance + 8 * kEps * std::abs(I.x)));
    CHECK(after.hit->I.y == T::within(I.y, 0, k * tolerance + 8 * kEps * std::abs(I.y)));
  }
}

TEST_SUITE_END();

TEST_CASE("geometry/ray_circle_exact: issue 15's lines, decided exactly") {
  SUBCASE("0. an exact tangent is tangent with its direction as given; rounded, as it lies") {
    const RayCircle c = intersect_exact(Ray2{{-8, -19}, {3, 4}}, {{0, 0}, 5});
    REQUIRE(c.hit.has_value());
    CHECK(exactly(*c.half_chord, 0));
    CHECK(c.hit->t * 5 == doctest::Approx(20).epsilon(4 * kEps));
    check_point(c.hit->I, 4, -3, 4 * kEps);
    check_vec(c.hit->N, 0.8, -0.6, 4 * kEps);
    // (3,4)/5 is not a double: rounded to unit length the line is no longer tangent, and it is
    // decided as it lies: a miss, or a chord of its true half length (~1e-7)
    const RayCircle rounded = intersect_exact(Ray2::unit({-8, -19}, {3, 4}), {{0, 0}, 5});
    if (rounded.hit) {
      CHECK(rounded.hit->t == doctest::Approx(20).epsilon(1e-6));
      CHECK(*rounded.half_chord > 0);
      CHECK(*rounded.half_chord < 1e-6);
    } else {
      CHECK(rounded.reason == NoHit::miss);
    }
  }
  SUBCASE("1. 1e-15 from tangency: the true chord, not a tangent; or a miss") {
    const RayCircle c = intersect_exact(Ray2{{-5, 1}, {1, 0}}, {{0, 0}, 1.000000000000001});
    REQUIRE(c.hit.has_value());
    CHECK(c.hit->t == doctest::Approx(4.999999952878391).epsilon(4 * kEps));
    const RayCircle m = intersect_exact(Ray2{{-5, 1}, {1, 0}}, {{0, 0}, 0.999999999999999});
    CHECK(m.reason == NoHit::miss);
  }
  SUBCASE("2. A inside by an ulp is inside") {
    const RayCircle c = intersect_exact(Ray2{{0, 2.9999999999999996}, {1, 0}}, {{0, 0}, 3});
    CHECK(c.inside);
  }
  SUBCASE("3. t_proj of a hit from outside is never negative") {
    const RayCircle c = intersect_exact(Ray2{{3, -6}, {-8.470329472543003e-22, 1.9073486328125e-06}},
                                  {{5, -6}, 2});
    CHECK((c.reason == NoHit::behind) == (c.t_proj < 0));
  }
  SUBCASE("4. at t = 0, N = (A − C)/r to the last digits") {
    const RayCircle c = intersect_exact(Ray2{{-15, -13}, {-1.4305114518720075e-05, 7.62939453125e-06}},
                                  {{-7, 2}, 17});
    REQUIRE(c.hit.has_value());
    CHECK(exactly(c.hit->t, 0));
    check_vec(c.hit->N, -8.0 / 17, -15.0 / 17, 2 * kEps);
  }
}

TEST_CASE("geometry/ray_circle_exact: at 1, 2 and 3 ulps from a boundary, the branch is the exact one") {
  // A Pythagorean point P of a circle on a binary grid (far from the origin or not): A = P moved
  // by k ulps of r (inside when r grew), or a tangent line through P with r moved by k ulps (a
  // chord when r grew, a miss when it shrank), or A outside with u ⊥ AC (t_proj = 0) moved.
  static constexpr double kTriples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {20, 21, 29}};
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const auto& tr = kTriples[rng.integer(0, 3)];
    const double unit = std::ldexp(1.0, static_cast<int>(rng.integer(-8, 4)));
    const double far = std::ldexp(1.0, static_cast<int>(rng.integer(0, 30)));
    const Point2 C{unit * std::round(rng.uniform(-far, far)), unit * std::round(rng.uniform(-far, far))};
    const Vec2 CP{unit * tr[0] * T::sign(rng), unit * tr[1] * T::sign(rng)};
    const double R = unit * tr[2];
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    double r = R;
    for (int i = 0; i < std::abs(k); ++i) r = std::nextafter(r, k > 0 ? INFINITY : -INFINITY);
    const Vec2 tangent = T::sign(rng) * perp(CP);
    const Vec2 scale_u = std::ldexp(1.0, static_cast<int>(rng.integer(-20, 20))) * tangent;
    switch (seed % 3) {
      case 0: {  // A on the circle of radius R, heading in: inside / hit at 0 / hit from outside
        const RayCircle c = intersect_exact(Ray2{C + CP, -1.0 * CP}, {C, r});
        CHECK(c.inside == (k > 0));
        REQUIRE(c.hit.has_value());
        if (k == 0) CHECK(exactly(c.hit->t, 0));
        else CHECK(c.hit->t > 0);
        break;
      }
      case 1: {  // tangent at P, from a few steps back along it
        const double back = static_cast<double>(rng.integer(1, 1024));
        const RayCircle c = intersect_exact(Ray2{C + CP - back * tangent, scale_u}, {C, r});
        CHECK(c.hit.has_value() == (k >= 0));
        if (k == 0) CHECK(exactly(*c.half_chord, 0));
        if (k > 0) CHECK(*c.half_chord > 0);
        if (k < 0) CHECK(c.reason == NoHit::miss);
        break;
      }
      default: {  // from 2·CP, u ⊥ AC moved by k ulps in one coordinate: behind or not
        Vec2 u = scale_u;
        const double u0 = u.x;
        for (int i = 0; i < std::abs(k); ++i) u.x = std::nextafter(u.x, k > 0 ? INFINITY : -INFINITY);
        const Vec2 AC = -2.0 * CP;
        const double toward = (u.x - u0) * AC.x;  // u·AC: exact by construction (sign)
        const RayCircle c = intersect_exact(Ray2{C + 2.0 * CP, u}, {C, R});
        CHECK((c.reason == NoHit::behind) == (toward < 0));
        CHECK((c.t_proj < 0) == (toward < 0));
        if (toward >= 0) CHECK(c.reason == NoHit::miss);
      }
    }
  }
}
