#pragma once
// Two doubles that stand for one number, computed by two roads (the method and the geometry
// core, a mistake's value and the right one) or scaled back from a decimal: equal but for the
// rounding of their last digits. Not a tolerance of the figures (geometry/tolerance.h decides
// those) nor of grading (the answer key's rule): the comparison of "the same number" wherever
// else one is needed, named once.
#include <algorithm>
#include <cmath>

namespace epure {

// A few thousand ulps of the reference's magnitude (of 1 below it): far below any decimal a
// sheet prints, far above what two roads to one double part by.
inline constexpr double kSameNumber = 1e-9;

// `x` and `reference` are one number.
inline bool agrees(double x, double reference) {
  return std::abs(x - reference) <= kSameNumber * std::max(1.0, std::abs(reference));
}

// `x` is a whole number, but for rounding.
inline bool is_whole(double x) { return agrees(std::nearbyint(x), x); }

}  // namespace epure
