#pragma once
// Points and vectors of the plane and of space. Points and vectors are distinct types, as in
// pbrt: a point minus a point is a vector, a point plus a vector is a point, and a transform
// moves a point with its translation but a vector without it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "geometry/exact.h"
#include "support/portable.h"

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
inline double norm(Vec2 v) { return portable::hypot(v.x, v.y); }
inline double norm2(Vec2 v) { return dot(v, v); }
// The vector turned a quarter turn counter-clockwise: u∧perp(u) = ‖u‖².
constexpr Vec2 perp(Vec2 v) { return {-v.y, v.x}; }
constexpr Vec2 to_vec(Point2 p) { return {p.x, p.y}; }
constexpr Point2 to_point(Vec2 v) { return {v.x, v.y}; }

// ---- Powers of two ---------------------------------------------------------------------------
// Multiplying by 2^k moves the exponent only: exact unless the result under- or overflows. The
// kernels bring their data near unit size this way, so that the squares they compute next
// neither overflow (a figure at 1e200) nor underflow (at 1e-200, or a subnormal direction).

// x·2^k: a multiplication by the power itself whenever it is a double (std::scalbn is a library
// call, and the kernels make several).
inline double times_pow2(double x, int k) {
  if (k < -1022 || k > 1023) return std::scalbn(x, k);
  return x * portable::bit_cast<double>(static_cast<std::uint64_t>(1023 + k) << 52);
}
inline Vec2 times_pow2(Vec2 v, int k) { return {times_pow2(v.x, k), times_pow2(v.y, k)}; }
inline Point2 times_pow2(Point2 p, int k) { return {times_pow2(p.x, k), times_pow2(p.y, k)}; }

// √(x² + y²) without std::hypot's guard against overflow and underflow, for a vector brought
// near unit size first: within an ulp, and several times faster.
inline double plain_norm(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }

// v times the power of two that brings its largest coordinate into [1, 2). A subnormal vector
// keeps all its digits, and ‖v‖ of a 1e300 vector is no longer near infinity. The zero vector
// and non-finite ones come back as they are.
inline Vec2 rescaled(Vec2 v) {
  const double m = std::max(std::abs(v.x), std::abs(v.y));
  if (!(m > 0) || !std::isfinite(m)) return v;
  return times_pow2(v, -std::ilogb(m));
}

// The unit vector along v; empty for the zero vector and for non-finite ones. Rescaled first:
// v / ‖v‖ of a subnormal v would divide rounded digits by a rounded length ((5e-324, 5e-324)
// would give (1, 1)).
inline std::optional<Vec2> normalized(Vec2 v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !(v.x != 0 || v.y != 0)) return std::nullopt;
  const Vec2 w = rescaled(v);
  return w / plain_norm(w);
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
inline double norm(Vec3 v) { return portable::hypot(v.x, v.y, v.z); }
inline double norm2(Vec3 v) { return dot(v, v); }
constexpr Vec3 to_vec(Point3 p) { return {p.x, p.y, p.z}; }

inline Vec3 times_pow2(Vec3 v, int k) {
  return {times_pow2(v.x, k), times_pow2(v.y, k), times_pow2(v.z, k)};
}
inline Point3 times_pow2(Point3 p, int k) {
  return {times_pow2(p.x, k), times_pow2(p.y, k), times_pow2(p.z, k)};
}
inline double plain_norm(Vec3 v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

inline Vec3 rescaled(Vec3 v) {
  const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(m > 0) || !std::isfinite(m)) return v;
  return times_pow2(v, -std::ilogb(m));
}

inline std::optional<Vec3> normalized(Vec3 v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) ||
      !(v.x != 0 || v.y != 0 || v.z != 0))
    return std::nullopt;
  const Vec3 w = rescaled(v);
  return w / plain_norm(w);
}

}  // namespace epure::geo
