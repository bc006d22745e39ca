#include "geometry/ray_square.h"

#include "geometry/ray_box.h"

namespace epure::geo {

std::string_view face_name(Face f) {
  static constexpr std::array<std::string_view, 3> plus{"+x", "+y", "+z"};
  static constexpr std::array<std::string_view, 3> minus{"-x", "-y", "-z"};
  return f.sign > 0 ? plus[f.axis] : minus[f.axis];
}

RaySquare intersect_canonical_square(const Ray2& ray) {
  const Point2 A = ray.origin;
  const Vec2 u = ray.direction;
  auto box = detail::intersect_box<2>({A.x, A.y}, {u.x, u.y});
  RaySquare res{box.faces, box.inside, std::nullopt, box.face};
  if (box.t) {
    Vec2 N{0, 0};
    (box.face->axis == 0 ? N.x : N.y) = box.face->sign;
    res.hit = Hit2{*box.t, {box.I[0], box.I[1]}, N};
  }
  return res;
}

}  // namespace epure::geo
