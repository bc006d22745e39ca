#pragma once
// The course's open questions: "does this work for any ellipse? any rectangle?" — yes, through
// transformations. An ellipse is the canonical circle and a rectangle the canonical square, put
// in place by T = translate(C) ∘ rotate(angle) ∘ scale(radii or half-sizes). The ray is carried
// into the canonical frame by T⁻¹ (its origin as a point, its direction as a vector, not
// renormalised, so that t names the same point in both frames), solved there by the canonical
// method, and the normal is carried back by the inverse transpose. A ray from far away is solved
// again from a point of it near the figure, so that the hit keeps the figure's digits rather
// than those of |A − C|; `canonical_ray` and `canonical` stay those seen from A.
#include "geometry/affine.h"
#include "geometry/ray_circle.h"
#include "geometry/ray_square.h"

namespace epure::geo {

struct Ellipse {
  Point2 C;
  double a, b;       // radii along its own axes
  double angle_deg;  // counter-clockwise rotation of the a-axis from the x-axis
};

struct Rectangle {
  Point2 C;
  double w, h;       // half-sizes along its own axes
  double angle_deg;  // counter-clockwise rotation of the w-axis from the x-axis
};

// canonical → world, for an ellipse or a rectangle. Throws DegenerateFigure("radii" / "half")
// for a radius or half-size ≤ 0 (or not finite), and ("angle") for an angle that is not finite.
Transform2 to_world(const Ellipse& e);
Transform2 to_world(const Rectangle& r);

template <class Canonical>
struct RayTransformed {
  Transform2 to_world;  // canonical → world
  Ray2 canonical_ray;   // (Ac, uc) = T⁻¹ of the ray
  Canonical canonical;  // the canonical figure's solution, in its frame
  bool inside;          // A strictly inside the figure
  std::optional<Hit2> hit;  // in the world frame, N unit and outward
};
using RayEllipse = RayTransformed<RayCircle>;
using RayRectangle = RayTransformed<RaySquare>;

// t in units of ray.direction.
RayEllipse intersect(const Ray2& ray, const Ellipse& ellipse);
RayRectangle intersect(const Ray2& ray, const Rectangle& rectangle);

// The same, solved in the canonical frame by the exact canonical kernels: the decisions are
// exact for the carried ray (A − C and u turned and scaled in doubles). That ray is exact when
// the angle is a multiple of 90° and the sizes are powers of two; otherwise the carrying rounds
// (cos and sin of a decimal angle are not exact), and so, within ~1e-15 of a boundary, may the
// decision (README, `epure solve`).
RayEllipse intersect_exact(const Ray2& ray, const Ellipse& ellipse);
RayRectangle intersect_exact(const Ray2& ray, const Rectangle& rectangle);

namespace detail {
// The world normal at the canonical normal n, by the inverse transpose, unit (turned_written.cpp
// rebuilds hits with it). Throws DegenerateFigure(size_field) beyond what doubles can draw.
Vec2 world_normal(const Transform2& world, Vec2 n, const char* size_field);
}  // namespace detail

}  // namespace epure::geo
