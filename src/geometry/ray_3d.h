#pragma once
// The course's closing remark: the methods carry over to 3D. Ray/sphere is ray/circle with a 3D
// cross product; ray/canonical cube [-1,1]³ is the square's method with six faces (at most three
// candidates from outside). Same conventions as ray_circle.h and ray_square.h.
#include <optional>

#include "geometry/box_faces.h"
#include "geometry/ray.h"
#include "geometry/ray_circle.h"

namespace epure::geo {

struct Sphere {
  Point3 C;
  double r;
};

struct RaySphere {
  Vec3 AC;
  double t_proj;
  Point3 P;
  double d2;
  bool inside;
  std::optional<Hit3> hit;
  std::optional<NoHit> reason;
  std::optional<double> half_chord;
};

struct RayCube {
  FaceSet<3> faces;
  bool inside;
  std::optional<Hit3> hit;
  std::optional<Face> face;
};

RaySphere intersect(const Ray3& ray, const Sphere& sphere);
RayCube intersect_canonical_cube(const Ray3& ray);

// Exact for the given doubles, as intersect_exact (ray_circle.h) and
// intersect_canonical_square_exact (ray_square.h); at an edge or a corner, x then y first.
RaySphere intersect_exact(const Ray3& ray, const Sphere& sphere);
// The same for the numbers as written (decimal.h).
RaySphere intersect_exact(const DPoint3& A, const DPoint3& u, const DPoint3& C, const Decimal& r);
PrintedValues<Vec3, Point3> printed_values(const DPoint3& A, const DPoint3& u, const DPoint3& C, const Decimal& r,
                                           const RaySphere& res, double length);
// As printed_values for the circle (ray_circle.h).
PrintedValues<Vec3, Point3> printed_values(const Ray3& ray, const Sphere& sphere, const RaySphere& res,
                                           double length);
RayCube intersect_canonical_cube_exact(const Ray3& ray);
// The same for the numbers as written (decimal.h): A and u (README, "What a number means").
RayCube intersect_canonical_cube_exact(const DPoint3& A, const DPoint3& u);

}  // namespace epure::geo
