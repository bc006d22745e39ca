#pragma once
// The preamble of the course: what the dot and cross products tell of two vectors.
#include "geometry/decimal.h"
#include "geometry/vec.h"

namespace epure::geo {

struct VectorPair {
  double dot;        // u·v
  double cross;      // u∧v = x_u·y_v − y_u·x_v
  double norm_u, norm_v;
  double cos, sin;   // of the signed angle from u to v: u·v = ‖u‖‖v‖cos, u∧v = ‖u‖‖v‖sin
  double angle_deg;  // that angle in degrees, in (−180, 180]
};

// Throws DegenerateFigure("u" or "v") for a zero vector: it has no direction, so no angle.
VectorPair compare_vectors(Vec2 u, Vec2 v);
// The same for the numbers as written (decimal.h; README, "What a number means"): the signs of
// u·v and u∧v exact for the decimals (u∧v = 0 for vectors parallel as written), their values to
// about an ulp of the decimals' products.
VectorPair compare_decimal_vectors(const DPoint2& u, const DPoint2& v);

// The preamble in space (ℝ³): u∧v is a vector, and the angle is unsigned (no orientation of a
// plane is given), in [0°, 180°].
struct VectorPair3 {
  double dot;
  Vec3 cross;        // u∧v = (y_u z_v − z_u y_v, z_u x_v − x_u z_v, x_u y_v − y_u x_v)
  double norm_u, norm_v;
  double cos, sin;   // u·v = ‖u‖‖v‖cos θ, ‖u∧v‖ = ‖u‖‖v‖sin θ (sin ≥ 0)
  double angle_deg;  // θ in [0, 180]
  bool collinear;    // u∧v = 0 exactly
  bool orthogonal;   // u·v = 0 exactly
};

// Throws DegenerateFigure("u" or "v") for a zero vector. The decisions are exact: for the doubles
// given as such, or for the numbers as written (decimal.h; README, "What a number means"): u∧v = 0
// for vectors collinear as written (0.3·(0.1, 0.2, 0.3)), u·v = 0 for orthogonal ones, whatever
// their rounding in binary.
VectorPair3 compare_vectors_3d(Vec3 u, Vec3 v);
VectorPair3 compare_decimal_vectors_3d(const DPoint3& u, const DPoint3& v);

// atan2(sin, cos) in degrees, in (−180, 180] and of the sine's sign: atan2(−0, −1) is −180, we
// say 180; a negative sine whose angle rounds to −180 gives −179.99999999999997.
double angle_degrees(double cos, double sin);

}  // namespace epure::geo
