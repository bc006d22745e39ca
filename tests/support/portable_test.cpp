// support/portable.h: the replacements for what the WebAssembly build's libraries lack or round
// differently, against the native library calls they stand for, bit for bit.
#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "support/portable.h"
#include "support/sin_cos.h"

namespace {

std::uint64_t bits(double x) { return epure::portable::bit_cast<std::uint64_t>(x); }

// xorshift64: the inputs, reproducibly
struct Draw {
  std::uint64_t s = 88172645463325252ull;
  std::uint64_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return s;
  }
  double any_finite() {
    for (;;) {
      const double x = epure::portable::bit_cast<double>(next());
      if (std::isfinite(x)) return x;
    }
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1)
  double moderate() {  // a mantissa at a scale from 2^-40 to 2^40
    return static_cast<double>(next() >> 11) * 0x1p-53 * std::ldexp(1.0, static_cast<int>(next() % 80) - 40);
  }
};

}  // namespace

TEST_CASE("portable: bit_cast") {
  CHECK(bits(1.0) == 0x3ff0000000000000ull);
  CHECK(epure::portable::bit_cast<double>(0x4000000000000000ull) == 2.0);
}

TEST_CASE("portable: parse_double keeps from_chars's contract") {
  const char* cases[] = {"0",      "-0",      "1.5",  "-2.25e3", "1e-400",   "1e400", "5e-324", "2.2250738585072011e-308",
                         "123456789012345678901234567890", "0.1", "+1", " 1", "abc", "1e", "-", "1.5x", "nan", "inf"};
  for (const char* c : cases) {
    CAPTURE(c);
    const char* end = c + std::strlen(c);
    double want = 42, got = 42;
    const auto a = std::from_chars(c, end, want);
    const auto b = epure::portable::parse_double(c, end, got);
    CHECK(a.ec == b.ec);
    if (a.ec == std::errc()) CHECK(a.ptr == b.ptr);
    CHECK(bits(want) == bits(got));
  }
}

TEST_CASE("portable: hypot has the native library's bits") {
  namespace d = epure::portable::detail;
  Draw draw;
  long mismatches = 0;
  for (int i = 0; i < 300000; ++i) {
    const double x = i % 2 ? draw.any_finite() : draw.moderate();
    const double y = i % 2 ? draw.any_finite() : draw.moderate();
    const double z = i % 3 ? draw.moderate() : x * 0.5;
    if (bits(d::glibc_hypot(x, y)) != bits(std::hypot(x, y))) ++mismatches;
    if (bits(d::libstdcxx_hypot(x, y, z)) != bits(std::hypot(x, y, z))) ++mismatches;
  }
  CHECK(mismatches == 0);
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(d::glibc_hypot(inf, std::nan("")) == inf);
  CHECK(std::isnan(d::glibc_hypot(1, std::nan(""))));
  CHECK(d::glibc_hypot(0, 0) == 0);
  CHECK(d::glibc_hypot(3, 4) == 5);
  CHECK(d::glibc_hypot(0x1p-1074, 0x1p-1074) == std::hypot(0x1p-1074, 0x1p-1074));
  CHECK(d::glibc_hypot(0x1p1023, 0x1p1023) == std::hypot(0x1p1023, 0x1p1023));  // 2^1023·√2: finite
  CHECK(d::glibc_hypot(0x1.fffffffffffffp1023, 0x1.fffffffffffffp1023) == inf);
}

TEST_CASE("portable: sin, cos and atan2 correctly rounded (values from mpmath at 300 bits)") {
  namespace p = epure::portable;
  double s = 1, c = 0;
  p::sin_cos_quarter(0, s, c);
  CHECK(bits(s) == bits(0.0));
  CHECK(c == 1);
  p::sin_cos_quarter(-0.0, s, c);  // the sign of zero kept
  CHECK(bits(s) == bits(-0.0));
  // below the normal range atan2 is y/x, correctly rounded, the sign of a zero kept
  CHECK(bits(p::atan2(1e-310, 3.0)) == bits(1e-310 / 3.0));
  CHECK(bits(p::atan2(-1e-300, 1e300)) == bits(-0.0));
  CHECK(bits(p::atan2(0x1p-1060, 0x1.8p0)) == bits(0x1p-1060 / 0x1.8p0));
  // arguments where glibc's sin and cos round the other way
  p::sin_cos_quarter(-0x1.bf0b19459991fp-4, s, c);
  CHECK(bits(s) == bits(-0x1.be2807714e255p-4));
  p::sin_cos_quarter(0x1.0ba1b83214863p-1, s, c);
  CHECK(bits(c) == bits(0x1.bba158e9337bdp-1));
  // and where glibc's atan2 does
  CHECK(bits(p::atan2(0x1.3929fbf1db1dp-3, 0x1.603eed789fa88p-2)) == bits(0x1.ac5496da119f5p-2));
  CHECK(bits(p::atan2(0x1.009bb5914c554p-2, 0x1.e4826e6aca348p-2)) == bits(0x1.f2c1536d2200dp-2));
  // within an ulp of the library everywhere else, exact constants at the axes
  Draw draw;
  for (int i = 0; i < 20000; ++i) {
    const double x = (draw.moderate() / 0x1p40 * 2 - 1) * 0.78539816339744828;
    p::sin_cos_quarter(x, s, c);
    CHECK(std::abs(s - std::sin(x)) <= std::abs(std::sin(x)) * 0x1p-52);
    CHECK(std::abs(c - std::cos(x)) <= std::abs(std::cos(x)) * 0x1p-52);
    const double a = draw.moderate() - 0x1p39, b = draw.moderate() - 0x1p39;
    CHECK(std::abs(p::atan2(a, b) - std::atan2(a, b)) <= std::abs(std::atan2(a, b)) * 0x1p-52);
  }
  CHECK(p::atan2(0.0, -1.0) == std::atan2(0.0, -1.0));
  CHECK(bits(p::atan2(-0.0, 1.0)) == bits(-0.0));
  CHECK(p::atan2(1.0, 0.0) == std::atan2(1.0, 0.0));
}

// support/sin_cos.h: the certified cheap path gives sin_cos_quarter's bits, whether it certifies
// an argument or hands it to the series.
namespace {

void check_fast_sin_cos(double x) {
  namespace p = epure::portable;
  double s0 = 2, c0 = 2, s1 = 3, c1 = 3;
  p::sin_cos_quarter(x, s0, c0);
  p::sin_cos_quarter_fast(x, s1, c1);
  CAPTURE(x);
  CHECK(bits(s1) == bits(s0));
  CHECK(bits(c1) == bits(c0));
}

}  // namespace

TEST_CASE("sin_cos_quarter_fast: sin_cos_quarter's bits") {
  SUBCASE("1. zeros keep their sign, tiny arguments give x and 1") {
    for (double x : {0.0, -0.0, 0x1p-1074, -0x1p-1074, 1e-300, 0x1.fffffffffffffp-31, -0x1p-30,
                     0x1p-30, 0x1.0000000000001p-30})
      check_fast_sin_cos(x);
  }
  SUBCASE("2. where glibc rounds the other way, and at the ends of the quarter") {
    for (double x : {-0x1.bf0b19459991fp-4, 0x1.0ba1b83214863p-1, 0.78539816339744828,
                     -0.78539816339744828, 45 * (3.141592653589793 / 180)})
      check_fast_sin_cos(x);
  }
  SUBCASE("3. random arguments, decimal angles, and those the cheap path does not certify") {
    namespace p = epure::portable;
    Draw draw;
    int uncertified = 0;
    constexpr int n = 100000;
    for (int i = 0; i < n; ++i) {
      double x;
      switch (i % 3) {
        case 0: x = (2 * draw.unit() - 1) * 0.78539816339744828; break;
        case 1: x = std::ldexp(0.5 + draw.unit() / 2, -static_cast<int>(draw.next() % 31)); break;
        default:  // a decimal angle in [−45°, 45°], as cos_sin_degrees reduces them
          x = (static_cast<double>(draw.next() % 9001) - 4500) / 100 * (3.141592653589793 / 180);
      }
      if (std::fabs(x) >= 0x1p-30) {
        double s, c;
        uncertified += p::detail::sin_cos_quarter_certified(x, s, c) ? 0 : 1;
      }
      check_fast_sin_cos(x);
    }
    // about one in 300: both paths run, and the cheap one carries the load
    CHECK(uncertified > 0);
    CHECK(uncertified < n / 100);
  }
}
