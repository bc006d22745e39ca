#pragma once
// doctest::Approx with both parts of the tolerance spelled out: a result agrees with the
// expected value when |got − expected| < relative·max(|got|, |expected|) + absolute.
// (Approx's own form is epsilon·(scale + max): scale = absolute / relative.) A zero part is
// taken as a vanishing one (1e-30 relative, 1e-300 absolute), so that within(x, 0, 0) accepts
// x itself, and ±0 alike: Approx's comparison is strict.
#include <doctest/doctest.h>

#include <algorithm>

namespace epure::test {

inline doctest::Approx within(double expected, double relative, double absolute) {
  const double rel = std::max(relative, 1e-30), abs = std::max(absolute, 1e-300);
  return doctest::Approx(expected).epsilon(rel).scale(abs / rel);
}

}  // namespace epure::test
