#pragma once
// Exercise 4 of the course: ray/canonical square [-1,1]², by its sides. Whatever the origin A,
// at most two sides can be reached first: those whose outer half-plane contains A (the
// candidate sides, `faces`). Each is met where (A + t·u)·n = 1, t = (1 − A·n) / (u·n), if the ray
// heads into it (u·n < 0) and the point lies on the side. A ray that starts inside (no candidate
// side) leaves through the side it meets first. A ray starting on the boundary is outside, its
// side a candidate: heading in, it hits at t = 0. A ray running along a side does not enter the
// square through it (u·n = 0), as in the course.
#include <optional>

#include "geometry/box_faces.h"
#include "geometry/decimal.h"
#include "geometry/ray.h"

namespace epure::geo {

struct RaySquare {
  FaceSet<2> faces;  // candidate sides: closed outer half-planes that contain A
  bool inside;       // A strictly inside the square
  std::optional<Hit2> hit;
  std::optional<Face> face;  // the side hit, with a hit
};

// t in units of ray.direction (which need not be unit length). Throws DegenerateFigure("u") for
// a zero direction.
RaySquare intersect_canonical_square(const Ray2& ray);

// The same with every decision exact for the given doubles (`epure solve`, README): candidate
// sides by σ·A_k ≥ 1 (closed outer half-planes), the side hit by exact comparisons of the
// planes' parameters and of the landing point against the side's ends; at a corner the x side
// is taken first. The hit point lies on the square (coordinates kept within [-1, 1]).
RaySquare intersect_canonical_square_exact(const Ray2& ray);
// The same for the numbers as written (decimal.h): A and u (README, "What a number means").
RaySquare intersect_canonical_square_exact(const DPoint2& A, const DPoint2& u);

}  // namespace epure::geo
