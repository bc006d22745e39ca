#include "geometry/ray_transformed.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "geometry/exact_vec.h"
#include "geometry/exponent.h"
#include "support/fma_clones.h"

namespace epure::geo {

namespace detail {

// The world normal by the inverse transpose, up to a positive factor: (M⁻¹)ᵀ = adj(M)ᵀ / det
// and det > 0 (positive sizes, a rotation), so [d −c; −b a]·n from the forward matrix points the
// same way. The forward matrix stays finite whatever the sizes, where M⁻¹ of radii near 1e-300
// overflows and left nothing to normalise. Throws for a figure beyond what doubles can draw.
Vec2 world_normal(const Transform2& world, Vec2 n, const char* size_field) {
  const Affine2Matrix& m = world.matrix();
  const auto N = normalized(Vec2{m.d * n.x - m.c * n.y, m.a * n.y - m.b * n.x});
  if (!N) throw DegenerateFigure(size_field, "figure too small or too large for a normal in doubles");
  return *N;
}

}  // namespace detail

namespace {

Transform2 place(Point2 C, double sx, double sy, double angle_deg) {
  if (!std::isfinite(angle_deg)) throw DegenerateFigure("angle", "not a finite angle");
  return Transform2::translate(to_vec(C)) * Transform2::rotate_degrees(angle_deg) *
         Transform2::scale(sx, sy);
}

void require_positive(double value, const char* field, const char* what) {
  if (!(value > 0) || !std::isfinite(value)) throw DegenerateFigure(field, what);
}

// T⁻¹ of the ray. The origin goes through the linear part only, relative to the centre:
// A − C is exact to half an ulp, where T⁻¹(A) = M⁻¹·A − M⁻¹·C would lose the digits of a small
// figure far from the origin. Same point, fewer roundings.
Ray2 to_canonical(const Transform2& world, Point2 centre, const Ray2& ray) {
  const Transform2 back = world.inverse();
  return {to_point(back.apply(ray.origin - centre)), back.apply(ray.direction)};
}

double max_abs(Vec2 v) { return std::max(std::abs(v.x), std::abs(v.y)); }

// The datum that sizes the figure, as the contract names it.
template <class Canonical>
constexpr const char* size_field() {
  return std::is_same_v<Canonical, RaySquare> ? "half" : "radii";
}

// The canonical solution carried back: t names the same point in both frames, N goes by the
// inverse transpose.
template <class Canonical>
RayTransformed<Canonical> carry_back(const Transform2& world, Point2 centre, const Ray2& ray,
                                     Ray2 canonical_ray, Canonical canonical) {
  RayTransformed<Canonical> res{world, canonical_ray, canonical, canonical.inside, std::nullopt};
  if (canonical.hit) {
    const double t = canonical.hit->t;
    const Vec2 N = detail::world_normal(world, canonical.hit->N, size_field<Canonical>());
    // I is A itself at t = 0; otherwise A + t·u or T(I_c) = C + M·I_c, whichever rounds less:
    // the second keeps the digits of a small figure seen from far away.
    const Vec2 reach = world.apply(to_vec(canonical.hit->I));
    const double from_a = max_abs(to_vec(ray.origin)) + std::abs(t) * max_abs(ray.direction);
    const double from_c = max_abs(to_vec(centre)) + max_abs(reach);
    const Point2 I = !(t > 0) ? ray.origin : from_c < from_a ? centre + reach : ray.at(t);
    res.hit = Hit2{t, I, N};
  }
  return res;
}

// A ray from far away, seen from nearby. Carrying A − C into the canonical frame rounds it by
// ε·|A − C|: far from the figure the line moves by that much, and the hit point with it. The
// same line through a point A' of it near the figure keeps the figure's digits (Box2D shifts to
// a local origin likewise): A' − C = (A − C) + t0·u with A − C exact and one fma, so A' is on
// the line to within ε of the figure's size. t0 stops 2·size short of the foot of C's
// perpendicular, outside the figure's bounding circle (radius ≤ √2·size), so that the first
// point of the figure seen from A' is the one seen from A. The canonical solution from A (its
// frame, its candidate sides) is kept for what it shows; only the hit is redone, and kept when
// it agrees (the same side of the rectangle).
template <class Canonical, class Solve>
void refine_from_nearby(RayTransformed<Canonical>& res, Point2 centre, double size, const Ray2& ray,
                        Solve solve) {
  if (!res.hit) return;
  // t_proj = u·AC / u·u in units of u, u rescaled by a power of two against overflow
  const int f = binary_exponent(max_abs(ray.direction));
  const Vec2 u = times_pow2(ray.direction, -f);
  const ExactVec2 AC = exact_difference(centre, ray.origin);
  const double length_u = plain_norm(u);
  const double t0 = times_pow2((dot(as_exact(u), AC) / length_u - 2 * size) / length_u, -f);
  if (!(t0 > 0) || !(res.hit->t > t0)) return;  // near already: nothing to gain
  // A' − C = (A − C) + t0·u
  const Vec2 from_centre{std::fma(t0, ray.direction.x, -AC.hi.x) - AC.lo.x,
                         std::fma(t0, ray.direction.y, -AC.hi.y) - AC.lo.y};
  const Transform2 back = res.to_world.inverse();
  const Canonical again =
      solve(Ray2{to_point(back.apply(from_centre)), back.apply(ray.direction)});
  if (!again.hit) return;
  if constexpr (requires { res.canonical.face; })
    if (again.face != res.canonical.face) return;
  res.hit = Hit2{t0 + again.hit->t, centre + res.to_world.apply(to_vec(again.hit->I)),
                 detail::world_normal(res.to_world, again.hit->N, size_field<Canonical>())};
}

}  // namespace

Transform2 to_world(const Ellipse& e) {
  require_positive(e.a, "radii", "radii must be > 0");
  require_positive(e.b, "radii", "radii must be > 0");
  return place(e.C, e.a, e.b, e.angle_deg);
}

Transform2 to_world(const Rectangle& r) {
  require_positive(r.w, "half", "half-sizes must be > 0");
  require_positive(r.h, "half", "half-sizes must be > 0");
  return place(r.C, r.w, r.h, r.angle_deg);
}

namespace {

template <class Solve>
RayEllipse ellipse_by(const Ray2& ray, const Ellipse& ellipse, Solve solve) {
  const Transform2 world = to_world(ellipse);
  const Ray2 canonical_ray = to_canonical(world, ellipse.C, ray);
  auto res = carry_back(world, ellipse.C, ray, canonical_ray, solve(canonical_ray));
  refine_from_nearby(res, ellipse.C, std::max(ellipse.a, ellipse.b), ray, solve);
  return res;
}

template <class Solve>
RayRectangle rectangle_by(const Ray2& ray, const Rectangle& rectangle, Solve solve) {
  const Transform2 world = to_world(rectangle);
  const Ray2 canonical_ray = to_canonical(world, rectangle.C, ray);
  auto res = carry_back(world, rectangle.C, ray, canonical_ray, solve(canonical_ray));
  refine_from_nearby(res, rectangle.C, std::max(rectangle.w, rectangle.h), ray, solve);
  return res;
}

}  // namespace

RayEllipse intersect(const Ray2& ray, const Ellipse& ellipse) {
  return ellipse_by(ray, ellipse, intersect_canonical_circle);
}
RayRectangle intersect(const Ray2& ray, const Rectangle& rectangle) {
  return rectangle_by(ray, rectangle, intersect_canonical_square);
}
EPURE_FMA_KERNEL RayEllipse intersect_exact(const Ray2& ray, const Ellipse& ellipse) {
  return ellipse_by(ray, ellipse, intersect_canonical_circle_exact);
}
EPURE_FMA_KERNEL RayRectangle intersect_exact(const Ray2& ray, const Rectangle& rectangle) {
  return rectangle_by(ray, rectangle, [](const Ray2& r) { return intersect_canonical_square_exact(r); });
}

}  // namespace epure::geo
