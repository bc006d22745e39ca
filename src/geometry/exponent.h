#pragma once
// The binary exponent of a double, for the kernels' rescaling by powers of two.
#include <cmath>
#include <cstdint>

#include "support/portable.h"

namespace epure::geo {

// ⌊log2 |x|⌋ for a finite non-zero x, as std::ilogb gives it, read from the exponent bits (a
// call into libm less in every kernel). Zeros, subnormals, infinities and NaNs, whose exponent
// field is all zeros or all ones, go to std::ilogb itself.
inline int binary_exponent(double x) {
  const int field = static_cast<int>((portable::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
  if (field == 0 || field == 0x7ff) return std::ilogb(x);
  return field - 1023;
}

}  // namespace epure::geo
