#include "geometry/vectors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/decimal_vec.h"
#include "geometry/degenerate.h"
#include "geometry/exponent.h"
#include "geometry/predicates.h"
#include "support/fma_clones.h"

namespace epure::geo {

double angle_degrees(double cos, double sin) {
  // correctly rounded: the same bits everywhere (portable.h)
  double degrees = portable::atan2(sin, cos) * (180.0 / std::numbers::pi);
  // −180 is outside the contract's (−180, 180]. A zero sine (atan2(−0, −1) = −π) is 180; a
  // negative one is an angle just above −180 that rounded to it, whose nearest double in the
  // interval is the next one up: 180 would contradict the sine's sign.
  if (degrees <= -180.0) return sin < 0 ? std::nextafter(-180.0, 0.0) : 180.0;
  return degrees;
}

// cos = u·v / ‖u‖‖v‖ and sin = u∧v / ‖u‖‖v‖ from the data's own products, each to about an
// ulp, so that the sine of nearly parallel vectors keeps its digits (normalising u and v first
// would leave it an absolute error of ε). Exact power-of-two rescaling keeps the products from
// overflowing or underflowing for extreme (even subnormal) vectors.
EPURE_FMA_KERNEL VectorPair compare_decimal_vectors(const DPoint2& du, const DPoint2& dv) {
  const Vec2 u = hi_vec(du), v = hi_vec(dv);
  const double norm_u = norm(u), norm_v = norm(v);
  if (!(norm_u > 0)) throw DegenerateFigure("u", "zero vector has no direction");
  if (!(norm_v > 0)) throw DegenerateFigure("v", "zero vector has no direction");
  // u·2^-fu and v·2^-fv near unit size (exact), with their decimals' rests
  const int fu = binary_exponent(std::max(std::abs(u.x), std::abs(u.y)));
  const int fv = binary_exponent(std::max(std::abs(v.x), std::abs(v.y)));
  const ExactVec2 U = decimal_vector(du, fu), V = decimal_vector(dv, fv);
  const Certain d = certain_dot(U, V), c = certain_cross(U, V);
  VectorPair r{};
  r.dot = times_pow2(d.value + d.lo, fu + fv);
  r.cross = times_pow2(c.value + c.lo, fu + fv);
  r.norm_u = norm_u;
  r.norm_v = norm_v;
  const double lengths = plain_norm(U.hi) * plain_norm(V.hi);
  r.cos = std::clamp((d.value + d.lo) / lengths, -1.0, 1.0);
  r.sin = std::clamp((c.value + c.lo) / lengths, -1.0, 1.0);
  r.angle_deg = angle_degrees(r.cos, r.sin);
  return r;
}

EPURE_FMA_KERNEL VectorPair3 compare_decimal_vectors_3d(const DPoint3& du, const DPoint3& dv) {
  const Vec3 u = hi_vec(du), v = hi_vec(dv);
  const double norm_u = norm(u), norm_v = norm(v);
  if (!(norm_u > 0)) throw DegenerateFigure("u", "zero vector has no direction");
  if (!(norm_v > 0)) throw DegenerateFigure("v", "zero vector has no direction");
  const int fu = binary_exponent(std::max({std::abs(u.x), std::abs(u.y), std::abs(u.z)}));
  const int fv = binary_exponent(std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}));
  const ExactVec3 U = decimal_vector(du, fu), V = decimal_vector(dv, fv);
  const Certain d = certain_dot(U, V);
  const Certain cx = certain_cross(U, V, 0), cy = certain_cross(U, V, 1), cz = certain_cross(U, V, 2);
  const Vec3 w{cx.value + cx.lo, cy.value + cy.lo, cz.value + cz.lo};  // u∧v·2^-(fu+fv)
  VectorPair3 r{};
  r.dot = times_pow2(d.value + d.lo, fu + fv);
  r.cross = {times_pow2(w.x, fu + fv), times_pow2(w.y, fu + fv), times_pow2(w.z, fu + fv)};
  r.norm_u = norm_u;
  r.norm_v = norm_v;
  const double lengths = plain_norm(U.hi) * plain_norm(V.hi);
  r.cos = std::clamp((d.value + d.lo) / lengths, -1.0, 1.0);
  r.sin = std::clamp(norm(w) / lengths, 0.0, 1.0);
  r.angle_deg = angle_degrees(r.cos, r.sin);
  r.collinear = cx.sign == 0 && cy.sign == 0 && cz.sign == 0;
  r.orthogonal = d.sign == 0;
  return r;
}

// Doubles as themselves: the same code.
VectorPair compare_vectors(Vec2 u, Vec2 v) { return compare_decimal_vectors(decimal_point(u), decimal_point(v)); }
VectorPair3 compare_vectors_3d(Vec3 u, Vec3 v) {
  return compare_decimal_vectors_3d(decimal_point(u), decimal_point(v));
}

}  // namespace epure::geo
