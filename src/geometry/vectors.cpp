#include "geometry/vectors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/degenerate.h"

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

VectorPair compare_vectors(Vec2 u, Vec2 v) {
  double norm_u = norm(u), norm_v = norm(v);
  // Exact zero is the only danger here (a division by zero): a tiny vector still has a direction.
  if (!(norm_u > 0)) throw DegenerateFigure("u", "zero vector has no direction");
  if (!(norm_v > 0)) throw DegenerateFigure("v", "zero vector has no direction");

  VectorPair r{};
  r.dot = dot(u, v);
  r.cross = cross(u, v);
  r.norm_u = norm_u;
  r.norm_v = norm_v;
  // cos = u·v / ‖u‖‖v‖ and sin = u∧v / ‖u‖‖v‖ from the data's own products, each rounded about
  // once, so that the sine of nearly parallel vectors keeps its digits (normalising u and v
  // first would leave it an absolute error of ε). Exact power-of-two rescaling keeps the
  // products from overflowing or underflowing for extreme (even subnormal) vectors.
  const Vec2 us = rescaled(u), vs = rescaled(v);
  const double lengths = plain_norm(us) * plain_norm(vs);
  r.cos = std::clamp(dot(us, vs) / lengths, -1.0, 1.0);
  r.sin = std::clamp(cross(us, vs) / lengths, -1.0, 1.0);
  r.angle_deg = angle_degrees(r.cos, r.sin);
  return r;
}

VectorPair3 compare_vectors_3d(Vec3 u, Vec3 v) {
  const double norm_u = norm(u), norm_v = norm(v);
  if (!(norm_u > 0)) throw DegenerateFigure("u", "zero vector has no direction");
  if (!(norm_v > 0)) throw DegenerateFigure("v", "zero vector has no direction");
  VectorPair3 r{};
  r.dot = dot(u, v);
  r.cross = cross(u, v);
  r.norm_u = norm_u;
  r.norm_v = norm_v;
  // as in the plane: from the data's own products, rescaled by powers of two
  const Vec3 us = rescaled(u), vs = rescaled(v);
  const double lengths = plain_norm(us) * plain_norm(vs);
  r.cos = std::clamp(dot(us, vs) / lengths, -1.0, 1.0);
  r.sin = std::clamp(norm(cross(us, vs)) / lengths, 0.0, 1.0);
  r.angle_deg = angle_degrees(r.cos, r.sin);  // correctly rounded, as in the plane
  r.collinear = r.sin <= kCollinearSin;
  r.orthogonal = std::abs(r.cos) <= kCollinearSin;
  return r;
}

}  // namespace epure::geo
