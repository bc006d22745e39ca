#include "geometry/projection.h"

#include "geometry/degenerate.h"
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
  double ab_length = norm(p.AB);
  if (scale.negligible(ab_length)) throw DegenerateFigure("B", "degenerate segment, A = B");

  // (AC − t·AB)·AB = 0  =>  t = AB·AC / AB·AB
  p.ab_dot_ac = dot(p.AB, p.AC);
  p.ab_dot_ab = dot(p.AB, p.AB);
  p.t = p.ab_dot_ac / p.ab_dot_ab;

  // AB and AC are differences of doubles, each exact to half an ulp of itself, so t is off by
  // a few ε of ‖AC‖/‖AB‖: within that of 0 or 1, P is on an end of the segment.
  Near near{kRoundoff * (norm(p.AC) / ab_length + 1)};
  if (near.on(p.t, 0.0)) {
    p.t = 0.0;
    p.P = A;
  } else if (near.on(p.t, 1.0)) {
    p.t = 1.0;
    p.P = B;
  } else {
    p.P = A + p.t * p.AB;
  }
  p.position = p.t < 0 ? Position::before : p.t > 1 ? Position::after : Position::between;
  return p;
}

}  // namespace epure::geo
