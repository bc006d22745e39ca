// geometry/exponent.h: binary_exponent is std::ilogb, read from the bits.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "geometry/exponent.h"

TEST_CASE("binary_exponent: std::ilogb for every kind of double") {
  using epure::geo::binary_exponent;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (double x : {1.0, -1.0, 1.5, 0.75, 2.0, 0x1.fffffffffffffp0, 3e-300, -7e300,
                   std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                   0x1.fffffffffffffp-1023, 0x1p-1074, 5e-320, 0.0, -0.0, inf, -inf,
                   std::numeric_limits<double>::quiet_NaN()}) {
    CAPTURE(x);
    CHECK(binary_exponent(x) == std::ilogb(x));
  }
  for (int k = -1074; k <= 1023; ++k) {
    CAPTURE(k);
    CHECK(binary_exponent(std::ldexp(1.0, k)) == k);
    CHECK(binary_exponent(std::ldexp(-1.75, k > -1074 ? k - 1 : k)) ==
          std::ilogb(std::ldexp(-1.75, k > -1074 ? k - 1 : k)));
  }
}
