#pragma once
// Points and vectors of the plane and of space. Points and vectors are distinct types, as in
// pbrt: a point minus a point is a vector, a point plus a vector is a point, and a transform
// moves a point with its translation but a vector without it.
#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/exact.h"

namespace epure::geo {

struct Vec2 {
  double x = 0, y = 0;
};
struct Point2 {
  double x = 0, y = 0;
};
struct Vec3 {
  double x = 0, y = 0, z = 0;
};
struct Point3 {
  double x = 0, y = 0, z = 0;
};

// ---- 2D -------------------------------------------------------------------------------------
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
constexpr Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
constexpr Vec2 operator*(Vec2 a, double k) { return {k * a.x, k * a.y}; }
constexpr Vec2 operator/(Vec2 a, double k) { return {a.x / k, a.y / k}; }
constexpr Vec2 operator-(Point2 b, Point2 a) { return {b.x - a.x, b.y - a.y}; }
constexpr Point2 operator+(Point2 p, Vec2 v) { return {p.x + v.x, p.y + v.y}; }
constexpr Point2 operator-(Point2 p, Vec2 v) { return {p.x - v.x, p.y - v.y}; }

// u·v and u∧v = x_u·y_v − y_u·x_v, each rounded once (Kahan's fma trick), so that a nearly
// perpendicular dot or a nearly parallel cross keeps its sign and its digits.
inline double dot(Vec2 u, Vec2 v) { return exact::sum_of_products(u.x, v.x, u.y, v.y); }
inline double cross(Vec2 u, Vec2 v) { return exact::difference_of_products(u.x, v.y, u.y, v.x); }
inline double norm(Vec2 v) { return std::hypot(v.x, v.y); }
inline double norm2(Vec2 v) { return dot(v, v); }
// The vector turned a quarter turn counter-clockwise: u∧perp(u) = ‖u‖².
constexpr Vec2 perp(Vec2 v) { return {-v.y, v.x}; }
constexpr Vec2 to_vec(Point2 p) { return {p.x, p.y}; }
constexpr Point2 to_point(Vec2 v) { return {v.x, v.y}; }

// v times the power of two that brings its largest coordinate into [1, 2). Exact (a power of two
// only moves the exponent), so that what is computed next neither overflows nor underflows: a
// subnormal vector keeps all its digits, and ‖v‖ of a 1e300 vector is no longer near infinity.
// The zero vector and non-finite ones come back as they are.
inline Vec2 rescaled(Vec2 v) {
  const double m = std::max(std::abs(v.x), std::abs(v.y));
  if (!(m > 0) || !std::isfinite(m)) return v;
  const int e = std::ilogb(m);
  return {std::scalbn(v.x, -e), std::scalbn(v.y, -e)};
}

// The unit vector along v; empty for the zero vector (and anything whose length is not a
// finite positive number). Rescaled first: v / ‖v‖ of a subnormal v would divide rounded
// digits by a rounded length ((5e-324, 5e-324) would give (1, 1)).
inline std::optional<Vec2> normalized(Vec2 v) {
  const double n = norm(v);
  if (!(n > 0) || !std::isfinite(n)) return std::nullopt;
  const Vec2 w = rescaled(v);
  const double nw = norm(w);
  return Vec2{w.x / nw, w.y / nw};
}

// ---- 3D -------------------------------------------------------------------------------------
constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(double k, Vec3 a) { return {k * a.x, k * a.y, k * a.z}; }
constexpr Vec3 operator*(Vec3 a, double k) { return {k * a.x, k * a.y, k * a.z}; }
constexpr Vec3 operator/(Vec3 a, double k) { return {a.x / k, a.y / k, a.z / k}; }
constexpr Vec3 operator-(Point3 b, Point3 a) { return {b.x - a.x, b.y - a.y, b.z - a.z}; }
constexpr Point3 operator+(Point3 p, Vec3 v) { return {p.x + v.x, p.y + v.y, p.z + v.z}; }

inline double dot(Vec3 u, Vec3 v) {
  return exact::sum_of_products(u.x, v.x, u.y, v.y) + u.z * v.z;
}
inline Vec3 cross(Vec3 u, Vec3 v) {
  return {exact::difference_of_products(u.y, v.z, u.z, v.y),
          exact::difference_of_products(u.z, v.x, u.x, v.z),
          exact::difference_of_products(u.x, v.y, u.y, v.x)};
}
inline double norm(Vec3 v) { return std::hypot(v.x, v.y, v.z); }
inline double norm2(Vec3 v) { return dot(v, v); }
constexpr Vec3 to_vec(Point3 p) { return {p.x, p.y, p.z}; }

inline Vec3 rescaled(Vec3 v) {
  const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(m > 0) || !std::isfinite(m)) return v;
  const int e = std::ilogb(m);
  return {std::scalbn(v.x, -e), std::scalbn(v.y, -e), std::scalbn(v.z, -e)};
}

inline std::optional<Vec3> normalized(Vec3 v) {
  const double n = norm(v);
  if (!(n > 0) || !std::isfinite(n)) return std::nullopt;
  const Vec3 w = rescaled(v);
  const double nw = norm(w);
  return Vec3{w.x / nw, w.y / nw, w.z / nw};
}

}  // namespace epure::geo
