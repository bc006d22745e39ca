#pragma once
// Vectors between data points, kept exact, and their dot and cross products rounded about once.
//
// B − A rounded to a double is off by up to half an ulp of its coordinates. That is harmless in
// most formulas, but not in a nearly vanishing product: AB∧CD of nearly parallel segments is
// made of the last digits of AB and CD, so their rounding would become its leading digits (a
// relative error of ε / sin of the angle). Keeping each difference as hi + lo (exactly B − A)
// and summing the products with their rounding errors leaves such a product correct to about ε
// of itself: t = AC∧CD / AB∧CD keeps its digits however close to parallel the lines are.
#include "geometry/exact.h"
#include "geometry/vec.h"

namespace epure::geo {

struct Decimal;

// hi + lo is the vector exactly; hi alone is its rounded value. A vector between decimals
// (decimal.h) is hi + lo to within `err` in each coordinate, and keeps what it is made of for
// the exact slow path of a decision (predicates.h): (to − from)·2^shift, `from` null for a datum
// itself; `to` null when hi + lo is exact.
struct ExactVec2 {
  Vec2 hi, lo;
  double err = 0;
  const Decimal* to = nullptr;
  const Decimal* from = nullptr;
  int shift = 0;
};
struct ExactVec3 {
  Vec3 hi, lo;
  double err = 0;
  const Decimal* to = nullptr;
  const Decimal* from = nullptr;
  int shift = 0;
};

// b − a, exactly (barring overflow).
inline ExactVec2 exact_difference(Point2 b, Point2 a) {
  const exact::TwoTerm x = exact::two_difference(b.x, a.x), y = exact::two_difference(b.y, a.y);
  return {{x.hi, y.hi}, {x.lo, y.lo}};
}
inline ExactVec3 exact_difference(Point3 b, Point3 a) {
  const exact::TwoTerm x = exact::two_difference(b.x, a.x), y = exact::two_difference(b.y, a.y),
                       z = exact::two_difference(b.z, a.z);
  return {{x.hi, y.hi, z.hi}, {x.lo, y.lo, z.lo}};
}

// A vector that is data as it stands (a direction), with nothing lost.
inline ExactVec2 as_exact(Vec2 v) { return {v, {0, 0}}; }
inline ExactVec3 as_exact(Vec3 v) { return {v, {0, 0, 0}}; }

// (a + a') ∘ (b + b') = a∘b + (a∘b' + a'∘b + a'∘b'): the first products compensated, the rest
// (ε-small beside them) in plain arithmetic, whose rounding is then ε² of the whole.
inline double dot(const ExactVec2& u, const ExactVec2& v) {
  exact::CompensatedSum s;
  s.add_product(u.hi.x, v.hi.x).add_product(u.hi.y, v.hi.y);
  s.add((u.hi.x * v.lo.x + u.lo.x * v.hi.x) + (u.hi.y * v.lo.y + u.lo.y * v.hi.y) +
        (u.lo.x * v.lo.x + u.lo.y * v.lo.y));
  return s.value();
}
inline double cross(const ExactVec2& u, const ExactVec2& v) {
  exact::CompensatedSum s;
  s.add_product(u.hi.x, v.hi.y).add_product(-u.hi.y, v.hi.x);
  s.add((u.hi.x * v.lo.y + u.lo.x * v.hi.y) - (u.hi.y * v.lo.x + u.lo.y * v.hi.x) +
        (u.lo.x * v.lo.y - u.lo.y * v.lo.x));
  return s.value();
}

namespace detail {
// u_i·v_j − u_j·v_i of exact coordinates: the 2D cross of two coordinate pairs.
inline double cross_pair(double ui, double ui_lo, double uj, double uj_lo, double vi, double vi_lo,
                         double vj, double vj_lo) {
  return cross(ExactVec2{{ui, uj}, {ui_lo, uj_lo}}, ExactVec2{{vi, vj}, {vi_lo, vj_lo}});
}
}  // namespace detail

inline double dot(const ExactVec3& u, const ExactVec3& v) {
  exact::CompensatedSum s;
  s.add_product(u.hi.x, v.hi.x).add_product(u.hi.y, v.hi.y).add_product(u.hi.z, v.hi.z);
  s.add((u.hi.x * v.lo.x + u.lo.x * v.hi.x) + (u.hi.y * v.lo.y + u.lo.y * v.hi.y) +
        (u.hi.z * v.lo.z + u.lo.z * v.hi.z) +
        (u.lo.x * v.lo.x + u.lo.y * v.lo.y + u.lo.z * v.lo.z));
  return s.value();
}
inline Vec3 cross(const ExactVec3& u, const ExactVec3& v) {
  return {detail::cross_pair(u.hi.y, u.lo.y, u.hi.z, u.lo.z, v.hi.y, v.lo.y, v.hi.z, v.lo.z),
          detail::cross_pair(u.hi.z, u.lo.z, u.hi.x, u.lo.x, v.hi.z, v.lo.z, v.hi.x, v.lo.x),
          detail::cross_pair(u.hi.x, u.lo.x, u.hi.y, u.lo.y, v.hi.x, v.lo.x, v.hi.y, v.lo.y)};
}

}  // namespace epure::geo
