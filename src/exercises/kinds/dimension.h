#pragma once
// What the plane and space change for a figure family's method (ball_family.h, box_family.h):
// the core's point, vector and ray types, and how a point's steps and answers are named (in the
// plane one name, "I", for I.x and I.y; in space three, "I.x", "I.y", "I.z"). Each family's
// Space<Dim> adds its own figure's types and names to these.
#include <string_view>

#include "exercises/method.h"
#include "geometry/ray.h"
#include "geometry/vec.h"

namespace epure::kinds {

template <int Dim>
struct Dimension;

template <>
struct Dimension<2> {
  using Point = geo::Point2;
  using Vec = geo::Vec2;
  using Ray = geo::Ray2;
  using Name = std::string_view;
};

template <>
struct Dimension<3> {
  using Point = geo::Point3;
  using Vec = geo::Vec3;
  using Ray = geo::Ray3;
  using Name = method::Names3;
};

}  // namespace epure::kinds
