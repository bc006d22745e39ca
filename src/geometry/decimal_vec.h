#pragma once
// Vectors between decimal data (decimal.h) as the kernels take them: hi + lo to about ε² of the
// decimals' difference, with a bound on what is left and what the vector is made of, for the
// exact slow path of the decisions (predicates.h). Between doubles given as such they are the
// exact differences of exact_vec.h, bit for bit.
#include <algorithm>
#include <cmath>

#include "geometry/decimal.h"
#include "geometry/exact_vec.h"

namespace epure::geo {

namespace detail {
// A subnormal decimal's rest is below the doubles (kept as ±2^-1074 for its sign: decimal.h), so
// hi + lo is only within 2^-1074 of it: scaled up with a figure of that size (every number near
// 1e-310), that would be a rounding of 1e-14. Such a number is scaled exactly instead, from its
// decimal, then rounded to hi + lo (rare: a subnormal datum; never a worksheet's).
inline bool below_normal(const Decimal& d) { return d.lo != 0 && std::abs(d.hi) < 0x1p-1022; }
inline void exactly_scaled(const exact::ExactDecimal& x, int e, double& hi, double& lo, double& err) {
  const exact::TwoTerm t = exact::two_term(exact::times_pow2(x, -e));
  hi = t.hi;
  lo = t.lo;
  if (lo != 0) err = std::max(err, std::abs(lo) * 0x1p-51 + 0x1p-1074);
}
// (b − a)·2^-e of two decimals: the doubles' difference exactly, plus the rests' difference.
inline void decimal_component(const Decimal& b, const Decimal& a, int e, double& hi, double& lo, double& err) {
  if (below_normal(b) || below_normal(a)) [[unlikely]] {
    exactly_scaled(exact::exact_value(b) - exact::exact_value(a), e, hi, lo, err);
    return;
  }
  const exact::TwoTerm s = exact::two_difference(b.hi, a.hi);
  if (b.lo == 0 && a.lo == 0) {
    hi = times_pow2(s.hi, -e);
    lo = times_pow2(s.lo, -e);
    return;
  }
  const double rest = s.lo + (b.lo - a.lo);
  const exact::TwoTerm t = exact::two_sum(s.hi, rest);
  hi = times_pow2(t.hi, -e);
  lo = times_pow2(t.lo, -e);
  // the rests' own errors, the two roundings of `rest`, and an underflow of the scaling
  const double bound = b.error() + a.error() + 0x1p-52 * (std::abs(b.lo) + std::abs(a.lo) + std::abs(rest));
  err = std::max(err, times_pow2(bound, -e) + 0x1p-1074);
}
inline void decimal_component(const Decimal& u, int f, double& hi, double& lo, double& err) {
  if (below_normal(u)) [[unlikely]] {
    exactly_scaled(exact::exact_value(u), f, hi, lo, err);
    return;
  }
  hi = times_pow2(u.hi, -f);
  lo = times_pow2(u.lo, -f);
  if (u.lo != 0) err = std::max(err, times_pow2(u.error(), -f) + 0x1p-1074);
}
}  // namespace detail

// (b − a)·2^-e.
inline ExactVec2 decimal_difference(const DPoint2& b, const DPoint2& a, int e) {
  ExactVec2 v;
  detail::decimal_component(b[0], a[0], e, v.hi.x, v.lo.x, v.err);
  detail::decimal_component(b[1], a[1], e, v.hi.y, v.lo.y, v.err);
  v.to = b.data();
  v.from = a.data();
  v.shift = -e;
  return v;
}
inline ExactVec3 decimal_difference(const DPoint3& b, const DPoint3& a, int e) {
  ExactVec3 v;
  detail::decimal_component(b[0], a[0], e, v.hi.x, v.lo.x, v.err);
  detail::decimal_component(b[1], a[1], e, v.hi.y, v.lo.y, v.err);
  detail::decimal_component(b[2], a[2], e, v.hi.z, v.lo.z, v.err);
  v.to = b.data();
  v.from = a.data();
  v.shift = -e;
  return v;
}
// A datum that is a vector (a direction), times 2^-f.
inline ExactVec2 decimal_vector(const DPoint2& u, int f) {
  ExactVec2 v;
  detail::decimal_component(u[0], f, v.hi.x, v.lo.x, v.err);
  detail::decimal_component(u[1], f, v.hi.y, v.lo.y, v.err);
  v.to = u.data();
  v.shift = -f;
  return v;
}
inline ExactVec3 decimal_vector(const DPoint3& u, int f) {
  ExactVec3 v;
  detail::decimal_component(u[0], f, v.hi.x, v.lo.x, v.err);
  detail::decimal_component(u[1], f, v.hi.y, v.lo.y, v.err);
  detail::decimal_component(u[2], f, v.hi.z, v.lo.z, v.err);
  v.to = u.data();
  v.shift = -f;
  return v;
}

// A scalar datum (a radius) times 2^-e: hi + lo within err, and the decimal it is.
struct DecimalScalar {
  double hi = 0, lo = 0, err = 0;
  const Decimal* exact = nullptr;  // null: hi + lo exactly
  int shift = 0;
  DecimalScalar() = default;
  DecimalScalar(double x) : hi(x) {}  // NOLINT: a double is its own decimal
  DecimalScalar(const Decimal& d, int e)
      : hi(times_pow2(d.hi, -e)), lo(times_pow2(d.lo, -e)),
        err(d.lo == 0 ? 0 : times_pow2(d.error(), -e) + 0x1p-1074), exact(&d), shift(-e) {
    if (detail::below_normal(d)) [[unlikely]] {
      err = 0;
      detail::exactly_scaled(exact::exact_value(d), e, hi, lo, err);
    }
  }
};

}  // namespace epure::geo
