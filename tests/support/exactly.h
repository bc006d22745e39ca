#pragma once
// For the few results a header promises to the last bit (a parameter snapped to exactly 0 or 1,
// an end point returned as given, a quarter turn with cos exactly 0, a symmetry of the rounded
// formula): compares the bits, so that −0 and +0 differ and nothing is "close enough". Every
// other comparison of doubles in the tests goes through doctest::Approx with an explicit epsilon.
#include <bit>
#include <cstdint>

namespace epure::test {

inline bool exactly(double got, double expected) {
  return std::bit_cast<std::uint64_t>(got) == std::bit_cast<std::uint64_t>(expected);
}

}  // namespace epure::test
