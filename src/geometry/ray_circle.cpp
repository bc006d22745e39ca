#include "geometry/ray_circle.h"

#include "geometry/ray_ball.h"
#include "support/fma_clones.h"

namespace epure::geo {

const char* to_string(NoHit reason) { return reason == NoHit::behind ? "behind" : "miss"; }

RayCircle intersect(const Ray2& ray, const Circle& circle) {
  return detail::intersect_ball<RayCircle, Hit2>(ray, circle.C, circle.r);
}

RayCircle intersect_canonical_circle(const Ray2& ray) { return intersect(ray, Circle{{0, 0}, 1.0}); }

EPURE_FMA_KERNEL RayCircle intersect_exact(const Ray2& ray, const Circle& circle) {
  return detail::intersect_ball_exact<RayCircle, Hit2>(ray, circle.C, circle.r);
}

EPURE_FMA_KERNEL RayCircle intersect_exact(const DPoint2& A, const DPoint2& u, const DPoint2& C, const Decimal& r) {
  return detail::intersect_ball_exact<RayCircle, Hit2, Ray2>(A, u, C, r);
}

EPURE_FMA_KERNEL PrintedValues<Vec2, Point2> printed_values(const DPoint2& A, const DPoint2& u, const DPoint2& C,
                                                            const Decimal& r, const RayCircle& res, double length) {
  return detail::printed_values(A, u, C, r, res, length);
}

EPURE_FMA_KERNEL PrintedValues<Vec2, Point2> printed_values(const Ray2& ray, const Circle& circle,
                                                            const RayCircle& res, double length) {
  return detail::printed_values(ray, circle.C, circle.r, res, length);
}

RayCircle intersect_canonical_circle_exact(const Ray2& ray) {
  return intersect_exact(ray, Circle{{0, 0}, 1.0});
}

}  // namespace epure::geo
