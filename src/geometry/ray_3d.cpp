#include "geometry/ray_3d.h"

#include "geometry/ray_ball.h"
#include "geometry/ray_box.h"
#include "support/fma_clones.h"

namespace epure::geo {

RaySphere intersect(const Ray3& ray, const Sphere& sphere) {
  return detail::intersect_ball<RaySphere, Hit3>(ray, sphere.C, sphere.r);
}

namespace {

RayCube cube_result(const detail::BoxResult<3>& box) {
  RayCube res{box.faces, box.inside, std::nullopt, box.face};
  if (box.t) {
    double n[3] = {0, 0, 0};
    n[box.face->axis] = box.face->sign;
    res.hit = Hit3{*box.t, {box.I[0], box.I[1], box.I[2]}, {n[0], n[1], n[2]}};
  }
  return res;
}

}  // namespace

RayCube intersect_canonical_cube(const Ray3& ray) {
  const Point3 A = ray.origin;
  const Vec3 u = ray.direction;
  return cube_result(detail::intersect_box<3>({A.x, A.y, A.z}, {u.x, u.y, u.z}));
}

EPURE_FMA_KERNEL RaySphere intersect_exact(const Ray3& ray, const Sphere& sphere) {
  return detail::intersect_ball_exact<RaySphere, Hit3>(ray, sphere.C, sphere.r);
}

EPURE_FMA_KERNEL RaySphere intersect_exact(const DPoint3& A, const DPoint3& u, const DPoint3& C, const Decimal& r) {
  return detail::intersect_ball_exact<RaySphere, Hit3, Ray3>(A, u, C, r);
}

EPURE_FMA_KERNEL PrintedValues<Vec3, Point3> printed_values(const DPoint3& A, const DPoint3& u, const DPoint3& C,
                                                            const Decimal& r, const RaySphere& res, double length) {
  return detail::printed_values(A, u, C, r, res, length);
}

EPURE_FMA_KERNEL PrintedValues<Vec3, Point3> printed_values(const Ray3& ray, const Sphere& sphere,
                                                            const RaySphere& res, double length) {
  return detail::printed_values(ray, sphere.C, sphere.r, res, length);
}

EPURE_FMA_KERNEL RayCube intersect_canonical_cube_exact(const Ray3& ray) {
  const Point3 A = ray.origin;
  const Vec3 u = ray.direction;
  return cube_result(detail::intersect_box_exact<3>(std::array<double, 3>{A.x, A.y, A.z}, std::array<double, 3>{u.x, u.y, u.z}));
}

EPURE_FMA_KERNEL RayCube intersect_canonical_cube_exact(const DPoint3& A, const DPoint3& u) {
  return cube_result(detail::intersect_box_exact<3>(A, u));
}

}  // namespace epure::geo
