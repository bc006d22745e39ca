#pragma once
// Error-free building blocks for the few sums of products where cancellation matters: the cross
// product of nearly parallel vectors, the squared distance behind a nearly tangent ray. std::fma
// is correctly rounded by IEEE 754, so these give the same bits on every platform.
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

}  // namespace epure::geo::exact
