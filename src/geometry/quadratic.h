#pragma once
// Exact numbers p + q·√K (K = 2 or 3, p and q exact decimals): the field that cos θ and sin θ of
// a whole multiple of 30° or 45° live in with the data (cos 45° = ½√2, cos 30° = ½√3), so that a
// figure turned by such an angle is decided exactly (turned_written.cpp): sums and products stay
// in it, and the sign of p + q√K is exact, comparing p² with K·q² when p and q differ in sign.
#include <cmath>

#include "geometry/decimal.h"

namespace epure::geo::exact {

template <int K>
struct Quadratic {
  ExactDecimal p, q;  // p + q·√K

  friend Quadratic operator+(const Quadratic& a, const Quadratic& b) { return {a.p + b.p, a.q + b.q}; }
  friend Quadratic operator-(const Quadratic& a, const Quadratic& b) { return {a.p - b.p, a.q - b.q}; }
  friend Quadratic operator-(const Quadratic& a) { return {-a.p, -a.q}; }
  friend Quadratic operator*(const Quadratic& a, const Quadratic& b) {
    return {a.p * b.p + exact_value(static_cast<double>(K)) * (a.q * b.q), a.p * b.q + a.q * b.p};
  }
  int sign() const {
    const int sp = p.sign(), sq = q.sign();
    if (sq == 0 || sp == sq) return sp != 0 ? sp : sq;
    if (sp == 0) return sq;
    // p and q√K of opposite signs: the larger magnitude wins
    return sp * (p * p - exact_value(static_cast<double>(K)) * (q * q)).sign();
  }
  // The value to about an ulp: p + q√K without cancellation, (p² − Kq²)/(p − q√K) when p and
  // q√K nearly cancel.
  double value() const {
    const double a = two_term(p).hi, b = two_term(q).hi * std::sqrt(static_cast<double>(K));
    if (p.sign() * q.sign() >= 0) return a + b;
    const TwoTerm n = two_term(p * p - exact_value(static_cast<double>(K)) * (q * q));
    return (n.hi + n.lo) / (a - b);
  }
};

}  // namespace epure::geo::exact
