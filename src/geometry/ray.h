#pragma once
// Rays and what they hit. A ray is an origin and a direction; its points are origin + t·direction
// for t ≥ 0, and every t the core returns is in units of that direction. Ray2::unit normalises
// the direction, so that t is a length, as the course's rays are (u normé). Rays carried into a
// canonical frame keep their direction as the transform leaves it, so t means the same point in
// both frames (pbrt's convention).
//
// Rounding a direction to unit length turns the line by up to ε about its origin: a figure 1e8
// away sees it moved by ε·1e8 ≈ 2e-8, and an exact tangent becomes a near one. The intersections
// take any direction and are accurate for the line as given; a caller that needs the last digits
// of a far or tangent hit passes the direction unrounded and multiplies t by its length.
#include <optional>

#include "geometry/degenerate.h"
#include "geometry/vec.h"

namespace epure::geo {

struct Ray2 {
  Point2 origin;
  Vec2 direction;

  // Throws DegenerateFigure("u") for a zero direction.
  static Ray2 unit(Point2 origin, Vec2 direction) {
    auto u = normalized(direction);
    if (!u) throw DegenerateFigure("u", "zero direction");
    return {origin, *u};
  }
  Point2 at(double t) const { return origin + t * direction; }
};

struct Ray3 {
  Point3 origin;
  Vec3 direction;

  static Ray3 unit(Point3 origin, Vec3 direction) {
    auto u = normalized(direction);
    if (!u) throw DegenerateFigure("u", "zero direction");
    return {origin, *u};
  }
  Point3 at(double t) const { return origin + t * direction; }
};

// The first point of a figure's boundary on the ray: its parameter, the point, and the unit
// outward normal there.
struct Hit2 {
  double t;
  Point2 I;
  Vec2 N;
};
struct Hit3 {
  double t;
  Point3 I;
  Vec3 N;
};

}  // namespace epure::geo
