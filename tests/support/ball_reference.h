#pragma once
// The expected answer of ray/circle and ray/sphere, computed independently of src/geometry: in
// quadruple precision, from the data exactly as given (the direction u not normalised first),
// by the plain quadratic |A + t·û − C|² = r² rather than the course's projection method.
// Used by ray_circle_test.cpp and ray_3d_test.cpp.
#include <optional>

#include "support/real.h"

namespace epure::test {

template <class V>
struct BallExpected {
  Real t_proj;      // û·AC, a length
  Real d2;          // squared distance from C to the line
  Real ac;          // ‖AC‖
  bool inside;      // ‖AC‖ < r
  bool behind;      // outside and t_proj < 0
  bool miss;        // d² > r²
  Real half_chord;  // √(r² − d²) when not a miss
  std::optional<Real> t;
  V I{}, N{};
};

// V is R2 or R3.
template <class V>
BallExpected<V> ball_reference(V A, V u, V C, Real r) {
  BallExpected<V> e{};
  const V uh = unit(u), ac = C - A;
  e.ac = norm(ac);
  e.t_proj = dot(uh, ac);
  // |A + t·û − C|² = r²  <=>  t² − 2·t_proj·t + (‖AC‖² − r²) = 0, discriminant t_proj² − ‖AC‖² + r²
  const Real c = dot(ac, ac) - r * r;
  e.d2 = cross_norm2(uh, ac);
  e.inside = c < 0;
  e.behind = !e.inside && e.t_proj < 0;
  e.miss = !e.behind && e.d2 > r * r;
  if (e.behind || e.miss) return e;
  e.half_chord = sqrt(r * r - e.d2);
  // the roots in the form that does not cancel: q = t_proj ± h, roots q and c / q
  const Real q = e.t_proj + (e.t_proj < 0 ? -e.half_chord : e.half_chord);
  Real small = q, large = q;
  if (q != 0) {
    const Real other = c / q;
    small = min(q, other);
    large = max(q, other);
  }
  e.t = e.inside ? large : max(small, Real(0));
  e.I = A + *e.t * uh;
  e.N = (e.I - C) / r;
  return e;
}

}  // namespace epure::test
