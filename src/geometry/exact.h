#pragma once
// Error-free building blocks for the sums of products where cancellation matters: the cross
// product of nearly parallel vectors, the distance behind a nearly tangent ray. std::fma is
// correctly rounded by IEEE 754, so these give the same bits on every platform.
#include <cmath>

namespace epure::geo::exact {

// a·b − c·d with one rounding error in all (Kahan): the product c·d is split into its rounded
// value and the exact error fma recovers.
inline double difference_of_products(double a, double b, double c, double d) {
  double cd = c * d;
  double error = std::fma(-c, d, cd);
  double result = std::fma(a, b, -cd);
  return result + error;
}

// a·b + c·d, likewise.
inline double sum_of_products(double a, double b, double c, double d) {
  return difference_of_products(a, b, -c, d);
}

// hi + lo exactly: the rounded result of an operation and the error its rounding made.
struct TwoTerm {
  double hi, lo;
};

// a + b = hi + lo exactly, whatever their magnitudes (Knuth's TwoSum).
inline TwoTerm two_sum(double a, double b) {
  const double s = a + b;
  const double b_virtual = s - a;
  return {s, (a - (s - b_virtual)) + (b - b_virtual)};
}
inline TwoTerm two_difference(double a, double b) { return two_sum(a, -b); }

// a·b = hi + lo exactly: the fma gives the product's rounding error.
inline TwoTerm two_product(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

// A sum of terms and products rounded about once at the end, as if computed in twice the
// working precision (Ogita, Rump and Oishi's Sum2/Dot2): each rounding error is carried aside
// and added back last. The result is within about ε of its own size, plus ε² of the terms'.
class CompensatedSum {
 public:
  CompensatedSum& add(double x) {
    const TwoTerm s = two_sum(sum_, x);
    sum_ = s.hi;
    error_ += s.lo;
    return *this;
  }
  CompensatedSum& add_product(double a, double b) {
    const TwoTerm p = two_product(a, b);
    add(p.hi);
    error_ += p.lo;
    return *this;
  }
  double value() const { return sum_ + error_; }
  // value() and what its rounding left out: the sum to about ε² of its terms, as hi + lo.
  TwoTerm two_term() const { return two_sum(sum_, error_); }

 private:
  double sum_ = 0, error_ = 0;
};

}  // namespace epure::geo::exact
