#pragma once
// sin x and cos x for |x| <= π/4, correctly rounded, the cheap way first. portable.h's
// sin_cos_quarter sums the Taylor series in double-double with three divisions per term (about
// 2 µs a call). Most arguments need far less to be rounded correctly, and the rounding can be
// certified (Ziv's strategy): when every value within the error bound of a cheap evaluation
// rounds to the same double, that double is the correctly rounded value, and so also
// sin_cos_quarter's (2^-100 off). Only certified values come out of the cheap path, so the bits
// are the same on every machine, and the same as before.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "support/portable.h"

namespace epure::portable {

namespace detail {

// 1/3!, 1/5!, 1/7! and 1/4!, 1/6! as double-doubles (to 2^-106 of themselves)
inline constexpr DD kInverse3Factorial{0x1.5555555555555p-3, 0x1.5555555555555p-57};
inline constexpr DD kInverse5Factorial{0x1.1111111111111p-7, 0x1.1111111111111p-63};
inline constexpr DD kInverse7Factorial{0x1.a01a01a01a01ap-13, 0x1.a01a01a01a01ap-73};
inline constexpr DD kInverse4Factorial{0x1.5555555555555p-5, 0x1.5555555555555p-59};
inline constexpr DD kInverse6Factorial{0x1.6c16c16c16c17p-10, -0x1.f49f49f49f49fp-65};

// The double nearest v = hi + lo when every value within `error` of v rounds to it (so then does
// the exact value v approximates, rounding being monotonic); false when a rounding boundary is
// that close. lo ± 2·error is off by far less than `error` once rounded (error ≫ ε·|lo|).
inline bool certainly_rounded(DD v, double error, double& rounded) {
  const double up = v.hi + (v.lo + 2 * error), down = v.hi + (v.lo - 2 * error);
  // the same double both ways: compared bit for bit, the question being identity
  if (bit_cast<std::uint64_t>(up) != bit_cast<std::uint64_t>(down)) return false;
  rounded = up;
  return true;
}

// c[0] + h·(c[1] + h·(c[2] + …)), in double
template <std::size_t N>
constexpr double horner(double h, const double (&c)[N]) {
  double sum = c[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) sum = c[i] + h * sum;
  return sum;
}

// sin x and cos x for 2^-30 <= |x| <= π/4 when the rounding is certified, else false. The
// series of dd_sin_cos in Horner's form with constant coefficients: the terms to x⁷/7! and
// x⁶/6! in double-double, the rest (below 4e-7 of the sum) in double. Relative error below
// 2^-66 by the terms' bounds (measured: 2^-72 for sin, 2^-69 for cos); certified against 2^-64.
inline bool sin_cos_quarter_certified(double x, double& s, double& c) {
  const DD y = two_prod(x, x);  // x² exactly (no underflow for |x| >= 2^-30)
  const DD y2 = dd_mul(y, y), y3 = dd_mul(y2, y);
  const double h = y.hi, h4 = y2.hi * y2.hi;
  // Σ_{k≥4} (−x²)^k / (2k+1)! and / (2k)!, to the 10th and 11th terms (the next below 2^-80)
  constexpr double sin_terms[] = {1 / 362880.0,          -1 / 39916800.0,
                                  1 / 6227020800.0,      -1 / 1307674368000.0,
                                  1 / 355687428096000.0, -1 / 121645100408832000.0,
                                  1 / 51090942171709440000.0};
  constexpr double cos_terms[] = {1 / 40320.0,           -1 / 3628800.0,
                                  1 / 479001600.0,       -1 / 87178291200.0,
                                  1 / 20922789888000.0,  -1 / 6402373705728000.0,
                                  1 / 2432902008176640000.0, -1 / 1124000727777607680000.0};
  const double sin_tail = h4 * horner(h, sin_terms), cos_tail = h4 * horner(h, cos_terms);
  // sin x = x·(1 − x²/3! + x⁴/5! − x⁶/7! + tail), cos x = 1 − x²/2 + x⁴/4! − x⁶/6! + tail
  const DD sin_over_x =
      dd_add(dd_add(DD{1, 0}, dd_neg(dd_mul(y, kInverse3Factorial))),
             dd_add(dd_mul(y2, kInverse5Factorial),
                    dd_add(dd_neg(dd_mul(y3, kInverse7Factorial)), DD{sin_tail, 0})));
  const DD cosine = dd_add(dd_add(DD{1, 0}, DD{-0.5 * y.hi, -0.5 * y.lo}),
                           dd_add(dd_mul(y2, kInverse4Factorial),
                                  dd_add(dd_neg(dd_mul(y3, kInverse6Factorial)), DD{cos_tail, 0})));
  const DD sine = dd_mul(sin_over_x, x);
  double rs, rc;
  if (!certainly_rounded(sine, 0x1p-64 * std::fabs(sine.hi), rs) ||
      !certainly_rounded(cosine, 0x1p-64 * cosine.hi, rc))
    return false;
  s = rs;
  c = rc;
  return true;
}

}  // namespace detail

// sin x and cos x for |x| <= π/4, correctly rounded: sin_cos_quarter's bits, about 20 times
// faster but for about one argument in 300 (near a rounding boundary), which takes the series.
inline void sin_cos_quarter_fast(double x, double& s, double& c) {
  // Below 2^-30, x³/6 < 2^-62·|x| and x²/2 < 2^-61: sin x rounds to x (±0 keeps its sign) and
  // cos x to 1, the nearest rounding boundaries being 2^-54 away; the series gives the same.
  if (std::fabs(x) < 0x1p-30) {
    s = x;
    c = 1;
    return;
  }
  if (detail::sin_cos_quarter_certified(x, s, c)) return;
  sin_cos_quarter(x, s, c);
}

}  // namespace epure::portable
