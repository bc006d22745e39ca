// Pins printed_values (geometry/ray_circle.h, ray_3d.h; ray_ball.h): the t_proj, t and N that
// `epure solve` and the answer keys print for ray/circle and ray/sphere, each within 4 ulps of
// max(S, |·|) against an independent quadruple-precision reference (support/ball_reference.h),
// and the kernels' own bits wherever those are within it. Cases: the switch itself (a value at
// 1, 2 and 3 ulps either side of the 4-ulp boundary); lines either side of the a-priori bound
// (|t_proj| near S/2); random far origins, where the kernels' formula reaches 5 ulps (the test
// requires such lines among its draws, so that it fails if the comparison is removed); N on
// the same draws.
#include <doctest/doctest.h>

#include <cmath>
#include <array>
#include <tuple>
#include <utility>

#include "geometry/ray_3d.h"
#include "geometry/ray_ball.h"
#include "geometry/ray_circle.h"
#include "support/ball_reference.h"
#include "support/draw.h"
#include "support/exactly.h"
#include "support/real.h"

using namespace epure::geo;
using epure::Rng;
namespace T = epure::test;
using T::Real;

namespace {

std::array<Real, 2> parts(T::R2 v) { return {v.x, v.y}; }
std::array<Real, 3> parts(T::R3 v) { return {v.x, v.y, v.z}; }

double ulp_of(double x) { return std::nextafter(std::abs(x), INFINITY) - std::abs(x); }

// |got − expected| in ulps of max(S, |expected|), expected exact
double ulps_off(double got, Real expected, double S) {
  const double bound = ulp_of(std::max(S, std::abs(static_cast<double>(expected))));
  return static_cast<double>(T::abs(Real(got) - expected)) / bound;
}

template <class V, class P>
struct Printed {
  double t_proj, t;              // printed_values'
  double plain_t_proj, plain_t;  // the kernel's values times length, as printed before
  bool hit;
  V N, plain_N;
  P I, plain_I;
};

// As `epure solve` calls it: the direction rescaled by a power of two, its length by hypot.
template <class Ray, class Ball>
auto print(const Ray& ray, const Ball& ball) {
  const auto res = intersect_exact(ray, ball);
  const double length = norm(ray.direction);
  const auto along = printed_values(ray, ball, res, length);
  using V = decltype(ray.direction);
  using P = decltype(ray.origin);
  return Printed<V, P>{along.t_proj, along.t, res.t_proj * length, res.hit ? res.hit->t * length : 0.0,
                       res.hit.has_value(), along.N, res.hit ? res.hit->N : V{},
                       along.I, res.hit ? res.hit->I : P{}};
}

}  // namespace

TEST_CASE("geometry/printed_values: the switch at 4 ulps, from 1 to 3 ulps either side") {
  // a, an accurate value between two doubles; w that many ulps away from its nearest double
  for (const double a_hi : {0.75, 1.25, 1.5 - 0x1p-40, 3.0}) {
    for (const double fraction : {0.0, 0.25, -0.375}) {
      const double ulp = ulp_of(a_hi);
      const detail::DD a{a_hi, fraction * ulp};
      for (int k = -7; k <= 7; ++k) {
        if (k == 4 || k == -4) continue;  // on the boundary itself, a's fraction decides
        CAPTURE(a_hi);
        CAPTURE(fraction);
        CAPTURE(k);
        const double w = a_hi + k * ulp;
        const double S = 0.5;  // below |a|: the bound is 4 ulps of a
        const double got = detail::checked(w, a, 0x1p-60 * ulp, S);
        const Real off = T::abs(Real(w) - (Real(a.hi) + Real(a.lo)));
        const bool within = off <= 4 * Real(ulp);
        CHECK(T::exactly(got, within ? w : a_hi));
      }
    }
  }
}

TEST_CASE("geometry/printed_values: either side of the a-priori bound, within 4 ulps") {
  // A = (1, 0), C = O, r = 1/4, u = (−1, y): t_proj = 1/√(1 + y²), S = 1. The bound vouches for
  // |t_proj| ≤ 0.498… (its 8ε within 4 ulps of 1): lines at 1, 2, 3 ulps of t_proj either side.
  const double boundary = (4 - 0x1p-6) / 8;
  for (int k = -3; k <= 3; ++k) {
    CAPTURE(k);
    const double target = boundary + k * ulp_of(boundary);
    const double y = std::sqrt(1 / (target * target) - 1);
    const Ray2 ray{{1, 0}, rescaled(Vec2{-1, y})};
    const Circle circle{{0, 0}, 0.25};
    const auto p = print(ray, circle);
    const auto e = T::ball_reference(T::real(ray.origin), T::real(ray.direction), T::real(circle.C),
                                     Real(circle.r));
    CHECK(ulps_off(p.t_proj, e.t_proj, 1.0) <= 4);
  }
}

namespace {

// Lines from `draw`, e.g. A at up to 1e3 sizes from a figure of any size, aimed at it or
// anywhere, the direction of any slope. Returns how many of the kernel's values (t_proj, t, N),
// and how many of its hit points' coordinates, exceeded 4 ulps.
// The kernel's value is kept wherever the accurate one, less its own error bound (a few hundredths
// of an ulp from an origin inside), shows it within 4 ulps: below this it must be kept.
constexpr double kKept = 3.95;

template <class Draw>
std::pair<int, int> far_origins(Draw draw, int seeds) {
  int beyond = 0, points_beyond = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    CAPTURE(seed);
    Rng rng(static_cast<std::uint64_t>(seed), 15);
    const auto [ray, ball, S] = draw(rng);
    const auto p = print(ray, ball);
    const auto e = T::ball_reference(T::real(ray.origin), T::real(ray.direction), T::real(ball.C),
                                     Real(ball.r));
    const double plain = ulps_off(p.plain_t_proj, e.t_proj, S);
    CHECK(ulps_off(p.t_proj, e.t_proj, S) <= 4);
    // the kernel's bits are kept wherever they are (with a margin for the reference) within
    if (plain <= kKept) CHECK(T::exactly(p.t_proj, p.plain_t_proj));
    if (plain > 4) ++beyond;
    if (p.hit && e.t) {
      const double plain_t = ulps_off(p.plain_t, *e.t, S);
      CAPTURE(plain_t);
      CAPTURE(p.t);
      CAPTURE(p.plain_t);
      CAPTURE(static_cast<double>(*e.t));
      CAPTURE(static_cast<double>(e.t_proj));
      CAPTURE(static_cast<double>(e.half_chord));
      CAPTURE(e.inside);
      CAPTURE(S);
      CHECK(ulps_off(p.t, *e.t, S) <= 4);
      if (plain_t <= kKept) CHECK(T::exactly(p.t, p.plain_t));
      if (plain_t > 4) ++beyond;
      // N·r as a length: within 4 ulps of max(1, S/r)
      const double n_unit = std::max(ulp_of(1.0), ulp_of(S) / ball.r);
      const auto n = detail::parts(p.N), plain_n = detail::parts(p.plain_N);
      const auto ref = parts(e.N);
      for (std::size_t i = 0; i < n.size(); ++i) {
        const double off = static_cast<double>(T::abs(Real(n[i]) - ref[i])) / n_unit;
        const double plain_off = static_cast<double>(T::abs(Real(plain_n[i]) - ref[i])) / n_unit;
        CHECK(off <= 4);
        if (plain_off <= kKept) CHECK(T::exactly(n[i], plain_n[i]));
        if (plain_off > 4) ++beyond;
      }
      // I, a point: within 4 ulps of max(S, |I|)
      const auto I = detail::parts(p.I), plain_I = detail::parts(p.plain_I);
      const auto ref_I = parts(e.I);
      for (std::size_t i = 0; i < I.size(); ++i) {
        const double plain_off = ulps_off(plain_I[i], ref_I[i], S);
        CHECK(ulps_off(I[i], ref_I[i], S) <= 4);
        if (plain_off <= kKept) CHECK(T::exactly(I[i], plain_I[i]));
        if (plain_off > 4) ++points_beyond;
      }
    }
  }
  return {beyond, points_beyond};
}

// A ray from afar toward a ball (or a random direction), in 2D or 3D: the ball's size over six
// decades, its radius up to two decades smaller, the origin up to three decades away; with S,
// the figure's scale (its largest coordinate or radius).
template <class Ray, class Ball, class PointAt, class Direction>
auto far_origin(Rng& rng, PointAt point, Direction direction) {
  const double size = T::decades(rng, -3, 3);
  const auto C = point(rng, size);
  const double r = size * T::decades(rng, -2, 0);
  const auto A = point(rng, size * T::decades(rng, 0, 3));
  const auto toward = (C - A) + to_vec(point(rng, rng.chance(0.5) ? r : 3 * size));
  const auto u = rescaled(rng.chance(0.2) ? direction(rng) : toward);
  const double S = std::max({detail::max_abs(A), detail::max_abs(C), r});  // the kernels' own scale
  return std::tuple{Ray{A, u}, Ball{C, r}, S};
}

}  // namespace

TEST_CASE("geometry/printed_values: far origins, circle and sphere, within 4 ulps") {
  auto circle = [](Rng& rng) {
    return far_origin<Ray2, Circle>(rng, T::point2, T::direction2);
  };
  auto sphere = [](Rng& rng) {
    return far_origin<Ray3, Sphere>(rng, T::point3, T::direction3);
  };
  // Without the comparison these lines would fail: the draws must hold some beyond 4 ulps.
  CHECK(far_origins(circle, 100000).first > 0);
  CHECK(far_origins(sphere, 100000).first > 0);
}

// An origin in the ball's box (inside, or just outside), the direction of any length: I = A + t·û
// where t·û is a chord (up to 2r) and t itself is within 4 ulps of S, so the kernel's I can
// reach 5 ulps of S (the exact reference found `"A":[-420.24…,-845.40…],"u":[8218.69…,
// -3594.24…],"C":[0,0],"r":976.53…`: A inside, near the circle).
template <class Ray, class Ball, class PointAt, class Direction>
auto inside_origin(Rng& rng, PointAt point, Direction direction) {
  const double r = T::decades(rng, -3, 3);
  const auto C = point(rng, rng.chance(0.5) ? 0.0 : r * T::decades(rng, -1, 1));
  const auto A = C + to_vec(point(rng, r));
  const auto u = direction(rng) * T::decades(rng, -3, 3);
  const double S = std::max({detail::max_abs(A), detail::max_abs(C), r});
  return std::tuple{Ray{A, u}, Ball{C, r}, S};
}

TEST_CASE("geometry/printed_values: hit points from inside, circle and sphere, within 4 ulps") {
  auto circle = [](Rng& rng) { return inside_origin<Ray2, Circle>(rng, T::point2, T::direction2); };
  auto sphere = [](Rng& rng) { return inside_origin<Ray3, Sphere>(rng, T::point3, T::direction3); };
  // Without I's comparison these lines would fail: the draws must hold some I beyond 4 ulps.
  const auto [circle_values, circle_points] = far_origins(circle, 100000);
  const auto [sphere_values, sphere_points] = far_origins(sphere, 100000);
  MESSAGE("kernel values beyond 4 ulps: circle ", circle_values, " + ", circle_points, " I coordinates, sphere ",
          sphere_values, " + ", sphere_points);
  CHECK(circle_points + sphere_points > 0);
}
