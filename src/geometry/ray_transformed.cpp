#include "geometry/ray_transformed.h"

#include <cmath>

namespace epure::geo {

namespace {

Transform2 place(Point2 C, double sx, double sy, double angle_deg) {
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

template <class Canonical>
RayTransformed<Canonical> carry_back(const Transform2& world, const Ray2& ray, Ray2 canonical_ray,
                                     Canonical canonical) {
  RayTransformed<Canonical> res{world, canonical_ray, canonical, canonical.inside, std::nullopt};
  if (canonical.hit) {
    const double t = canonical.hit->t;
    const Vec2 N = *normalized(world.apply_normal(canonical.hit->N));
    res.hit = Hit2{t, ray.at(t), N};
  }
  return res;
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

RayEllipse intersect(const Ray2& ray, const Ellipse& ellipse) {
  const Transform2 world = to_world(ellipse);
  const Ray2 canonical_ray = to_canonical(world, ellipse.C, ray);
  return carry_back(world, ray, canonical_ray, intersect_canonical_circle(canonical_ray));
}

RayRectangle intersect(const Ray2& ray, const Rectangle& rectangle) {
  const Transform2 world = to_world(rectangle);
  const Ray2 canonical_ray = to_canonical(world, rectangle.C, ray);
  return carry_back(world, ray, canonical_ray, intersect_canonical_square(canonical_ray));
}

}  // namespace epure::geo
