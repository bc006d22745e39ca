#include "geometry/projection.h"

#include <cmath>

#include "geometry/degenerate.h"
#include "geometry/exact_vec.h"
#include "geometry/tolerance.h"

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
  const int e = scale.value > 0 ? std::ilogb(scale.value) : 0;
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

}  // namespace epure::geo
