#include "geometry/ray_square.h"

#include "geometry/ray_box.h"
#include "support/fma_clones.h"

namespace epure::geo {

namespace {

RaySquare square_result(const detail::BoxResult<2>& box) {
  RaySquare res{box.faces, box.inside, std::nullopt, box.face};
  if (box.t) {
    Vec2 N{0, 0};
    (box.face->axis == 0 ? N.x : N.y) = box.face->sign;
    res.hit = Hit2{*box.t, {box.I[0], box.I[1]}, N};
  }
  return res;
}

}  // namespace

RaySquare intersect_canonical_square(const Ray2& ray) {
  const Point2 A = ray.origin;
  const Vec2 u = ray.direction;
  return square_result(detail::intersect_box<2>({A.x, A.y}, {u.x, u.y}));
}

EPURE_FMA_KERNEL RaySquare intersect_canonical_square_exact(const Ray2& ray) {
  const Point2 A = ray.origin;
  const Vec2 u = ray.direction;
  return square_result(detail::intersect_box_exact<2>(std::array<double, 2>{A.x, A.y}, std::array<double, 2>{u.x, u.y}));
}

EPURE_FMA_KERNEL RaySquare intersect_canonical_square_exact(const DPoint2& A, const DPoint2& u) {
  return square_result(detail::intersect_box_exact<2>(A, u));
}

}  // namespace epure::geo
