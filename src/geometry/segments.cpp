#include "geometry/segments.h"

#include <algorithm>

#include "geometry/degenerate.h"
#include "geometry/tolerance.h"

namespace epure::geo {

const char* to_string(SegmentRelation r) {
  switch (r) {
    case SegmentRelation::intersects: return "intersects";
    case SegmentRelation::outside: return "outside";
    case SegmentRelation::parallel: return "parallel";
    case SegmentRelation::collinear: return "collinear";
  }
  return "?";
}

namespace {

// A parameter within `tolerance` of 0 or 1 is on that end of its segment.
double snap_to_ends(double t, double tolerance) {
  Near near{tolerance};
  if (near.on(t, 0.0)) return 0.0;
  if (near.on(t, 1.0)) return 1.0;
  return t;
}

bool in_unit_interval(double t) { return t >= 0.0 && t <= 1.0; }

}  // namespace

SegmentIntersection intersect_segments(Point2 A, Point2 B, Point2 C, Point2 D) {
  Scale scale = Scale::of({A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
  SegmentIntersection s{};
  s.AB = B - A;
  s.CD = D - C;
  s.AC = C - A;
  double ab = norm(s.AB), cd = norm(s.CD), ac = norm(s.AC);
  if (scale.negligible(ab)) throw DegenerateFigure("B", "degenerate segment, A = B");
  if (scale.negligible(cd)) throw DegenerateFigure("D", "degenerate segment, C = D");

  s.ab_cross_cd = cross(s.AB, s.CD);
  s.ac_cross_cd = cross(s.AC, s.CD);
  s.ac_cross_ab = cross(s.AC, s.AB);

  // parallel: the sine of the angle between the lines is below rounding
  if (std::abs(s.ab_cross_cd) <= kRoundoff * ab * cd) {
    // same line when C is on (AB): its distance |AB∧AC| / ‖AB‖ is below rounding of the figure
    double distance_c = std::abs(s.ac_cross_ab) / ab;
    bool same_line = distance_c <= kRoundoff * std::max({ab, cd, ac});
    s.relation = same_line ? SegmentRelation::collinear : SegmentRelation::parallel;
    return s;
  }

  // Each parameter carries the rounding of its numerator and of the denominator, in units of
  // the denominator: ε·(‖AC‖ + ‖AB‖)·‖CD‖ / |AB∧CD| for t_ab, and symmetrically for t_cd.
  double denominator = std::abs(s.ab_cross_cd);
  double t_ab = snap_to_ends(s.ac_cross_cd / s.ab_cross_cd, kRoundoff * (ac + ab) * cd / denominator);
  double t_cd = snap_to_ends(s.ac_cross_ab / s.ab_cross_cd, kRoundoff * (ac + cd) * ab / denominator);
  s.t_ab = t_ab;
  s.t_cd = t_cd;
  if (!in_unit_interval(t_ab) || !in_unit_interval(t_cd)) {
    s.relation = SegmentRelation::outside;
    return s;
  }
  s.relation = SegmentRelation::intersects;
  // An end that the other segment touches is the intersection itself, to the last bit.
  if (t_ab <= 0.0) s.I = A;
  else if (t_ab >= 1.0) s.I = B;
  else if (t_cd <= 0.0) s.I = C;
  else if (t_cd >= 1.0) s.I = D;
  else s.I = A + t_ab * s.AB;
  return s;
}

}  // namespace epure::geo
