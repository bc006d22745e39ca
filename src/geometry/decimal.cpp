#include "geometry/decimal.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "support/portable.h"

namespace epure::geo {

namespace {

// The parts of a JSON number text: sign, significant digits (no leading or trailing zero) and
// the power of ten that follows them.
struct Parts {
  bool negative = false;
  std::string_view integer, fraction;  // the digits before and after '.'
  std::int64_t exponent = 0;           // of the 'e' part, saturated
};

Parts split(std::string_view text) {
  Parts p;
  std::size_t i = 0;
  if (i < text.size() && text[i] == '-') {
    p.negative = true;
    ++i;
  }
  const std::size_t int_begin = i;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  p.integer = text.substr(int_begin, i - int_begin);
  if (i < text.size() && text[i] == '.') {
    const std::size_t frac_begin = ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    p.fraction = text.substr(frac_begin, i - frac_begin);
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool minus = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) minus = text[i++] == '-';
    std::int64_t e = 0;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i)
      e = std::min<std::int64_t>(e * 10 + (text[i] - '0'), 1'000'000'000);
    p.exponent = minus ? -e : e;
  }
  return p;
}

// The significant digits of integer·fraction, and the power of ten of their last one.
struct Significand {
  std::string digits;  // no leading, no trailing zero; empty for zero
  std::int64_t exponent = 0;
};

Significand significand(const Parts& p) {
  Significand s;
  s.digits.reserve(p.integer.size() + p.fraction.size());
  for (char c : p.integer)
    if (!s.digits.empty() || c != '0') s.digits += c;
  for (char c : p.fraction)
    if (!s.digits.empty() || c != '0') s.digits += c;
  s.exponent = p.exponent - static_cast<std::int64_t>(p.fraction.size());
  while (!s.digits.empty() && s.digits.back() == '0') {
    s.digits.pop_back();
    ++s.exponent;
  }
  return s;
}

constexpr std::uint64_t kPow10[] = {1ULL,
                                    10ULL,
                                    100ULL,
                                    1000ULL,
                                    10000ULL,
                                    100000ULL,
                                    1000000ULL,
                                    10000000ULL,
                                    100000000ULL,
                                    1000000000ULL,
                                    10000000000ULL,
                                    100000000000ULL,
                                    1000000000000ULL,
                                    10000000000000ULL,
                                    100000000000000ULL,
                                    1000000000000000ULL,
                                    10000000000000000ULL,
                                    100000000000000000ULL,
                                    1000000000000000000ULL,
                                    10000000000000000000ULL};

__extension__ typedef unsigned __int128 U128;
__extension__ typedef __int128 I128;

// D·10^q − hi for D < 2^64, by integers when they fit 127 bits: the rest of a decimal of up to
// 19 digits, the worksheets' and the shortest round trips of doubles. Nothing when they do not.
std::optional<double> short_rest(std::uint64_t D, int q, double hi) {
  if (hi == 0) return std::nullopt;
  int k = 0;
  const double f = std::frexp(std::abs(hi), &k);
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // |hi| = m·2^(k−53)
  k -= 53;
  if (q <= 0 && q >= -22) {
    // D / P − m·2^k = (D·2^s − m·P·2^(k+s)) / (P·2^s), s = max(0, −k)
    const int s = k < 0 ? -k : 0;
    const U128 P = U128(kPow10[std::min(-q, 19)]) * (q < -19 ? kPow10[-q - 19] : 1);
    if (s > 63) return std::nullopt;  // D·2^s could pass 2^127 (a hi far below D / P: never)
    const U128 a = U128(D) << s;
    const int up = k + s;  // ≥ 0
    if (up > 52) return std::nullopt;
    const U128 b = (U128(m) * P) << up;
    if (a >> 126 || b >> 126) return std::nullopt;
    const I128 n = static_cast<I128>(a) - static_cast<I128>(b);
    if (n == 0) return 0.0;
    // N / P, then 2^-s: two roundings (Decimal::error)
    return std::ldexp(static_cast<double>(n) / static_cast<double>(P), -s);
  }
  if (q > 0 && q <= 19) {
    const U128 x = U128(D) * kPow10[q];  // < 2^128
    if (x >> 126) return std::nullopt;
    if (k < 0) {
      // hi has bits below 1 but the decimal is an integer: they are equal below 2^53
      return static_cast<double>(static_cast<I128>(x) - static_cast<I128>(U128(m) >> -k));
    }
    if (k > 60) return std::nullopt;
    const U128 b = U128(m) << k;
    if (b >> 126) return std::nullopt;
    return static_cast<double>(static_cast<I128>(x) - static_cast<I128>(b));
  }
  return std::nullopt;
}

double to_double(const std::string& text) {
  double x = 0;
  const auto [end, error] = portable::parse_double(text.data(), text.data() + text.size(), x);
  if (error == std::errc::result_out_of_range) {
    // beyond the doubles: infinite, or zero of the right sign below them
    const bool negative = !text.empty() && text[0] == '-';
    const auto e = text.find('e');
    const bool tiny = e != std::string::npos && text[e + 1] == '-';
    x = tiny ? 0.0 : std::numeric_limits<double>::infinity();
    if (negative) x = -x;
  }
  return x;
}

}  // namespace

// value − hi rounded, never zero when it is not: a rest below the smallest double (a decimal
// between two subnormals, or below them all) is kept as ±2^-1074 for its sign (Decimal::error
// bounds it then).
static double exact_rest(const Decimal& d, double hi) {
  const exact::TwoTerm rest = exact::two_term(exact::exact_value(d) - exact::exact_value(hi));
  return rest.hi != 0 ? rest.hi : rest.lo;
}

Decimal read_decimal(std::string_view text, double hi) {
  Decimal d = Decimal::of(hi);
  const Parts parts = split(text);
  const Significand s = significand(parts);
  if (s.digits.empty()) {  // zero, whatever its sign
    d.form = Decimal::Form::short_decimal;
    return d;
  }
  d.negative = parts.negative;
  if (s.digits.size() > Decimal::kMaxDigits || s.exponent < Decimal::kMinExponent) {
    d.form = Decimal::Form::beyond;  // nothing computed: the reader refuses it
    return d;
  }
  if (s.digits.size() <= 19 && s.exponent >= -2'000'000'000 && s.exponent <= 2'000'000'000) {
    d.form = Decimal::Form::short_decimal;
    std::uint64_t D = 0;
    for (char c : s.digits) D = D * 10 + static_cast<std::uint64_t>(c - '0');
    d.digits = D;
    d.exponent = static_cast<std::int32_t>(s.exponent);
    if (auto rest = short_rest(D, d.exponent, hi)) {
      d.lo = d.negative ? -*rest : *rest;
      return d;
    }
  } else {
    d.form = Decimal::Form::long_decimal;
    d.text = text;
  }
  // the rest exactly, in big integers (long decimals, powers of ten beyond 10^±22)
  d.lo = exact_rest(d, hi);
  return d;
}

Decimal decimal_of_digits(bool negative, std::uint64_t digits, int exponent, double hi) {
  Decimal d = Decimal::of(hi);
  d.form = Decimal::Form::short_decimal;
  if (digits == 0) return d;  // zero, whatever its sign
  while (digits % 10 == 0) {  // the form read_decimal gives: no trailing zero
    digits /= 10;
    ++exponent;
  }
  d.negative = negative;
  d.digits = digits;
  d.exponent = exponent;
  if (auto rest = short_rest(digits, exponent, hi)) {
    d.lo = negative ? -*rest : *rest;
    return d;
  }
  d.lo = exact_rest(d, hi);
  return d;
}

Decimal written(double x) {
  if (!std::isfinite(x)) return Decimal::of(x);
  // fmt's shortest round trip (Dragonbox), the digits the JSON writer prints: emscripten's libc++
  // has no std::to_chars for doubles. At most 17 significant digits: a short decimal, which keeps
  // no view of the text.
  char buffer[40];
  const auto end = fmt::format_to_n(buffer, sizeof buffer, "{}", x).out;
  return read_decimal({buffer, static_cast<std::size_t>(end - buffer)}, x);
}

Decimal with_exact_parts(Decimal d) {
  if (d.form == Decimal::Form::binary) return d;
  const exact::TwoTerm parts = exact::two_term(exact::exact_value(d));
  d.hi = parts.hi;
  d.lo = parts.lo;
  return d;
}

bool same_value(const Decimal& a, const Decimal& b) {
  if (a.hi != b.hi || a.lo != b.lo) return false;  // each a function of the value
  if (a.lo == 0) return true;                       // both the double hi
  if (a.form == Decimal::Form::short_decimal && b.form == Decimal::Form::short_decimal)
    return a.digits == b.digits && a.exponent == b.exponent && a.negative == b.negative && a.scale2 == b.scale2;
  return (exact::exact_value(a) - exact::exact_value(b)).sign() == 0;
}

int compare(const Decimal& a, const Decimal& b) {
  // hi is monotone in the value: where they differ, it orders them; so does lo beyond its errors
  if (a.hi != b.hi) return a.hi < b.hi ? -1 : 1;
  if (std::abs(a.lo - b.lo) > 2 * (a.error() + b.error())) return a.lo < b.lo ? -1 : 1;
  if (same_value(a, b)) return 0;
  return (exact::exact_value(a) - exact::exact_value(b)).sign();
}

namespace exact {

ExactDecimal exact_value(double x) {
  if (x == 0 || !std::isfinite(x)) return {};
  int k = 0;
  const double f = std::frexp(std::abs(x), &k);
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  k -= 53;
  const BigInteger M = BigInteger::from_unsigned(m, x < 0);
  if (k >= 0) return {M.times_pow2(k), 0};
  return {M.times_pow5(-k), k};  // m·2^k = m·5^-k·10^k
}

namespace {
ExactDecimal written_value(const Decimal& d) {
  switch (d.form) {
    case Decimal::Form::binary:
    case Decimal::Form::beyond: return exact_value(d.hi);
    case Decimal::Form::short_decimal: return {BigInteger::from_unsigned(d.digits, d.negative), d.exponent};
    case Decimal::Form::long_decimal: {
      const Parts p = split(d.text);
      const Significand s = significand(p);
      BigInteger m = BigInteger::from_digits(s.digits);
      if (p.negative) m = -m;
      return {m, static_cast<int>(s.exponent)};
    }
  }
  return {};
}
}  // namespace

ExactDecimal exact_value(const Decimal& d) {
  if (d.form == Decimal::Form::binary || d.scale2 == 0) return written_value(d);
  return times_pow2(written_value(d), d.scale2);
}

ExactDecimal operator+(const ExactDecimal& a, const ExactDecimal& b) {
  if (a.m.is_zero()) return b;
  if (b.m.is_zero()) return a;
  if (a.exponent == b.exponent) return {a.m + b.m, a.exponent};
  if (a.exponent < b.exponent) return {a.m + b.m.times_pow10(b.exponent - a.exponent), a.exponent};
  return {a.m.times_pow10(a.exponent - b.exponent) + b.m, b.exponent};
}
ExactDecimal operator-(const ExactDecimal& a, const ExactDecimal& b) { return a + (-b); }
ExactDecimal operator*(const ExactDecimal& a, const ExactDecimal& b) {
  return {a.m * b.m, a.exponent + b.exponent};
}

ExactDecimal times_pow2(const ExactDecimal& a, int k) {
  if (k >= 0) return {a.m.times_pow2(k), a.exponent};
  return {a.m.times_pow5(-k), a.exponent + k};
}

TwoTerm two_term(const ExactDecimal& a) {
  if (a.m.is_zero()) return {0, 0};
  const auto text = [](const ExactDecimal& x) { return x.m.to_string() + "e" + std::to_string(x.exponent); };
  const double hi = to_double(text(a));
  if (!std::isfinite(hi)) return {hi, 0};
  const ExactDecimal rest = a - exact_value(hi);
  double lo = rest.m.is_zero() ? 0.0 : to_double(text(rest));
  if (lo == 0 && !rest.m.is_zero()) lo = rest.sign() * std::numeric_limits<double>::denorm_min();
  return {hi, lo};
}

}  // namespace exact

}  // namespace epure::geo
