#include "geometry/segments.h"

#include <algorithm>
#include <cmath>

#include "geometry/degenerate.h"
#include "geometry/exact_vec.h"
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

  // The parameters are ratios: computed on the figure brought near unit size by a power of two
  // (exact), so that the cross products neither overflow at 1e200 nor underflow at 1e-200.
  const int e = scale.value > 0 ? std::ilogb(scale.value) : 0;
  auto down = [e](Point2 p) { return times_pow2(p, -e); };
  const ExactVec2 AB = exact_difference(down(B), down(A));
  const ExactVec2 CD = exact_difference(down(D), down(C));
  const ExactVec2 AC = exact_difference(down(C), down(A));
  const double ab = plain_norm(AB.hi), cd = plain_norm(CD.hi), ac = plain_norm(AC.hi);
  const Scale unit_scale{times_pow2(scale.value, -e)};
  if (unit_scale.negligible(ab)) throw DegenerateFigure("B", "degenerate segment, A = B");
  if (unit_scale.negligible(cd)) throw DegenerateFigure("D", "degenerate segment, C = D");

  // Cross products of the exact differences, each rounded about once: nearly parallel lines
  // keep the digits of AB∧CD, and with them those of t_ab and t_cd.
  const double ab_cross_cd = cross(AB, CD);
  const double ac_cross_cd = cross(AC, CD), ac_cross_ab = cross(AC, AB);
  s.ab_cross_cd = times_pow2(ab_cross_cd, 2 * e);
  s.ac_cross_cd = times_pow2(ac_cross_cd, 2 * e);
  s.ac_cross_ab = times_pow2(ac_cross_ab, 2 * e);

  // parallel: the sine of the angle between the lines is below the data's rounding
  if (std::abs(ab_cross_cd) <= kRoundoff * ab * cd) {
    // same line when C is on (AB): its distance |AB∧AC| / ‖AB‖ is below rounding of the figure
    double distance_c = std::abs(ac_cross_ab) / ab;
    bool same_line = distance_c <= kRoundoff * std::max({ab, cd, ac});
    s.relation = same_line ? SegmentRelation::collinear : SegmentRelation::parallel;
    return s;
  }

  // Each coordinate of the data is off by half an ulp of the figure (decimal input): that moves
  // t_ab by about ε·(‖AC‖ + ‖AB‖)·‖CD‖ / |AB∧CD|, and t_cd symmetrically. Within that of an end,
  // the segments were meant to touch there.
  double denominator = std::abs(ab_cross_cd);
  double t_ab = snap_to_ends(ac_cross_cd / ab_cross_cd, kRoundoff * (ac + ab) * cd / denominator);
  double t_cd = snap_to_ends(ac_cross_ab / ab_cross_cd, kRoundoff * (ac + cd) * ab / denominator);
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
  else {
    // A + t_ab·AB with AB exact: one rounding per coordinate beyond t_ab's own
    s.I = Point2{A.x + std::fma(t_ab, s.AB.x, t_ab * times_pow2(AB.lo.x, e)),
                 A.y + std::fma(t_ab, s.AB.y, t_ab * times_pow2(AB.lo.y, e))};
  }
  return s;
}

}  // namespace epure::geo
