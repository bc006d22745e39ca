#include "geometry/projection.h"

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

const char* to_string(Position p) {
  switch (p) {
    case Position::before: return "before";
    case Position::between: return "between";
    case Position::after: return "after";
  }
  return "?";
}

Projection project(Point2 A, Point2 B, Point2 C) {
  Scale scale = Scale::of({A.x, A.y, B.x, B.y, C.x, C.y});
  Projection p{};
  p.AB = B - A;
  p.AC = C - A;
  // t is a ratio: computed on the figure brought near unit size by a power of two (exact), so
  // that AB·AB neither underflows at 1e-200 nor overflows at 1e200.
  const int e = scale.value > 0 ? binary_exponent(scale.value) : 0;
  const ExactVec2 AB = exact_difference(times_pow2(B, -e), times_pow2(A, -e));
  const ExactVec2 AC = exact_difference(times_pow2(C, -e), times_pow2(A, -e));
  const double ab_length = plain_norm(AB.hi);
  if (Scale{times_pow2(scale.value, -e)}.negligible(ab_length))
    throw DegenerateFigure("B", "degenerate segment, A = B");

  // (AC − t·AB)·AB = 0  =>  t = AB·AC / AB·AB, each product of the exact differences rounded
  // about once: t keeps its digits even when AC is nearly perpendicular to AB (t ≈ 0).
  const double ab_dot_ac = dot(AB, AC), ab_dot_ab = dot(AB, AB);
  p.t = ab_dot_ac / ab_dot_ab;
  p.ab_dot_ac = times_pow2(ab_dot_ac, 2 * e);
  p.ab_dot_ab = times_pow2(ab_dot_ab, 2 * e);

  // The data are decimal numbers rounded to doubles, each off by half an ulp: a t within a few
  // ε of ‖AC‖/‖AB‖ of 0 or 1 puts P on an end of the segment, as the figure meant.
  Near near{kRoundoff * (plain_norm(AC.hi) / ab_length + 1)};
  if (near.on(p.t, 0.0)) {
    p.t = 0.0;
    p.P = A;
  } else if (near.on(p.t, 1.0)) {
    p.t = 1.0;
    p.P = B;
  } else {
    // A + t·AB with AB exact: one rounding per coordinate beyond t's own
    p.P = {A.x + std::fma(p.t, p.AB.x, p.t * times_pow2(AB.lo.x, e)),
           A.y + std::fma(p.t, p.AB.y, p.t * times_pow2(AB.lo.y, e))};
  }
  p.position = p.t < 0 ? Position::before : p.t > 1 ? Position::after : Position::between;
  return p;
}

Projection project_exact(Point2 A, Point2 B, Point2 C) {
  return project_exact(decimal_point(A), decimal_point(B), decimal_point(C));
}

EPURE_FMA_KERNEL Projection project_exact(const DPoint2& dA, const DPoint2& dB, const DPoint2& dC) {
  const Point2 A = hi_point(dA), B = hi_point(dB), C = hi_point(dC);
  Scale scale = Scale::of({A.x, A.y, B.x, B.y, C.x, C.y});
  Projection p{};
  p.AB = B - A;
  p.AC = C - A;
  // A segment only when A ≠ B as numbers (two decimals may share their nearest double).
  if (same_value(dA[0], dB[0]) && same_value(dA[1], dB[1])) throw DegenerateFigure("B", "degenerate segment, A = B");
  // t is a ratio: computed on the figure brought near unit size by a power of two (exact), so
  // that AB·AB neither underflows at 1e-200 nor overflows at 1e200.
  const int e = scale.value > 0 ? binary_exponent(scale.value) : 0;
  const ExactVec2 AB = decimal_difference(dB, dA, e), AC = decimal_difference(dC, dA, e);

  // (AC − t·AB)·AB = 0  =>  t = AB·AC / AB·AB. The position is the sign of AB·AC (t < 0) and of
  // AB·BC = AB·AC − AB·AB (t > 1), each exact for the given doubles (predicates.h).
  const Certain ab_dot_ac = certain_dot(AB, AC);
  const exact::TwoTerm ab_ab = detail::compensated_dot(AB, AB);  // > 0
  const double ab_dot_ab = ab_ab.hi;
  // t = AB·AC / AB·AB of the products rounded about once: within 1.5 ulps of t (the quotient
  // of the double-doubles, predicates.h, would halve that, but change the last bit of answers
  // that worksheet keys already print)
  auto ratio = [&](const Certain& n) { return n.value / ab_ab.hi; };
  p.ab_dot_ac = times_pow2(ab_dot_ac.value, 2 * e);
  p.ab_dot_ab = times_pow2(ab_dot_ab, 2 * e);
  // A + t·AB with AB exact: one rounding per coordinate beyond t's own
  // (the decimal's rest of `from` added with AB's: nothing for doubles)
  auto along = [&](const DPoint2& from, const ExactVec2& by, double k) {
    return Point2{from[0].hi + (std::fma(k, times_pow2(by.hi.x, e), k * times_pow2(by.lo.x, e)) + from[0].lo),
                  from[1].hi + (std::fma(k, times_pow2(by.hi.y, e), k * times_pow2(by.lo.y, e)) + from[1].lo)};
  };
  // Both signs and both quotients are computed whatever the case, and the case then selects
  // among them: the same values as taking each case's own path, without a hard-to-predict
  // branch between them (the figures come before, between and after alike).
  const double t = ratio(ab_dot_ac);
  // the sign of AB·BC places t against 1; t − 1 = AB·BC / AB·AB keeps its own digits near B
  const Certain ab_dot_bc = certain_dot(AB, decimal_difference(dC, dB, e));
  const double beyond = ratio(ab_dot_bc);
  if (ab_dot_ac.sign < 0) {
    p.position = Position::before;
    // of AB·AC's sign: negative unless the quotient underflows
    p.t = std::min(t, -std::numeric_limits<double>::denorm_min());
  } else if (ab_dot_ac.sign == 0) {
    p.position = Position::between;
    p.t = 0;
  } else if (t < 0.5) {  // AB·BC < 0 for sure: between, and t from AB·AC keeps its digits near 0
    p.position = Position::between;
    p.t = t;
  } else if (ab_dot_bc.sign > 0) {
    // t itself from AB·AC (rounded about once), kept on its side of 1 as the position says
    p.position = Position::after;
    p.t = std::max(t, std::nextafter(1.0, 2.0));
  } else {
    p.position = Position::between;
    p.t = ab_dot_bc.sign == 0 ? 1.0 : std::min(t, 1.0);
  }
  // P = B + (t − 1)·AB within 2^-20 of B (from t ≥ 1/2 on): A + t·AB would carry t's rounding
  // (ε·‖AB‖) into a point that B's own digits place better; elsewhere A + t·AB, as `project`
  // computes it. A and B themselves where t is exactly 0 or 1.
  constexpr double kNearB = 0x1p-20;
  const bool near_b = ab_dot_ac.sign > 0 && !(t < 0.5) && std::abs(beyond) < kNearB;
  p.P = along(near_b ? dB : dA, AB, near_b ? beyond : p.t);
  if (ab_dot_ac.sign == 0) p.P = A;
  else if (ab_dot_ac.sign > 0 && !(t < 0.5) && ab_dot_bc.sign == 0) p.P = B;
  return p;
}

}  // namespace epure::geo
