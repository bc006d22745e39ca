#pragma once
// Filtered exact predicates: the sign of each polynomial of the data that decides a branch
// (before / between / after, parallel, inside, behind, tangent, on a side), exact for the given
// doubles, and its value to about an ulp.
//
// Each predicate first evaluates its polynomial in compensated arithmetic (about ε² of its
// terms off) and checks the result against a bound on that error, the floating-point filter of
// Shewchuk's predicates: beyond the bound the sign is certain, and the common case costs a few
// more flops than the plain formula. Within it (the data on or within ~1e-30 of a boundary) the
// polynomial is evaluated again as an exact expansion (expansion.h), whose sign is the true one.
// A `Certain` carries both: `sign` exact, `value` of that same sign (zero exactly when the
// polynomial is zero), so that a quotient computed from it never contradicts the branch.
//
// The data are expected near unit size (the kernels scale them by powers of two first): the
// filter bounds are relative, and the fma products exact, only away from underflow (a line whose
// numbers span more is refused: solve/number_span.h).
//
// The bound is the value's error too: a value within 2^56 of it (a decimal's digits beyond the
// doubles cancelling the rest, 1e-20 of the terms) is taken from the slow path, exactly rounded,
// so that quotients of these values stay within 4 ulps of the decimals' figure.
#include <cmath>

#include "geometry/decimal_vec.h"
#include "geometry/exact_vec.h"
#include "geometry/tolerance.h"

namespace epure::geo {

struct Certain {
  int sign;         // −1, 0 or +1, exact
  double value;     // within about an ulp of the exact value, of its sign
  double lo = 0;    // value + lo is within about ε² of the terms (a double-double)
};

// n / d of two double-doubles, rounded about once (within about half an ulp plus ε² of the
// terms): the correction term makes it n.value / d.value itself whenever both are exact
// doubles, and keeps t's last digits near 1, where a plain quotient of the rounded values is
// 1.5 ulps off.
inline double quotient(const Certain& n, double d_hi, double d_lo) {
  const double q = n.value / d_hi;
  const double remainder = std::fma(-q, d_hi, n.value) + (n.lo - q * d_lo);  // n − q·d
  return q + remainder / d_hi;
}

inline int sign_of(double x) { return (x > 0) - (x < 0); }

namespace detail {
// The compensated evaluations below are off by at most a small multiple of ε²·T, T the sum of
// the magnitudes of the products they add (Ogita, Rump and Oishi's Dot2 bound, with the
// plainly computed low-order products counted in): 64·ε²·T covers that with margin.
inline constexpr double kCompensatedFilter = 64 * kEpsilon * kEpsilon;
// A plain sum of two products of exact two-term values, off by at most a few ε of its terms:
// 8·ε·T covers it.
inline constexpr double kPlainFilter = 8 * kEpsilon;
// The filter's bound is also the error of the value: beyond 2^56 times it, the value is within
// 2^-56 of itself (a quarter ulp), and t = n / d keeps its 4 ulps. Nearer (a decimal's digits
// beyond the doubles, 1e-20 of the terms, make the value: t_ab of segments parallel but for a
// 20th digit), the slow path gives it exactly rounded. No worksheet line comes near: their
// figures keep a margin from every boundary.
inline constexpr double kValueMargin = 0x1p56;
inline bool value_certain(double value, double bound) { return std::abs(value) > kValueMargin * bound; }

// dot and cross of exact_vec.h, as hi + lo (their hi is those functions' result, bit for bit).
inline exact::TwoTerm compensated_dot(const ExactVec2& u, const ExactVec2& v) {
  exact::CompensatedSum s;
  s.add_product(u.hi.x, v.hi.x).add_product(u.hi.y, v.hi.y);
  s.add((u.hi.x * v.lo.x + u.lo.x * v.hi.x) + (u.hi.y * v.lo.y + u.lo.y * v.hi.y) +
        (u.lo.x * v.lo.x + u.lo.y * v.lo.y));
  return s.two_term();
}
inline exact::TwoTerm compensated_cross(const ExactVec2& u, const ExactVec2& v) {
  exact::CompensatedSum s;
  s.add_product(u.hi.x, v.hi.y).add_product(-u.hi.y, v.hi.x);
  s.add((u.hi.x * v.lo.y + u.lo.x * v.hi.y) - (u.hi.y * v.lo.x + u.lo.y * v.hi.x) +
        (u.lo.x * v.lo.y - u.lo.y * v.lo.x));
  return s.two_term();
}
inline exact::TwoTerm compensated_dot(const ExactVec3& u, const ExactVec3& v) {
  exact::CompensatedSum s;
  s.add_product(u.hi.x, v.hi.x).add_product(u.hi.y, v.hi.y).add_product(u.hi.z, v.hi.z);
  s.add((u.hi.x * v.lo.x + u.lo.x * v.hi.x) + (u.hi.y * v.lo.y + u.lo.y * v.hi.y) +
        (u.hi.z * v.lo.z + u.lo.z * v.hi.z) +
        (u.lo.x * v.lo.x + u.lo.y * v.lo.y + u.lo.z * v.lo.z));
  return s.two_term();
}

// The slow paths, exact (out of line: they are rare, and keep the fast path small).
Certain exact_dot(const ExactVec2& u, const ExactVec2& v);
Certain exact_cross(const ExactVec2& u, const ExactVec2& v);
Certain exact_dot(const ExactVec3& u, const ExactVec3& v);
Certain exact_cross(const ExactVec3& u, const ExactVec3& v, int axis);
Certain exact_excess(const ExactVec2& v, const DecimalScalar& r);
Certain exact_excess(const ExactVec3& v, const DecimalScalar& r);
Certain exact_discriminant(const ExactVec2& u, const ExactVec2& v, const DecimalScalar& r);
Certain exact_discriminant(const ExactVec3& u, const ExactVec3& v, const DecimalScalar& r);

// What the decimals' rests may move u·v or u∧v by (their `err`), with margin: zero between
// doubles, so that the filter is then the one it always was.
inline double perturbation(const ExactVec2& u, const ExactVec2& v) {
  if (u.err == 0 && v.err == 0) return 0;
  const double nu = std::abs(u.hi.x) + std::abs(u.hi.y), nv = std::abs(v.hi.x) + std::abs(v.hi.y);
  return 2 * (u.err * (nv + 2 * v.err) + v.err * nu) + 0x1p-1060;
}
inline double perturbation(const ExactVec3& u, const ExactVec3& v) {
  if (u.err == 0 && v.err == 0) return 0;
  const double nu = std::abs(u.hi.x) + std::abs(u.hi.y) + std::abs(u.hi.z);
  const double nv = std::abs(v.hi.x) + std::abs(v.hi.y) + std::abs(v.hi.z);
  return 2 * (u.err * (nv + 3 * v.err) + v.err * nu) + 0x1p-1060;
}
Certain exact_sum_of_products(exact::TwoTerm x1, double y1, exact::TwoTerm x2, double y2);
}  // namespace detail

// u·v of exact vectors.
inline Certain certain_dot(const ExactVec2& u, const ExactVec2& v) {
  const exact::TwoTerm value = detail::compensated_dot(u, v);
  const double terms = std::abs(u.hi.x * v.hi.x) + std::abs(u.hi.y * v.hi.y);
  if (detail::value_certain(value.hi, detail::kCompensatedFilter * terms + detail::perturbation(u, v)))
    return {sign_of(value.hi), value.hi, value.lo};
  return detail::exact_dot(u, v);
}
inline Certain certain_dot(const ExactVec3& u, const ExactVec3& v) {
  const exact::TwoTerm value = detail::compensated_dot(u, v);
  const double terms =
      std::abs(u.hi.x * v.hi.x) + std::abs(u.hi.y * v.hi.y) + std::abs(u.hi.z * v.hi.z);
  if (detail::value_certain(value.hi, detail::kCompensatedFilter * terms + detail::perturbation(u, v)))
    return {sign_of(value.hi), value.hi, value.lo};
  return detail::exact_dot(u, v);
}

// u∧v of exact vectors.
inline Certain certain_cross(const ExactVec2& u, const ExactVec2& v) {
  const exact::TwoTerm value = detail::compensated_cross(u, v);
  const double terms = std::abs(u.hi.x * v.hi.y) + std::abs(u.hi.y * v.hi.x);
  if (detail::value_certain(value.hi, detail::kCompensatedFilter * terms + detail::perturbation(u, v)))
    return {sign_of(value.hi), value.hi, value.lo};
  return detail::exact_cross(u, v);
}

// One coordinate of u×v in space (axis 0, 1, 2: x, y, z), of exact vectors.
inline Certain certain_cross(const ExactVec3& u, const ExactVec3& v, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  auto at = [](const Vec3& w, int k) { return k == 0 ? w.x : k == 1 ? w.y : w.z; };
  const ExactVec2 a{{at(u.hi, i), at(u.hi, j)}, {at(u.lo, i), at(u.lo, j)}, u.err};
  const ExactVec2 b{{at(v.hi, i), at(v.hi, j)}, {at(v.lo, i), at(v.lo, j)}, v.err};
  const exact::TwoTerm value = detail::compensated_cross(a, b);
  const double terms = std::abs(a.hi.x * b.hi.y) + std::abs(a.hi.y * b.hi.x);
  if (detail::value_certain(value.hi, detail::kCompensatedFilter * terms + detail::perturbation(a, b)))
    return {sign_of(value.hi), value.hi, value.lo};
  return detail::exact_cross(u, v, axis);
}

// ‖v‖² − r² of an exact vector: the sign says outside (+), on (0) or inside (−) the circle.
// (r is a radius: a double, or a decimal datum with its rest, decimal_vec.h.)
inline Certain certain_excess(const ExactVec2& v, const DecimalScalar& radius) {
  const double r = radius.hi;
  exact::CompensatedSum s;
  s.add_product(v.hi.x, v.hi.x).add_product(v.hi.y, v.hi.y).add_product(-r, r);
  s.add(2 * (v.hi.x * v.lo.x + v.hi.y * v.lo.y) + (v.lo.x * v.lo.x + v.lo.y * v.lo.y));
  if (radius.lo != 0) s.add(-(2 * r + radius.lo) * radius.lo);
  const exact::TwoTerm value = s.two_term();
  const double terms = v.hi.x * v.hi.x + v.hi.y * v.hi.y + r * r;
  const double moved = v.err == 0 && radius.err == 0
                           ? 0
                           : 4 * (v.err * (std::abs(v.hi.x) + std::abs(v.hi.y) + v.err) +
                                  radius.err * (std::abs(r) + radius.err)) + 0x1p-1060;
  if (detail::value_certain(value.hi, detail::kCompensatedFilter * terms + moved))
    return {sign_of(value.hi), value.hi, value.lo};
  return detail::exact_excess(v, radius);
}
inline Certain certain_excess(const ExactVec3& v, const DecimalScalar& radius) {
  const double r = radius.hi;
  exact::CompensatedSum s;
  s.add_product(v.hi.x, v.hi.x).add_product(v.hi.y, v.hi.y).add_product(v.hi.z, v.hi.z);
  s.add_product(-r, r);
  s.add(2 * (v.hi.x * v.lo.x + v.hi.y * v.lo.y + v.hi.z * v.lo.z) +
        (v.lo.x * v.lo.x + v.lo.y * v.lo.y + v.lo.z * v.lo.z));
  if (radius.lo != 0) s.add(-(2 * r + radius.lo) * radius.lo);
  const exact::TwoTerm value = s.two_term();
  const double terms = v.hi.x * v.hi.x + v.hi.y * v.hi.y + v.hi.z * v.hi.z + r * r;
  const double moved =
      v.err == 0 && radius.err == 0
          ? 0
          : 4 * (v.err * (std::abs(v.hi.x) + std::abs(v.hi.y) + std::abs(v.hi.z) + v.err) +
                 radius.err * (std::abs(r) + radius.err)) + 0x1p-1060;
  if (detail::value_certain(value.hi, detail::kCompensatedFilter * terms + moved))
    return {sign_of(value.hi), value.hi, value.lo};
  return detail::exact_excess(v, radius);
}

// x1·y1 + x2·y2 for exact two-term x and double y.
inline Certain certain_sum_of_products(exact::TwoTerm x1, double y1, exact::TwoTerm x2, double y2) {
  const double value = (x1.hi * y1 + x2.hi * y2) + (x1.lo * y1 + x2.lo * y2);
  const double terms = std::abs(x1.hi * y1) + std::abs(x2.hi * y2);
  if (std::abs(value) > detail::kPlainFilter * terms) return {sign_of(value), value};
  return detail::exact_sum_of_products(x1, y1, x2, y2);
}

// ‖u‖²·r² − ‖u × v‖² (u∧v in 2D): ‖u‖² (r² − d²), d the distance from the line through the
// origin along u to the point v. Its sign says miss (−), tangent (0) or chord (+); its value
// keeps its digits near tangency, where r² − d² computed from d would be made of rounding.
// Double-double evaluation, with the exact expansion within 2^-40 of the terms (a chord of
// less than 1e-6 of the radius): there a double-double no longer gives √(r² − d²) to an ulp.
// u may be a decimal datum (its rest in u.lo, within u.err), as may r.
Certain certain_discriminant(const ExactVec2& u, const ExactVec2& v, const DecimalScalar& r);
Certain certain_discriminant(const ExactVec3& u, const ExactVec3& v, const DecimalScalar& r);
inline Certain certain_discriminant(Vec2 u, const ExactVec2& v, const DecimalScalar& r) {
  return certain_discriminant(as_exact(u), v, r);
}
inline Certain certain_discriminant(Vec3 u, const ExactVec3& v, const DecimalScalar& r) {
  return certain_discriminant(as_exact(u), v, r);
}

}  // namespace epure::geo
