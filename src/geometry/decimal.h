#pragma once
// A number as it was written: the decimal of a JSON number's text ("0.1" is one tenth, "5e-324"
// five times 10^-324), or a double given as such. The core decides on that exact value
// (README, "epure solve": one meaning for a number) and computes on its nearest double plus the
// rounded rest, hi + lo, which is the decimal to about ε² of itself.
//
// The exact value comes into play only in the slow path of a decision (predicates.h), where
// a floating-point filter could not tell a sign: then it is an ExactDecimal, a big integer times
// a power of ten, and every sum and product of such is exact.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include "geometry/big_integer.h"
#include "geometry/exact.h"
#include "geometry/vec.h"

namespace epure::geo {

struct Decimal {
  double hi = 0;  // the nearest double
  double lo = 0;  // the rest, value − hi, rounded to nearest: zero exactly when the value is hi
  // The exact value: hi itself (binary), ±digits·10^exponent (short), or the text (long: more
  // than 19 significant digits, read again in the slow path; the text outlives the number).
  // beyond: more than kMaxDigits significant digits, or a last digit below 10^kMinExponent: its
  // exact arithmetic would grow without bound (1e-838478), so its reader refuses it.
  enum class Form : std::uint8_t { binary, short_decimal, long_decimal, beyond };
  static constexpr int kMaxDigits = 1000;
  static constexpr int kMinExponent = -1500;
  Form form = Form::binary;
  bool negative = false;
  std::int32_t exponent = 0;
  std::uint64_t digits = 0;
  std::string_view text;
  std::int32_t scale2 = 0;  // the value is the number written times 2^scale2 (times_pow2 below)

  // A double, meant as itself.
  static Decimal of(double x) {
    Decimal d;
    d.hi = x;
    return d;
  }
  // |value − (hi + lo)|, bounded: lo is rounded at most twice (2^-51 of itself, 2^-1074 more
  // when subnormal; a rest too small for any double is kept as ±2^-1074 for its sign).
  double error() const { return lo == 0 ? 0 : std::abs(lo) * 0x1p-51 + 0x1p-1074; }
};

// hi and lo of d computed again from its exact value (decimal.cpp).
Decimal with_exact_parts(Decimal d);

// d·2^k, exactly (a direction rescaled by a power of two). A subnormal decimal's rest is below
// the doubles (kept as ±2^-1074 for its sign), so its hi + lo is only within 2^-1074 of it:
// scaled up (a direction near 1e-310 brought to unit size), hi and lo are taken again from the
// exact value, else they would carry a rounding of 1e-12 into the kernels.
inline Decimal times_pow2(Decimal d, int k) {
  const bool rest_lost = d.lo != 0 && std::abs(d.hi) < 0x1p-1022 && k > 0;
  d.hi = times_pow2(d.hi, k);
  d.lo = times_pow2(d.lo, k);
  if (d.form != Decimal::Form::binary) d.scale2 += k;
  if (rest_lost) [[unlikely]] return with_exact_parts(d);
  return d;
}

// The decimal of a JSON number text (-?int(.frac)?([eE][+-]?digits)?), `hi` its correctly
// rounded double (finite). The text must outlive the result.
Decimal read_decimal(std::string_view text, double hi);

// The same for a number already split, ±digits·10^exponent (digits < 10^19, at most 19 of
// them): the line reader's fast path, which has read the digits for the double.
Decimal decimal_of_digits(bool negative, std::uint64_t digits, int exponent, double hi);

// The decimal a program prints for x: its shortest round trip ("0.1" for 0.1's double). The
// worksheets' data are these: the keys decide on them (exercises/kinds).
Decimal written(double x);

using DPoint2 = std::array<Decimal, 2>;
using DPoint3 = std::array<Decimal, 3>;
inline DPoint2 decimal_point(Point2 p) { return {Decimal::of(p.x), Decimal::of(p.y)}; }
inline DPoint2 decimal_point(Vec2 v) { return {Decimal::of(v.x), Decimal::of(v.y)}; }
inline DPoint3 decimal_point(Point3 p) { return {Decimal::of(p.x), Decimal::of(p.y), Decimal::of(p.z)}; }
inline DPoint3 decimal_point(Vec3 v) { return {Decimal::of(v.x), Decimal::of(v.y), Decimal::of(v.z)}; }
inline DPoint2 written_point(Point2 p) { return {written(p.x), written(p.y)}; }
inline DPoint3 written_point(Vec3 v) { return {written(v.x), written(v.y), written(v.z)}; }
inline Point2 hi_point(const DPoint2& p) { return {p[0].hi, p[1].hi}; }
inline Vec2 hi_vec(const DPoint2& p) { return {p[0].hi, p[1].hi}; }
inline Point3 hi_point(const DPoint3& p) { return {p[0].hi, p[1].hi, p[2].hi}; }
inline Vec3 hi_vec(const DPoint3& p) { return {p[0].hi, p[1].hi, p[2].hi}; }
inline Vec2 lo_vec(const DPoint2& p) { return {p[0].lo, p[1].lo}; }
inline Vec3 lo_vec(const DPoint3& p) { return {p[0].lo, p[1].lo, p[2].lo}; }

// Whether two numbers are the same decimal, exactly.
bool same_value(const Decimal& a, const Decimal& b);
// The exact sign of a − b.
int compare(const Decimal& a, const Decimal& b);

namespace exact {

// m·10^exponent, exactly.
struct ExactDecimal {
  BigInteger m;
  int exponent = 0;
  int sign() const { return m.sign(); }
};

ExactDecimal exact_value(const Decimal& d);
ExactDecimal exact_value(double x);
ExactDecimal operator+(const ExactDecimal& a, const ExactDecimal& b);
ExactDecimal operator-(const ExactDecimal& a, const ExactDecimal& b);
ExactDecimal operator*(const ExactDecimal& a, const ExactDecimal& b);
inline ExactDecimal operator-(const ExactDecimal& a) { return {-a.m, a.exponent}; }
// a·2^k, exactly (2^-k = 5^k·10^-k).
ExactDecimal times_pow2(const ExactDecimal& a, int k);
// The value as hi + lo: hi correctly rounded, lo the rest rounded (of its sign, never zero
// when the rest is not).
TwoTerm two_term(const ExactDecimal& a);

}  // namespace exact

}  // namespace epure::geo
