#pragma once
// The one home of the geometry core's floating-point tolerances. Every comparison that decides a
// branch (parallel or not, inside or not, tangent or miss) goes through here, scaled by the size
// of the figure at hand; nothing else in src/geometry compares doubles against a bare epsilon.
//
// The grading tolerance (how far a student's answer may be from the key) is a different thing
// and lives in the answer key.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace epure::geo {

inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// A quantity that a handful of rounded operations computed from the data carries a relative
// error of a few ε. 32ε (≈ 7e-15) covers that with margin, yet stays six orders below the 1e-9
// at which answers are compared: a figure that is genuinely 1e-12 away from tangency or
// parallelism is still told apart correctly.
inline constexpr double kRoundoff = 32 * kEpsilon;

// Two points closer than this, relative to the figure's scale, are the same point: their
// difference is made of rounding of the inputs, not of data.
inline constexpr double kCoincident = 4 * kEpsilon;

// The size of a figure: the largest absolute coordinate that enters the computation. Relative
// tolerances multiply it, so a figure drawn at 1e-8 or at 1e8 decides its branches alike.
struct Scale {
  double value = 0;

  static Scale of(std::initializer_list<double> coordinates) {
    double m = 0;
    for (double c : coordinates) m = std::max(m, std::abs(c));
    return Scale{m};
  }

  // Absolute tolerance for a length (or a coordinate) computed from the data.
  double length() const { return kRoundoff * value; }
  // Absolute tolerance for an area-like quantity (cross or dot of two data vectors).
  double area() const { return kRoundoff * value * value; }
  // True when a length this small is only rounding: the points it separates coincide.
  bool negligible(double length) const { return !(length > kCoincident * value); }
};

// Compares x with a bound within an absolute tolerance: the three-way answer every branch needs.
// `below` and `above` are strict beyond the tolerance; a value within it counts as on the bound.
struct Near {
  double tolerance;
  bool below(double x, double bound) const { return x < bound - tolerance; }
  bool above(double x, double bound) const { return x > bound + tolerance; }
  bool on(double x, double bound) const { return !below(x, bound) && !above(x, bound); }
};

}  // namespace epure::geo
