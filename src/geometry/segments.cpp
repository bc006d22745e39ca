#include "geometry/segments.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/decimal_vec.h"
#include "geometry/degenerate.h"
#include "geometry/exact_vec.h"
#include "geometry/exponent.h"
#include "geometry/predicates.h"
#include "geometry/tolerance.h"
#include "support/fma_clones.h"

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
  const int e = scale.value > 0 ? binary_exponent(scale.value) : 0;
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

namespace {

// A line parameter t = n / den, rounded about once, and its place against [0, 1], exact: the
// sign of n against 0, of m = den − n against 1, each times that of den.
struct Parameter {
  double t;
  int end;  // −1 below 0, 0 within [0, 1], +1 above 1
  bool at_start, at_finish;  // t = 0 or t = 1 exactly
  double back = 1;  // 1 − t to its own digits, when t ≥ 1/2 (else 1)
};

// n, the numerator (its sign exact); den the denominator (sign exact, non-zero); m(), the exact
// complement den − n, computed only when t is near 1 or beyond.
template <class Complement>
Parameter parameter(const Certain& n, const Certain& den, Complement m) {
  Parameter p{};
  const int sn = n.sign * den.sign;  // the sign of t
  if (sn == 0) {
    p.t = 0;
    p.at_start = true;
    return p;
  }
  const double t = n.value / den.value;  // within 1.5 ulps (as project_exact's t)
  if (sn < 0) {
    p.t = std::min(t, -std::numeric_limits<double>::denorm_min());  // < 0, as its sign says
    p.end = -1;
    return p;
  }
  if (t < 0.5) {  // 0 < t < 1 for sure
    p.t = t;
    return p;
  }
  // t itself from n / den (rounded about once), its place against 1 from den − n
  const Certain rest = m();  // den − n: 1 − t = rest / den
  const int sr = rest.sign * den.sign;
  p.back = rest.value / den.value;
  if (sr == 0) {
    p.t = 1;
    p.at_finish = true;
  } else if (sr < 0) {
    p.t = std::max(t, std::nextafter(1.0, 2.0));  // > 1
    p.end = 1;
  } else {
    p.t = std::min(t, 1.0);
  }
  return p;
}

}  // namespace

SegmentIntersection intersect_segments_exact(Point2 A, Point2 B, Point2 C, Point2 D) {
  return intersect_segments_exact(decimal_point(A), decimal_point(B), decimal_point(C), decimal_point(D));
}

EPURE_FMA_KERNEL SegmentIntersection intersect_segments_exact(const DPoint2& dA, const DPoint2& dB, const DPoint2& dC,
                                                              const DPoint2& dD) {
  const Point2 A = hi_point(dA), B = hi_point(dB), C = hi_point(dC), D = hi_point(dD);
  Scale scale = Scale::of({A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
  SegmentIntersection s{};
  s.AB = B - A;
  s.CD = D - C;
  s.AC = C - A;
  // A segment only when its ends differ as numbers (two decimals may share their double).
  if (same_value(dA[0], dB[0]) && same_value(dA[1], dB[1])) throw DegenerateFigure("B", "degenerate segment, A = B");
  if (same_value(dC[0], dD[0]) && same_value(dC[1], dD[1])) throw DegenerateFigure("D", "degenerate segment, C = D");

  // The parameters are ratios: computed on the figure brought near unit size by a power of two
  // (exact), so that the cross products neither overflow at 1e200 nor underflow at 1e-200.
  const int e = scale.value > 0 ? binary_exponent(scale.value) : 0;
  const ExactVec2 AB = decimal_difference(dB, dA, e);
  const ExactVec2 CD = decimal_difference(dD, dC, e);
  const ExactVec2 AC = decimal_difference(dC, dA, e);

  // Cross products of the exact differences, their signs exact (predicates.h).
  const Certain ab_cross_cd = certain_cross(AB, CD);
  const Certain ac_cross_cd = certain_cross(AC, CD), ac_cross_ab = certain_cross(AC, AB);
  s.ab_cross_cd = times_pow2(ab_cross_cd.value, 2 * e);
  s.ac_cross_cd = times_pow2(ac_cross_cd.value, 2 * e);
  s.ac_cross_ab = times_pow2(ac_cross_ab.value, 2 * e);

  // parallel: AB∧CD = 0 exactly; the same line when C is on (AB) too (AC∧AB = 0)
  if (ab_cross_cd.sign == 0) {
    s.relation = ac_cross_ab.sign == 0 ? SegmentRelation::collinear : SegmentRelation::parallel;
    return s;
  }

  // t_ab = AC∧CD / AB∧CD, 1 − t_ab = CB∧CD / AB∧CD (AB − AC = CB);
  // t_cd = AC∧AB / AB∧CD, 1 − t_cd = AB∧AD / AB∧CD (AB∧CD + AB∧AC = AB∧AD).
  const Parameter t_ab = parameter(ac_cross_cd, ab_cross_cd,
                                   [&] { return certain_cross(decimal_difference(dB, dC, e), CD); });
  const Parameter t_cd = parameter(ac_cross_ab, ab_cross_cd,
                                   [&] { return certain_cross(AB, decimal_difference(dD, dA, e)); });
  s.t_ab = t_ab.t;
  s.t_cd = t_cd.t;
  if (t_ab.end != 0 || t_cd.end != 0) {
    s.relation = SegmentRelation::outside;
    return s;
  }
  s.relation = SegmentRelation::intersects;
  const Vec2 ab_hi = times_pow2(AB.hi, e);  // B − A rounded (with the decimals' rests: s.AB for doubles)
  // An end that the other segment touches is the intersection itself, to the last bit.
  if (t_ab.at_start) s.I = A;
  else if (t_ab.at_finish) s.I = B;
  else if (t_cd.at_start) s.I = C;
  else if (t_cd.at_finish) s.I = D;
  else if (constexpr double kNearB = 0x1p-20; std::abs(t_ab.back) < kNearB) {
    // within 2^-20 of B (no worksheet's crossing is): B − (1 − t_ab)·AB, where A + t_ab·AB would carry t_ab's rounding
    s.I = Point2{B.x - (std::fma(t_ab.back, ab_hi.x, t_ab.back * times_pow2(AB.lo.x, e)) - dB[0].lo),
                 B.y - (std::fma(t_ab.back, ab_hi.y, t_ab.back * times_pow2(AB.lo.y, e)) - dB[1].lo)};
  } else {
    // A + t_ab·AB with AB exact: one rounding per coordinate beyond t_ab's own (and A's
    // decimal rest with it)
    s.I = Point2{A.x + (std::fma(t_ab.t, ab_hi.x, t_ab.t * times_pow2(AB.lo.x, e)) + dA[0].lo),
                 A.y + (std::fma(t_ab.t, ab_hi.y, t_ab.t * times_pow2(AB.lo.y, e)) + dA[1].lo)};
  }
  return s;
}

}  // namespace epure::geo
