#include "geometry/vectors.h"

#include <algorithm>
#include <numbers>

#include "geometry/degenerate.h"

namespace epure::geo {

double angle_degrees(double cos, double sin) {
  double degrees = std::atan2(sin, cos) * (180.0 / std::numbers::pi);
  // atan2 returns −π for a negative zero sine: the contract's interval is (−180, 180].
  return degrees <= -180.0 ? 180.0 : degrees;
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
  // Normalising first keeps ‖u‖‖v‖ from overflowing or underflowing for extreme vectors.
  Vec2 uh = u / norm_u, vh = v / norm_v;
  r.cos = std::clamp(dot(uh, vh), -1.0, 1.0);
  r.sin = std::clamp(cross(uh, vh), -1.0, 1.0);
  r.angle_deg = angle_degrees(r.cos, r.sin);
  return r;
}

}  // namespace epure::geo
