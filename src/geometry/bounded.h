#pragma once
// A real number known to lie within `err` of a double `mid` (midpoint-radius interval
// arithmetic): sums and products carry their operands' radii and their own rounding, so that a
// sign is certain when |mid| > err. The floating-point filter of a decision whose polynomial is
// written once for both this type and exact decimals (turned_written.cpp): where the filter
// cannot tell, the same polynomial is evaluated exactly.
#include <cmath>

#include "geometry/decimal.h"

namespace epure::geo {

struct Bounded {
  double mid = 0;
  double err = 0;

  static Bounded of(const Decimal& d) { return {d.hi, std::abs(d.lo) + d.error()}; }
  // |mid| > err, certain; 0 when it cannot tell (then the caller decides exactly).
  int certain_sign() const { return mid > err ? 1 : -mid > err ? -1 : 0; }
};

namespace detail {
// Each result's own rounding (half an ulp, counted as a whole one), the rounding of the radius
// sum itself (a relative 2^-50), and an underflow's absolute 2^-1074 (with margin): the radius
// is an upper bound whatever the magnitudes. Infinite or NaN results leave no certain sign.
inline double rounded_radius(double result, double radius) {
  return (radius + 0x1p-52 * std::abs(result)) * (1 + 0x1p-50) + 0x1p-1070;
}
}  // namespace detail

inline Bounded operator-(Bounded a) { return {-a.mid, a.err}; }
inline Bounded operator+(Bounded a, Bounded b) {
  const double s = a.mid + b.mid;
  return {s, detail::rounded_radius(s, a.err + b.err)};
}
inline Bounded operator-(Bounded a, Bounded b) { return a + -b; }
inline Bounded operator*(Bounded a, Bounded b) {
  const double p = a.mid * b.mid;
  return {p, detail::rounded_radius(p, std::abs(a.mid) * b.err + std::abs(b.mid) * a.err + a.err * b.err)};
}

}  // namespace epure::geo
