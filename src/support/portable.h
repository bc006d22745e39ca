#pragma once
// The few standard library pieces that not every toolchain epure is built with has, or that
// round differently from one C library to the next: the WebAssembly build of `epure explore`
// (emscripten 3.1.6: clang 14, its own libc++ and musl) lacks std::bit_cast and the
// floating-point std::from_chars / std::to_chars, and its hypot, sin, cos and atan2 round some
// results otherwise than glibc's. Every use goes through here, so that the rest of the code has
// no #if, and the page's `epure.solve` gives the native bits (tests/browser/).
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <type_traits>

namespace epure::portable {

// std::bit_cast, from the builtin that both GCC (11+) and clang provide.
template <class To, class From>
  requires(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>)
constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}

// std::from_chars for a double in the general format, with its contract: no leading
// whitespace or '+', `value` left alone on error, result_out_of_range when the number
// overflows or underflows to zero (a subnormal result is a result), never the locale's
// decimal separator.
inline std::from_chars_result parse_double(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  return std::from_chars(first, last, value);
#else
  // strtod of a C-locale library (emscripten's musl: '.' whatever the locale), on a
  // NUL-terminated copy. Correctly rounded as from_chars is.
  if (first == last || *first == '+' || *first == ' ' || *first == '\t' || *first == '\n' || *first == '\r' ||
      *first == '\f' || *first == '\v')
    return {first, std::errc::invalid_argument};
  char small[128];
  const auto n = static_cast<std::size_t>(last - first);
  char* buf = n < sizeof small ? small : static_cast<char*>(std::malloc(n + 1));
  if (buf == nullptr) return {first, std::errc::not_enough_memory};
  std::memcpy(buf, first, n);
  buf[n] = '\0';
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(buf, &end);
  const int error = errno;
  const auto used = static_cast<std::size_t>(end - buf);
  if (buf != small) std::free(buf);
  if (used == 0) return {first, std::errc::invalid_argument};
  if (error == ERANGE && (std::isinf(v) || v == 0)) return {first + used, std::errc::result_out_of_range};
  value = v;
  return {first + used, std::errc()};
#endif
}

// ---- std::hypot, with the bits of the native build's libraries ------------------------------
// The native build calls std::hypot: glibc's for two arguments, libstdc++'s for three. Other C
// libraries round some results differently (musl's, in the WebAssembly build), so there the
// same algorithms are written out here (tests/support/portable_test.cpp checks them against
// the native ones, bit for bit).
namespace detail {

// glibc's hypot (2.35 on, after C. F. Borges, "An improved algorithm for hypot(a, b)"), its
// kernel without fma: for ax >= ay >= 0 whose squares neither overflow nor underflow.
inline double hypot_kernel(double ax, double ay) {
  double h = std::sqrt(ax * ax + ay * ay);
  double t1, t2;
  if (h <= 2.0 * ay) {
    const double delta = h - ay;
    t1 = ax * (2.0 * delta - ax);
    t2 = (delta - 2.0 * (ax - ay)) * delta;
  } else {
    const double delta = h - ax;
    t1 = 2.0 * delta * (ax - 2.0 * ay);
    t2 = (4.0 * delta - ay) * ay + delta * delta;
  }
  h -= (t1 + t2) / (2.0 * h);
  return h;
}

inline double glibc_hypot(double x, double y) {
  constexpr double kScale = 0x1p-600, kLarge = 0x1p+511, kTiny = 0x1p-511, kEps = 0x1p-54;
  if (!std::isfinite(x) || !std::isfinite(y)) {
    if (std::isinf(x) || std::isinf(y)) return HUGE_VAL;
    return x + y;
  }
  x = std::fabs(x);
  y = std::fabs(y);
  double ax = x < y ? y : x;
  const double ay = x < y ? x : y;
  if (ax > kLarge) {
    if (ay <= ax * kEps) return ax + ay;
    return hypot_kernel(ax * kScale, ay * kScale) / kScale;
  }
  if (ay < kTiny) {
    if (ax >= ay / kEps) return ax + ay;
    ax = hypot_kernel(ax / kScale, ay / kScale) * kScale;
    return ax;
  }
  if (ay <= ax * kEps) return ax + ay;
  return hypot_kernel(ax, ay);
}

// libstdc++'s three-argument std::hypot.
inline double libstdcxx_hypot(double x, double y, double z) {
  x = std::fabs(x);
  y = std::fabs(y);
  z = std::fabs(z);
  if (const double a = x < y ? y < z ? z : y : x < z ? z : x)
    return a * std::sqrt((x / a) * (x / a) + (y / a) * (y / a) + (z / a) * (z / a));
  return 0;
}

}  // namespace detail

#if defined(__GLIBC__) && defined(__GLIBCXX__)
inline double hypot(double x, double y) { return std::hypot(x, y); }
inline double hypot(double x, double y, double z) { return std::hypot(x, y, z); }
#else
inline double hypot(double x, double y) { return detail::glibc_hypot(x, y); }
inline double hypot(double x, double y, double z) { return detail::libstdcxx_hypot(x, y, z); }
#endif

// ---- sin, cos and atan2, correctly rounded ------------------------------------------------
// Every C library rounds these its own way (glibc's sin misrounds about 0.15% of arguments in
// [−π/4, π/4], musl's others), so the same figure would carry different bits natively and in
// the browser. These are evaluated in double-double arithmetic (Dekker's products, no fma),
// to about 2^-100, then rounded once: the correctly rounded value but for arguments within
// 2^-47 ulp of a rounding boundary. The same bits on every machine.
namespace detail {

struct DD {
  double hi, lo;
};
inline DD two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
inline DD fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
inline void split(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  hi = c - (c - a);
  lo = a - hi;
}
inline DD two_prod(double a, double b) {
  const double p = a * b;
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
inline DD dd_add(DD a, DD b) {
  DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = fast_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return fast_two_sum(s.hi, s.lo);
}
inline DD dd_neg(DD a) { return {-a.hi, -a.lo}; }
inline DD dd_mul(DD a, DD b) {
  DD p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return fast_two_sum(p.hi, p.lo);
}
inline DD dd_mul(DD a, double b) {
  DD p = two_prod(a.hi, b);
  p.lo += a.lo * b;
  return fast_two_sum(p.hi, p.lo);
}
inline DD dd_div(DD a, DD b) {
  const double q1 = a.hi / b.hi;
  DD r = dd_add(a, dd_neg(dd_mul(b, q1)));
  const double q2 = r.hi / b.hi;
  r = dd_add(r, dd_neg(dd_mul(b, q2)));
  const double q3 = r.hi / b.hi;
  return dd_add(fast_two_sum(q1, q2), DD{q3, 0});
}

// sin x and cos x for |x| <= π/4 (x a double-double), by their Taylor series to x^29 / 29!.
inline void dd_sin_cos(DD x, DD& s, DD& c) {
  const DD minus_x2 = dd_neg(dd_mul(x, x));
  DD ts = x, tc{1, 0};
  s = x;
  c = {1, 0};
  for (int k = 1; k <= 14; ++k) {
    ts = dd_div(dd_mul(ts, minus_x2), DD{static_cast<double>((2 * k) * (2 * k + 1)), 0});
    tc = dd_div(dd_mul(tc, minus_x2), DD{static_cast<double>((2 * k - 1) * (2 * k)), 0});
    s = dd_add(s, ts);
    c = dd_add(c, tc);
  }
}

// π/2 as a double-double
inline constexpr DD kHalfPi{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};

}  // namespace detail

// sin x and cos x for |x| <= π/4, correctly rounded (above).
inline void sin_cos_quarter(double x, double& s, double& c) {
  if (x == 0) {  // exactly ±0: sin keeps the sign of zero (the series would add +0)
    s = x;
    c = 1;
    return;
  }
  detail::DD ds, dc;
  detail::dd_sin_cos({x, 0}, ds, dc);
  s = ds.hi + ds.lo;
  c = dc.hi + dc.lo;
}

// atan2(y, x), correctly rounded (above): the library's value a, within an ulp or so, then one
// Newton step in double-double, θ = a + atan((y cos a − x sin a) / (x cos a + y sin a)).
// Zeros, infinities and NaNs: the library's (its constants ±π, ±π/2, ±π/4, ±3π/4 are the
// correctly rounded ones).
inline double atan2(double y, double x) {
  using namespace detail;
  const double a = std::atan2(y, x);
  if (!std::isfinite(x) || !std::isfinite(y) || x == 0 || y == 0) return a;
  // Below the normal range the scaling further down would lose y's bits; there atan(y/x) is y/x
  // to far below an ulp, and the division is correctly rounded (and keeps the sign of a −0).
  if (x > 0 && std::fabs(a) < 0x1p-1000) return y / x;
  // both near 1 in size (exact), so that no product below under- or overflows
  int e = 0;
  std::frexp(std::fabs(x) > std::fabs(y) ? x : y, &e);
  x = std::ldexp(x, -e);
  y = std::ldexp(y, -e);
  // sin a and cos a: a = k·π/2 + r, |r| <= π/4
  const double k = std::nearbyint(a / kHalfPi.hi);
  const DD r = dd_add({a, 0}, dd_neg(dd_mul(kHalfPi, k)));
  DD s, c;
  dd_sin_cos(r, s, c);
  switch (static_cast<int>(k)) {
    case 1: { const DD t = s; s = c; c = dd_neg(t); break; }    // sin(r + π/2) = cos r
    case -1: { const DD t = s; s = dd_neg(c); c = t; break; }
    case 2: case -2: s = dd_neg(s); c = dd_neg(c); break;
    default: break;
  }
  const DD num = dd_add(dd_mul(c, y), dd_neg(dd_mul(s, x)));
  const DD den = dd_add(dd_mul(c, x), dd_mul(s, y));
  const DD q = dd_div(num, den);  // tiny: atan q = q to far below an ulp of θ
  const DD theta = dd_add({a, 0}, q);
  return theta.hi + theta.lo;
}

}  // namespace epure::portable
