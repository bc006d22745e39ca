// Pins geometry/ray_transformed.h: ray/ellipse and ray/rectangle as the canonical circle and
// square under T = translate(C) ∘ rotate(angle) ∘ scale. The contract's worked examples; in
// numbered cases: radii / half-sizes ≤ 0 ("radii" / "half"), a non-finite angle ("angle"), a
// zero direction ("u"); a round ellipse is a circle and a unit rectangle the square; quarter
// turns (a 90° ellipse is the 0° one with its radii swapped), 45°, 30°, any angle reduced;
// start inside (the exit), on the boundary heading in (t = 0, I = A) or out (no hit), tangent,
// corners and grazing sides; 1e-200 to 1e200. Property tests against independent quadruple-
// precision references: the implicit quadratic of the ellipse, the slab method for the
// rectangle. Each comparison allows what the figure itself allows: the reference is evaluated
// again with every datum moved by ε (A, u's direction, C, the radii, the angle), and the answer
// may differ from the reference by a small multiple of how far those moved it. Figures whose
// branch changes under such a nudge are within rounding of a boundary and left to the
// numbered cases. Also: I on the figure, N unit and outward (for the rectangle the rotated axis
// normal of the side hit), t = |AI|, and the transform's frame: T⁻¹ carries the ray to the
// canonical one, t naming the same point in both.
#include "geometry/ray_transformed.h"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "geometry/degenerate.h"
#include "support/approx.h"
#include "support/box_reference.h"
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

template <class F>
void check_refused(F&& call, const std::string& field) {
  try {
    call();
    FAIL("no exception");
  } catch (const DegenerateFigure& e) {
    CHECK(e.field() == field);
  }
}

void check_hit(const std::optional<Hit2>& hit, double t, Point2 I, Vec2 N, double tolerance) {
  REQUIRE(hit.has_value());
  CHECK(hit->t == T::within(t, tolerance, tolerance));
  CHECK(hit->I.x == T::within(I.x, tolerance, tolerance));
  CHECK(hit->I.y == T::within(I.y, tolerance, tolerance));
  CHECK(hit->N.x == T::within(N.x, tolerance, tolerance));
  CHECK(hit->N.y == T::within(N.y, tolerance, tolerance));
}

// ---- the references ------------------------------------------------------------------------

// world = C + R·S·canonical, R the rotation (c, −s; s, c), S = diag(a, b)
struct Frame {
  T::R2 C;
  Real a, b, c, s;
  T::R2 e1() const { return {c, s}; }
  T::R2 e2() const { return {-s, c}; }
  T::R2 point(T::R2 P) const { return vec(P - C); }
  T::R2 vec(T::R2 v) const { return {T::dot(v, e1()) / a, T::dot(v, e2()) / b}; }
};

struct Expected {
  bool inside = false;
  std::optional<Real> t;  // a length along the ray
  T::R2 I, N;
  int axis = -1, sign = 0;  // the rectangle's side hit
  bool same_branch(const Expected& o) const {
    return inside == o.inside && t.has_value() == o.t.has_value() && axis == o.axis &&
           sign == o.sign;
  }
};

// The implicit quadratic |p + t·v|² = 1 in the canonical frame, solved in its stable form.
Expected ellipse_reference(T::R2 A, T::R2 u, const Frame& f) {
  Expected e;
  const T::R2 p = f.point(A), v = f.vec(u);
  const Real alpha = T::dot(v, v), beta = T::dot(p, v), gamma = T::dot(p, p) - 1;
  e.inside = gamma < 0;
  const Real disc = beta * beta - alpha * gamma;
  if (disc < 0) return e;
  const Real q = -(beta + (beta < 0 ? -T::sqrt(disc) : T::sqrt(disc)));
  Real lo = q / alpha, hi = lo;
  if (q != 0) {
    const Real other = gamma / q;
    lo = T::min(lo, other);
    hi = T::max(q / alpha, other);
  }
  Real t;
  if (e.inside)
    t = hi;
  else if (lo >= 0)
    t = lo;
  else
    return e;  // both behind (outside, the product of the roots is ≥ 0)
  e.t = t * T::norm(u);
  e.I = A + t * u;
  const T::R2 ic = p + t * v;
  e.N = T::unit(ic.x / f.a * f.e1() + ic.y / f.b * f.e2());
  return e;
}

// The slab method in the canonical frame (support/box_reference.h), carried back.
Expected rectangle_reference(T::R2 A, T::R2 u, const Frame& f) {
  Expected e;
  const T::R2 p = f.point(A), v = f.vec(u);
  const auto box = T::box_reference_real<2>({p.x, p.y}, {v.x, v.y});
  e.inside = box.inside;
  if (!box.t) return e;
  const Real t = *box.t / T::norm(v);  // in units of v, which are those of u
  e.t = t * T::norm(u);
  e.I = A + t * u;
  e.axis = box.axis;
  e.sign = box.sign;
  e.N = Real(box.sign) * (box.axis == 0 ? f.e1() : f.e2());
  return e;
}

// ---- figures and the ε-nudged comparison ---------------------------------------------------

struct Figure {
  Point2 A;
  Vec2 u;
  Point2 C;
  double a, b, angle;
};

Frame frame_of(const Figure& g) {
  const T::RealCosSin cs = T::cos_sin_degrees(g.angle);
  return {T::real(g.C), g.a, g.b, cs.cos, cs.sin};
}

// world point of a canonical point, in doubles (to build figures; the data are what they are)
Point2 place(const Figure& g, Vec2 canonical) {
  const double r = g.angle * std::numbers::pi / 180;
  const double x = g.a * canonical.x, y = g.b * canonical.y;
  return {g.C.x + std::cos(r) * x - std::sin(r) * y, g.C.y + std::sin(r) * x + std::cos(r) * y};
}
Vec2 place_vec(const Figure& g, Vec2 canonical) {
  Figure at_origin = g;
  at_origin.C = {0, 0};
  return to_vec(place(at_origin, canonical));
}

// Figures of every kind: around, inside, far and aimed, nearly tangent (ellipse) or nearly
// through a corner (rectangle), at sizes 1e-8 to 1e8, aspect ratios up to ~300, any angle (a
// third of them 0, 90, 45 or 30 degrees).
Figure draw_figure(Rng& rng, int kind) {
  const double size = T::decades(rng, -8, 8);
  Figure g;
  g.C = T::point2(rng, 3 * size);
  g.a = size * T::decades(rng, -1.25, 0.25);
  g.b = size * T::decades(rng, -1.25, 0.25);
  const double special[] = {0, 90, 45, 30, -90, 180};
  g.angle = rng.chance(0.33) ? special[rng.integer(0, 5)] : rng.uniform(-720, 720);
  const Vec2 along = *normalized(T::direction2(rng));
  switch (kind) {
    case 0:
      g.A = g.C + 4 * size * Vec2{rng.uniform(-1, 1), rng.uniform(-1, 1)};
      g.u = T::direction2(rng);
      break;
    case 1:
      g.A = place(g, rng.uniform(0, 0.7) * along);
      g.u = T::direction2(rng);
      break;
    case 2: {
      const Point2 target = place(g, {rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)});
      g.A = target + size * T::decades(rng, 0.5, 6) * *normalized(T::direction2(rng));
      g.u = T::decades(rng, -3, 3) * (target - g.A);
      break;
    }
    default: {  // the canonical line at 1 ± η from the centre: nearly tangent to the circle,
                // nearly through a corner's side lines for the square
      const double eta = T::decades(rng, -12, -3) * T::sign(rng), distance = T::decades(rng, -1, 3);
      g.A = place(g, -distance * along + (1 + eta) * perp(along));
      g.u = T::decades(rng, -3, 3) * place_vec(g, along);
      break;
    }
  }
  return g;
}

struct Comparison {
  Expected e;
  bool ambiguous = false;
  double t = 0, Ix = 0, Iy = 0, Nx = 0, Ny = 0;  // how far ε-nudges move each output
};

// The figure with every datum nudged in turn by `eps`: A by eps of |A − C| + the figure's
// size, u's direction by eps rad, C by eps of |C| + size, the radii by eps of themselves, the
// frame's angle by eps rad.
// With `local`, A moves by eps of the figure's size only: the line itself is exact data (the
// direction as given) and the implementation works from a point of it near the figure.
template <class Reference>
std::vector<Expected> nudged(const Figure& g, Reference reference, Real eps, bool local = false) {
  const Frame f = frame_of(g);
  const T::R2 A = T::real(g.A), u = T::real(g.u);
  const Real size = T::max(f.a, f.b);
  const Real reach = local ? 4 * size : T::norm(A - f.C) + size, place = T::norm(f.C) + size;
  Frame turned = f, wider = f, taller = f, right = f, up = f;
  turned.c = f.c - f.s * eps;
  turned.s = f.s + f.c * eps;
  wider.a = f.a * (1 + eps);
  taller.b = f.b * (1 + eps);
  right.C.x += eps * place;
  up.C.y += eps * place;
  return {reference(A + T::R2{eps * reach, 0}, u, f),
          reference(A + T::R2{0, eps * reach}, u, f),
          reference(A, u + eps * T::R2{-u.y, u.x}, f),
          reference(A, u, turned),
          reference(A, u, wider),
          reference(A, u, taller),
          reference(A, u, right),
          reference(A, u, up)};
}

// The reference and how far ε-nudges move it. A figure whose branch changes under nudges of
// 64ε is within the data's rounding of a boundary (the tolerance policy's band is 32ε of the
// figure's reach): ambiguous.
template <class Reference>
Comparison compare(const Figure& g, Reference reference, bool local = false) {
  Comparison out;
  out.e = reference(T::real(g.A), T::real(g.u), frame_of(g));
  for (const Expected& n : nudged(g, reference, 64 * kEps))
    if (!n.same_branch(out.e)) out.ambiguous = true;
  if (out.ambiguous) return out;
  for (const Expected& n : nudged(g, reference, kEps, local)) {
    if (!n.same_branch(out.e)) out.ambiguous = true;
    if (out.ambiguous || !n.t) continue;
    out.t += d(T::abs(*n.t - *out.e.t));
    out.Ix += d(T::abs(n.I.x - out.e.I.x));
    out.Iy += d(T::abs(n.I.y - out.e.I.y));
    out.Nx += d(T::abs(n.N.x - out.e.N.x));
    out.Ny += d(T::abs(n.N.y - out.e.N.y));
  }
  return out;
}

// The answer within 32 times the nudges' spread (the implementation rounds a dozen times, each
// a nudge of that order) plus a few ε of the value itself.
void check_against(const Comparison& c, bool inside, const std::optional<Hit2>& hit,
                   double length_u) {
  CHECK(inside == c.e.inside);
  REQUIRE(hit.has_value() == c.e.t.has_value());
  if (!hit) return;
  constexpr double k = 32;
  CHECK(hit->t * length_u == T::within(d(*c.e.t), 16 * kEps, k * c.t));
  CHECK(hit->I.x == T::within(d(c.e.I.x), 16 * kEps, k * c.Ix));
  CHECK(hit->I.y == T::within(d(c.e.I.y), 16 * kEps, k * c.Iy));
  CHECK(hit->N.x == T::within(d(c.e.N.x), 0, k * c.Nx + 16 * kEps));
  CHECK(hit->N.y == T::within(d(c.e.N.y), 0, k * c.Ny + 16 * kEps));
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/ray_transformed: the contract's worked examples") {
  SUBCASE("1. ellipse (2, 1) at 0°, from the left") {
    const RayEllipse e = intersect(Ray2::unit({-5, 0}, {1, 0}), Ellipse{{0, 0}, 2, 1, 0});
    CHECK_FALSE(e.inside);
    check_hit(e.hit, 3, {-2, 0}, {-1, 0}, 0);
  }
  SUBCASE("2. ellipse (2, 1) at 90°, from below") {
    const RayEllipse e = intersect(Ray2::unit({0, -5}, {0, 1}), Ellipse{{0, 0}, 2, 1, 90});
    check_hit(e.hit, 3, {0, -2}, {0, -1}, 0);
  }
  SUBCASE("3. rectangle (2, 1) at 0° centred at (1, 0.5)") {
    const RayRectangle r = intersect(Ray2::unit({-5, 0}, {1, 0}), Rectangle{{1, 0.5}, 2, 1, 0});
    CHECK_FALSE(r.inside);
    check_hit(r.hit, 4, {-1, 0}, {-1, 0}, 0);
  }
  SUBCASE("4. the unit square at 45°: a diamond") {
    const RayRectangle r = intersect(Ray2::unit({-5, 0.3}, {1, 0}), Rectangle{{0, 0}, 1, 1, 45});
    check_hit(r.hit, 3.885786437626905, {-1.114213562373095, 0.3},
              {-0.7071067811865476, 0.7071067811865476}, 4 * kEps);
  }
}

TEST_CASE("geometry/ray_transformed: every branch") {
  SUBCASE("1. degenerate figures are refused, naming the field") {
    const Ray2 ray = Ray2::unit({-5, 0}, {1, 0});
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    for (auto [a, b] :
         {std::pair{0.0, 1.0}, std::pair{1.0, -1.0}, std::pair{nan, 1.0}, std::pair{1.0, inf}}) {
      CAPTURE(a);
      CAPTURE(b);
      check_refused([&] { intersect(ray, Ellipse{{0, 0}, a, b, 0}); }, "radii");
      check_refused([&] { intersect(ray, Rectangle{{0, 0}, a, b, 0}); }, "half");
    }
    for (double angle : {nan, inf, -inf}) {
      check_refused([&] { intersect(ray, Ellipse{{0, 0}, 2, 1, angle}); }, "angle");
      check_refused([&] { intersect(ray, Rectangle{{0, 0}, 2, 1, angle}); }, "angle");
    }
    check_refused([] { intersect(Ray2{{0, 0}, {0, 0}}, Ellipse{{0, 0}, 2, 1, 0}); }, "u");
    check_refused([] { intersect(Ray2{{0, 0}, {0, 0}}, Rectangle{{0, 0}, 2, 1, 0}); }, "u");
  }
  SUBCASE("2. a round ellipse is a circle, a unit rectangle at the origin the square") {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
      Rng rng(seed, 5);
      CAPTURE(seed);
      const Point2 A = T::point2(rng, 4), C = T::point2(rng, 1);
      const Vec2 u = T::direction2(rng);
      const double r = T::decades(rng, -0.5, 0.5);
      const RayEllipse e = intersect(Ray2::unit(A, u), Ellipse{C, r, r, rng.uniform(-180, 180)});
      const RayCircle c = intersect(Ray2::unit(A, u), Circle{C, r});
      CHECK(e.inside == c.inside);
      REQUIRE(e.hit.has_value() == c.hit.has_value());
      if (c.hit) check_hit(e.hit, c.hit->t, c.hit->I, c.hit->N, 1e-13);
      const RayRectangle q = intersect(Ray2::unit(A, u), Rectangle{{0, 0}, 1, 1, 0});
      const RaySquare s = intersect_canonical_square(Ray2::unit(A, u));
      CHECK(q.inside == s.inside);
      REQUIRE(q.hit.has_value() == s.hit.has_value());
      if (s.hit) check_hit(q.hit, s.hit->t, s.hit->I, s.hit->N, 4 * kEps);
    }
  }
  SUBCASE("3. quarter turns: 90° with radii (2, 1) is 0° with radii (1, 2), exactly") {
    const Ray2 ray = Ray2::unit({-3, 0.7}, {1, -0.1});
    const RayEllipse e90 = intersect(ray, Ellipse{{0.5, 0.25}, 2, 1, 90}),
                     e0 = intersect(ray, Ellipse{{0.5, 0.25}, 1, 2, 0});
    check_hit(e90.hit, e0.hit->t, e0.hit->I, e0.hit->N, 0);
    const RayEllipse e270 = intersect(ray, Ellipse{{0.5, 0.25}, 2, 1, -90});
    check_hit(e270.hit, e0.hit->t, e0.hit->I, e0.hit->N, 0);
    const RayRectangle r90 = intersect(ray, Rectangle{{0.5, 0.25}, 2, 1, 90}),
                       r0 = intersect(ray, Rectangle{{0.5, 0.25}, 1, 2, 0});
    check_hit(r90.hit, r0.hit->t, r0.hit->I, r0.hit->N, 0);
    // a half turn maps each figure onto itself
    const RayEllipse e180 = intersect(ray, Ellipse{{0.5, 0.25}, 1, 2, 180});
    check_hit(e180.hit, e0.hit->t, e0.hit->I, e0.hit->N, 4 * kEps);
  }
  SUBCASE("4. 45°: ellipse (2, 1) crossed along the x-axis at x = −√1.6, N ∝ (−5, 3)") {
    // (x·c/2)² + (x·s)² = 1 with c = s = √½: x² (1/8 + 1/2) = 1
    const RayEllipse e = intersect(Ray2::unit({-5, 0}, {1, 0}), Ellipse{{0, 0}, 2, 1, 45});
    const double x = std::sqrt(1.6);
    check_hit(e.hit, 5 - x, {-x, 0}, {-5 / std::sqrt(34.0), 3 / std::sqrt(34.0)}, 4 * kEps);
  }
  SUBCASE("5. 45°: the diamond's left corner, t = 5 − √2 (a tie of two sides)") {
    const RayRectangle r = intersect(Ray2::unit({-5, 0}, {1, 0}), Rectangle{{0, 0}, 1, 1, 45});
    REQUIRE(r.hit.has_value());
    CHECK(r.hit->t == doctest::Approx(5 - std::sqrt(2.0)).epsilon(4 * kEps));
    CHECK(r.hit->I.x == doctest::Approx(-std::sqrt(2.0)).epsilon(4 * kEps));
    CHECK(r.hit->I.y == T::within(0, 0, 4 * kEps));
  }
  SUBCASE("6. 30° and its equivalents: −330°, 390°, 750°") {
    const Ray2 ray = Ray2::unit({-4, 1}, {3, -1});
    const RayEllipse e = intersect(ray, Ellipse{{0.2, 0.1}, 2, 0.5, 30});
    const Expected x =
        ellipse_reference(T::real(ray.origin), T::real(ray.direction),
                          frame_of({ray.origin, ray.direction, {0.2, 0.1}, 2, 0.5, 30}));
    check_hit(e.hit, d(*x.t), {d(x.I.x), d(x.I.y)}, {d(x.N.x), d(x.N.y)}, 8 * kEps);
    for (double angle : {-330.0, 390.0, 750.0}) {
      CAPTURE(angle);
      check_hit(intersect(ray, Ellipse{{0.2, 0.1}, 2, 0.5, angle}).hit, e.hit->t, e.hit->I,
                e.hit->N, 0);
    }
    const RayRectangle r = intersect(ray, Rectangle{{0.2, 0.1}, 2, 0.5, 30});
    const Expected y =
        rectangle_reference(T::real(ray.origin), T::real(ray.direction),
                            frame_of({ray.origin, ray.direction, {0.2, 0.1}, 2, 0.5, 30}));
    check_hit(r.hit, d(*y.t), {d(y.I.x), d(y.I.y)}, {d(y.N.x), d(y.N.y)}, 8 * kEps);
  }
  SUBCASE("7. from inside: the exit point") {
    const RayEllipse e = intersect(Ray2::unit({0.5, 0.25}, {0, 1}), Ellipse{{0.5, 0.25}, 3, 2, 0});
    CHECK(e.inside);
    check_hit(e.hit, 2, {0.5, 2.25}, {0, 1}, 0);
    const RayRectangle r = intersect(Ray2::unit({0, 0}, {1, 1}), Rectangle{{0, 0}, 2, 1, 0});
    CHECK(r.inside);
    check_hit(r.hit, std::sqrt(2.0), {1, 1}, {0, 1}, 4 * kEps);
  }
  SUBCASE("8. from the boundary: in at t = 0 with I = A, out: no hit") {
    const Ellipse ellipse{{1, 1}, 2, 1, 0};
    const RayEllipse in = intersect(Ray2::unit({3, 1}, {-1, 0.5}), ellipse);
    CHECK_FALSE(in.inside);
    check_hit(in.hit, 0, {3, 1}, {1, 0}, 2 * kEps);
    CHECK(exactly(in.hit->I.x, 3));
    CHECK_FALSE(intersect(Ray2::unit({3, 1}, {1, 0.5}), ellipse).hit.has_value());
    const Rectangle rectangle{{1, 1}, 2, 1, 0};
    const RayRectangle on = intersect(Ray2::unit({3, 1.5}, {-1, 0.2}), rectangle);
    CHECK_FALSE(on.inside);
    check_hit(on.hit, 0, {3, 1.5}, {1, 0}, 0);
    CHECK_FALSE(intersect(Ray2::unit({3, 1.5}, {1, 0.2}), rectangle).hit.has_value());
    // rotated 30°, from a vertex of the ellipse: its coordinates are rounded, still "on"
    const Ellipse slanted{{0, 0}, 2, 1, 30};
    const Point2 vertex{2 * std::sqrt(3.0) / 2, 2 * 0.5};
    const RayEllipse v = intersect(Ray2::unit(vertex, {-1, 0}), slanted);
    CHECK_FALSE(v.inside);
    REQUIRE(v.hit.has_value());
    CHECK(v.hit->t == T::within(0, 0, 1e-15));
  }
  SUBCASE("9. tangent to the ellipse, grazing the rectangle's side") {
    const RayEllipse e = intersect(Ray2::unit({-5, 1}, {1, 0}), Ellipse{{0, 0}, 2, 1, 0});
    check_hit(e.hit, 5, {0, 1}, {0, 1}, 0);
    const RayRectangle r = intersect(Ray2::unit({-5, 1}, {1, 0}), Rectangle{{0, 0}, 2, 1, 0});
    check_hit(r.hit, 3, {-2, 1}, {-1, 0}, 0);
    CHECK_FALSE(
        intersect(Ray2::unit({-5, 1 + 1e-9}, {1, 0}), Ellipse{{0, 0}, 2, 1, 0}).hit.has_value());
  }
  SUBCASE("10. every scale, 1e-200 to 1e200") {
    for (double k : {1e-200, 1e-8, 1e8, 1e200}) {
      CAPTURE(k);
      const RayEllipse e =
          intersect(Ray2::unit({-5 * k, 0}, {1, 0}), Ellipse{{0, 0}, 2 * k, k, 45});
      const double x = std::sqrt(1.6);
      REQUIRE(e.hit.has_value());
      CHECK(e.hit->t == doctest::Approx((5 - x) * k).epsilon(8 * kEps));
      CHECK(e.hit->I.x == doctest::Approx(-x * k).epsilon(8 * kEps));
      CHECK(e.hit->I.y == T::within(0, 0, 8 * kEps * k));
      CHECK(e.hit->N.x == doctest::Approx(-5 / std::sqrt(34.0)).epsilon(8 * kEps));
      CHECK(e.hit->N.y == doctest::Approx(3 / std::sqrt(34.0)).epsilon(8 * kEps));
      const RayRectangle r =
          intersect(Ray2::unit({-5 * k, 0.3 * k}, {1, 0}), Rectangle{{0, 0}, k, k, 45});
      REQUIRE(r.hit.has_value());
      CHECK(r.hit->t == doctest::Approx(3.885786437626905 * k).epsilon(8 * kEps));
      CHECK(r.hit->I.x == doctest::Approx(-1.114213562373095 * k).epsilon(8 * kEps));
      CHECK(r.hit->I.y == doctest::Approx(0.3 * k).epsilon(8 * kEps));
      CHECK(r.hit->N.x == doctest::Approx(-std::sqrt(0.5)).epsilon(8 * kEps));
    }
  }
  SUBCASE("11. the canonical frame: T⁻¹ carries the ray, t names the same point") {
    // (A within two sizes of the figure: a ray from farther is solved again from nearby)
    const Ray2 ray = Ray2::unit({-3, 1}, {3, -1});
    const RayEllipse e = intersect(ray, Ellipse{{0.2, 0.1}, 2, 0.5, 30});
    REQUIRE(e.canonical.hit.has_value());
    CHECK(exactly(e.canonical.hit->t, e.hit->t));
    const Point2 back = e.to_world.apply(e.canonical.hit->I);
    CHECK(back.x == T::within(e.hit->I.x, 0, 8 * kEps));
    CHECK(back.y == T::within(e.hit->I.y, 0, 8 * kEps));
    CHECK(norm(e.canonical.hit->I - Point2{0, 0}) == doctest::Approx(1).epsilon(4 * kEps));
    const Point2 Ac = e.to_world.inverse().apply(ray.origin);
    CHECK(e.canonical_ray.origin.x == T::within(Ac.x, 0, 8 * kEps * 4));
    CHECK(e.canonical_ray.origin.y == T::within(Ac.y, 0, 8 * kEps * 4));
    // from farther: the canonical solution is still the one seen from A, the hit agrees with it
    const Ray2 far = Ray2::unit({-40, 14}, {3, -1});
    const RayEllipse f = intersect(far, Ellipse{{0.2, 0.1}, 2, 0.5, 30});
    REQUIRE(f.canonical.hit.has_value());
    CHECK(f.hit->t == T::within(f.canonical.hit->t, 4 * kEps, 0));
    const Point2 Af = f.to_world.inverse().apply(far.origin);
    CHECK(f.canonical_ray.origin.x == T::within(Af.x, 0, 8 * kEps * 40));
  }
}

TEST_CASE("geometry/ray_transformed: random ellipses against the implicit quadratic") {
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Figure g = draw_figure(rng, static_cast<int>(seed % 4));
    CAPTURE(g.A.x);
    CAPTURE(g.A.y);
    CAPTURE(g.u.x);
    CAPTURE(g.u.y);
    CAPTURE(g.C.x);
    CAPTURE(g.C.y);
    CAPTURE(g.a);
    CAPTURE(g.b);
    CAPTURE(g.angle);
    const auto c = compare(g, ellipse_reference);
    if (c.ambiguous) continue;
    ++compared;
    const Ellipse ellipse{g.C, g.a, g.b, g.angle};
    const RayEllipse unit = intersect(Ray2::unit(g.A, g.u), ellipse);
    check_against(c, unit.inside, unit.hit, 1.0);
    const RayEllipse raw = intersect(Ray2{g.A, g.u}, ellipse);
    check_against(c, raw.inside, raw.hit, norm(g.u));
    if (!unit.hit) continue;
    // on the ellipse, N unit and outward, t = |AI|
    const Frame f = frame_of(g);
    const T::R2 ic = f.point(T::real(unit.hit->I));
    const double reach = d(T::norm(T::real(g.A) - f.C)) / std::min(g.a, g.b);
    CHECK(d(T::norm(ic)) ==
          T::within(1, 0, 32 * kEps * (1 + reach) + 32 * c.Ix / std::min(g.a, g.b)));
    CHECK(norm(unit.hit->N) == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(d(T::dot(T::real(unit.hit->N), T::real(unit.hit->I) - f.C)) > 0);
    CHECK(norm(unit.hit->I - g.A) ==
          T::within(unit.hit->t, 16 * kEps, 16 * kEps * norm(to_vec(g.A))));
  }
  CHECK(compared > 2700);
}

TEST_CASE("geometry/ray_transformed: random rectangles against the slab method") {
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed, 1);
    CAPTURE(seed);
    const Figure g = draw_figure(rng, static_cast<int>(seed % 4));
    CAPTURE(g.A.x);
    CAPTURE(g.A.y);
    CAPTURE(g.u.x);
    CAPTURE(g.u.y);
    CAPTURE(g.C.x);
    CAPTURE(g.C.y);
    CAPTURE(g.a);
    CAPTURE(g.b);
    CAPTURE(g.angle);
    const auto c = compare(g, rectangle_reference);
    if (c.ambiguous) continue;
    ++compared;
    const Rectangle rectangle{g.C, g.a, g.b, g.angle};
    const RayRectangle unit = intersect(Ray2::unit(g.A, g.u), rectangle);
    check_against(c, unit.inside, unit.hit, 1.0);
    const RayRectangle raw = intersect(Ray2{g.A, g.u}, rectangle);
    check_against(c, raw.inside, raw.hit, norm(g.u));
    if (!unit.hit) continue;
    // on the side named, N its rotated axis normal, t = |AI|
    REQUIRE(unit.canonical.face.has_value());
    CHECK(unit.canonical.face->axis == c.e.axis);
    CHECK(unit.canonical.face->sign == c.e.sign);
    const Frame f = frame_of(g);
    const T::R2 ic = f.point(T::real(unit.hit->I));
    const Real on_side = unit.canonical.face->axis == 0 ? ic.x : ic.y;
    const double reach = d(T::norm(T::real(g.A) - f.C)) / std::min(g.a, g.b);
    CHECK(d(on_side) ==
          T::within(unit.canonical.face->sign, 0,
                    32 * kEps * (1 + reach) + 32 * (c.Ix + c.Iy) / std::min(g.a, g.b)));
    CHECK(norm(unit.hit->I - g.A) ==
          T::within(unit.hit->t, 16 * kEps, 16 * kEps * norm(to_vec(g.A))));
  }
  CHECK(compared > 2700);
}

TEST_CASE(
    "geometry/ray_transformed: from far away, with the direction as given, the hit keeps the "
    "figure's digits") {
  // A up to 1e6 sizes away: the hit is redone from a point of the ray near the figure, so that
  // only the figure's own rounding remains (A nudged by ε of the figure's size, not of |A − C|)
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 1500; ++seed) {
    Rng rng(seed, 2);
    CAPTURE(seed);
    const Figure g = draw_figure(rng, 2);
    CAPTURE(g.A.x);
    CAPTURE(g.A.y);
    CAPTURE(g.angle);
    const auto ce = compare(g, ellipse_reference, true);
    if (!ce.ambiguous) {
      const RayEllipse e = intersect(Ray2{g.A, g.u}, Ellipse{g.C, g.a, g.b, g.angle});
      check_against(ce, e.inside, e.hit, norm(g.u));
      ++compared;
    }
    const auto cr = compare(g, rectangle_reference, true);
    if (!cr.ambiguous) {
      const RayRectangle r = intersect(Ray2{g.A, g.u}, Rectangle{g.C, g.a, g.b, g.angle});
      check_against(cr, r.inside, r.hit, norm(g.u));
      ++compared;
    }
  }
  CHECK(compared > 2800);
  SUBCASE("a unit ellipse at 30° seen from 1e8") {
    const Point2 A{1e8, -3e7};
    const Vec2 u = Point2{0.3, 0.1} - A;
    const Figure g{A, u, {0, 0}, 1, 0.5, 30};
    const Expected e = ellipse_reference(T::real(A), T::real(u), frame_of(g));
    const RayEllipse got = intersect(Ray2{A, u}, Ellipse{{0, 0}, 1, 0.5, 30});
    check_hit(got.hit, d(*e.t) / norm(u), {d(e.I.x), d(e.I.y)}, {d(e.N.x), d(e.N.y)}, 8 * kEps);
  }
}

TEST_SUITE_END();

TEST_CASE("ray_transformed exact: quarter turns and sizes powers of two decide exactly, 0-3 ulps") {
  // The carried ray is exact there (A − C on a binary grid, a quarter turn, a division by a
  // power of two): A on the ellipse or the rectangle at the end of an axis, moved by k ulps
  // along it, heading to the centre. Inside exactly when the move went in; on it, a hit at t = 0.
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    const double angle = 90.0 * static_cast<double>(rng.integer(-4, 4));
    const double a = std::ldexp(1.0, static_cast<int>(rng.integer(-4, 4)));
    const double b = std::ldexp(1.0, static_cast<int>(rng.integer(-4, 4)));
    const double unit = std::ldexp(1.0, -6);
    const double far = std::ldexp(1.0, static_cast<int>(rng.integer(0, 20)));
    const Point2 C{unit * std::round(rng.uniform(-far, far)), unit * std::round(rng.uniform(-far, far))};
    const bool along_a = rng.chance(0.5);
    const double size = along_a ? a : b, side = T::sign(rng);
    // the local axis (a's or b's) in the world, a quarter turn of the x axis
    const int quarter = ((static_cast<int>(angle / 90) % 4) + 4 + (along_a ? 0 : 1)) % 4;
    const Vec2 axis = quarter == 0 ? Vec2{1, 0} : quarter == 1 ? Vec2{0, 1} : quarter == 2 ? Vec2{-1, 0} : Vec2{0, -1};
    Point2 A = C + (side * size) * axis;
    double& moved = axis.x != 0 ? A.x : A.y;
    const double centre = axis.x != 0 ? C.x : C.y;
    if (moved == 0) continue;  // a zero moved by an ulp is subnormal: outside the contract
    for (int i = 0; i < std::abs(k); ++i) moved = std::nextafter(moved, k > 0 ? INFINITY : -INFINITY);
    const double offset = std::abs(moved - centre);  // exact: grid points
    const bool inside = offset < size;
    const Vec2 u = C - A;
    if (rng.chance(0.5)) {
      const RayEllipse e = intersect_exact(Ray2{A, u}, Ellipse{C, a, b, angle});
      CHECK(e.inside == inside);
      REQUIRE(e.hit.has_value());
      if (offset == size) CHECK(exactly(e.hit->t, 0));
    } else {
      const RayRectangle r = intersect_exact(Ray2{A, u}, Rectangle{C, a, b, angle});
      CHECK(r.inside == inside);
      REQUIRE(r.hit.has_value());
      if (offset == size) CHECK(exactly(r.hit->t, 0));
    }
  }
}
