#pragma once
// The reference arithmetic of the geometry tests: quadruple precision (113-bit significand), so
// that an expected value computed in the test is exact to far below the tolerances the tests
// check, and never comes from the function under test. GCC and Clang give __float128 on x86-64;
// where long double is itself quadruple (aarch64) it is used; elsewhere long double is the best
// there is and the references are only as good as it.
//
// Differences of two doubles of comparable size are exact in Real, and so are products of two
// doubles: the references see the data exactly as the functions under test receive them.
#include <cfloat>
#include <cmath>

#include "geometry/vec.h"

namespace epure::test {

#if defined(__SIZEOF_FLOAT128__) && LDBL_MANT_DIG < 113
__extension__ typedef __float128 Real;
#else
using Real = long double;
#endif

inline Real abs(Real x) { return x < 0 ? -x : x; }
inline Real max(Real a, Real b) { return a < b ? b : a; }
inline Real min(Real a, Real b) { return a < b ? a : b; }

// √x by Newton's method from the long double root: each step doubles the correct digits.
inline Real sqrt(Real x) {
  if (!(x > 0)) return 0;
  Real y = std::sqrt(static_cast<long double>(x));
  for (int i = 0; i < 2; ++i) y = (y + x / y) / 2;
  return y;
}

// cos and sin of an angle in degrees, reduced to [−45°, 45°] exactly and evaluated in long
// double (64 bits: far below the double rounding the tests allow for).
struct RealCosSin {
  Real cos, sin;
};
inline RealCosSin cos_sin_degrees(double degrees) {
  const long double turns = std::fmod(static_cast<long double>(degrees), 360.0L);
  const long double quarter = std::nearbyint(turns / 90);
  const long double radians =
      (turns - 90 * quarter) * (3.14159265358979323846264338327950288L / 180);
  const Real c = std::cos(radians), s = std::sin(radians);
  switch ((static_cast<int>(quarter) % 4 + 4) % 4) {
    case 0:
      return {c, s};
    case 1:
      return {-s, c};
    case 2:
      return {-c, -s};
    default:
      return {s, -c};
  }
}

struct R2 {
  Real x = 0, y = 0;
};
inline R2 real(geo::Point2 p) { return {p.x, p.y}; }
inline R2 real(geo::Vec2 v) { return {v.x, v.y}; }
inline R2 operator+(R2 a, R2 b) { return {a.x + b.x, a.y + b.y}; }
inline R2 operator-(R2 a, R2 b) { return {a.x - b.x, a.y - b.y}; }
inline R2 operator*(Real k, R2 a) { return {k * a.x, k * a.y}; }
inline R2 operator/(R2 a, Real k) { return {a.x / k, a.y / k}; }
inline Real dot(R2 a, R2 b) { return a.x * b.x + a.y * b.y; }
inline Real cross(R2 a, R2 b) { return a.x * b.y - a.y * b.x; }
inline Real norm(R2 a) { return sqrt(dot(a, a)); }
inline R2 unit(R2 a) { return a / norm(a); }
inline Real distance(R2 a, R2 b) { return norm(a - b); }
// ‖a ∧ b‖², free of the cancellation of ‖a‖²‖b‖² − (a·b)²
inline Real cross_norm2(R2 a, R2 b) { return cross(a, b) * cross(a, b); }

struct R3 {
  Real x = 0, y = 0, z = 0;
};
inline R3 real(geo::Point3 p) { return {p.x, p.y, p.z}; }
inline R3 real(geo::Vec3 v) { return {v.x, v.y, v.z}; }
inline R3 operator+(R3 a, R3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline R3 operator-(R3 a, R3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline R3 operator*(Real k, R3 a) { return {k * a.x, k * a.y, k * a.z}; }
inline R3 operator/(R3 a, Real k) { return {a.x / k, a.y / k, a.z / k}; }
inline Real dot(R3 a, R3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline R3 cross(R3 a, R3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real norm(R3 a) { return sqrt(dot(a, a)); }
inline R3 unit(R3 a) { return a / norm(a); }
inline Real distance(R3 a, R3 b) { return norm(a - b); }
inline Real cross_norm2(R3 a, R3 b) { return dot(cross(a, b), cross(a, b)); }

// Back to double for doctest's Approx and for messages.
inline double d(Real x) { return static_cast<double>(x); }

}  // namespace epure::test
