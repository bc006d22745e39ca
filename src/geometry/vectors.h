#pragma once
// The preamble of the course: what the dot and cross products tell of two vectors.
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

// atan2(sin, cos) in degrees, folded into (−180, 180] (atan2(−0, −1) is −180: we say 180).
double angle_degrees(double cos, double sin);

}  // namespace epure::geo
