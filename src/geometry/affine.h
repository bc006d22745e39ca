#pragma once
// Affine maps of the plane, kept with their inverse (as pbrt's Transform keeps m and mInv), so
// that a point moves with the translation, a direction without it, and a normal by the inverse
// transpose: the three things a ray needs to visit a canonical figure's frame and come back.
#include "geometry/vec.h"

namespace epure::geo {

// x' = a·x + b·y + e,  y' = c·x + d·y + f
struct Affine2Matrix {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
};

class Transform2 {
 public:
  Transform2() = default;
  // Throws DegenerateFigure("transform") for a singular matrix (no inverse).
  explicit Transform2(const Affine2Matrix& m);

  static Transform2 translate(Vec2 by);
  // Counter-clockwise rotation by `degrees`; quarter turns are exact (cos 90° is 0, not 6e-17).
  static Transform2 rotate_degrees(double degrees);
  // Throws DegenerateFigure("scale") unless both factors are non-zero.
  static Transform2 scale(double sx, double sy);

  // (this ∘ inner): apply `inner` first, then this.
  Transform2 operator*(const Transform2& inner) const;
  Transform2 inverse() const { return Transform2(inv_, m_); }

  Point2 apply(Point2 p) const;
  Vec2 apply(Vec2 v) const;
  // A normal n of a curve maps to (M⁻¹)ᵀ·n, which stays perpendicular to the mapped tangents.
  // Not renormalised: the caller decides.
  Vec2 apply_normal(Vec2 n) const;

  const Affine2Matrix& matrix() const { return m_; }
  const Affine2Matrix& inverse_matrix() const { return inv_; }

 private:
  Transform2(const Affine2Matrix& m, const Affine2Matrix& inv) : m_(m), inv_(inv) {}
  Affine2Matrix m_, inv_;
};

// cos and sin of an angle in degrees, exact at multiples of 90°.
struct CosSin {
  double cos, sin;
};
CosSin cos_sin_degrees(double degrees);

}  // namespace epure::geo
