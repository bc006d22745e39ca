#include "geometry/affine.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/degenerate.h"
#include "geometry/exact.h"
#include "support/sin_cos.h"

namespace epure::geo {

namespace {

Affine2Matrix multiply(const Affine2Matrix& p, const Affine2Matrix& q) {  // p ∘ q
  return {p.a * q.a + p.b * q.c, p.a * q.b + p.b * q.d,
          p.c * q.a + p.d * q.c, p.c * q.b + p.d * q.d,
          p.a * q.e + p.b * q.f + p.e, p.c * q.e + p.d * q.f + p.f};
}

}  // namespace

Transform2::Transform2(const Affine2Matrix& m) : m_(m) {
  const double det = exact::difference_of_products(m.a, m.d, m.b, m.c);
  // Singular only when the columns are parallel to rounding: relative to their sizes.
  const double size = portable::hypot(m.a, m.c) * portable::hypot(m.b, m.d);
  if (!(std::abs(det) > 64 * std::numeric_limits<double>::epsilon() * size))
    throw DegenerateFigure("transform", "singular matrix, no inverse");
  // [a b; c d]⁻¹ = [d −b; −c a] / det, and the translation follows: −M⁻¹·(e, f)
  inv_.a = m.d / det;
  inv_.b = -m.b / det;
  inv_.c = -m.c / det;
  inv_.d = m.a / det;
  inv_.e = -(inv_.a * m.e + inv_.b * m.f);
  inv_.f = -(inv_.c * m.e + inv_.d * m.f);
}

Transform2 Transform2::translate(Vec2 by) {
  return Transform2({1, 0, 0, 1, by.x, by.y}, {1, 0, 0, 1, -by.x, -by.y});
}

Transform2 Transform2::rotate_degrees(double degrees) {
  const auto [c, s] = cos_sin_degrees(degrees);
  return Transform2({c, -s, s, c, 0, 0}, {c, s, -s, c, 0, 0});
}

Transform2 Transform2::scale(double sx, double sy) {
  if (!(sx != 0) || !(sy != 0) || !std::isfinite(1 / sx) || !std::isfinite(1 / sy))
    throw DegenerateFigure("scale", "zero scale factor, no inverse");
  return Transform2({sx, 0, 0, sy, 0, 0}, {1 / sx, 0, 0, 1 / sy, 0, 0});
}

Transform2 Transform2::operator*(const Transform2& inner) const {
  // (M∘N)⁻¹ = N⁻¹∘M⁻¹
  return Transform2(multiply(m_, inner.m_), multiply(inner.inv_, inv_));
}

Point2 Transform2::apply(Point2 p) const {
  return {m_.a * p.x + m_.b * p.y + m_.e, m_.c * p.x + m_.d * p.y + m_.f};
}

Vec2 Transform2::apply(Vec2 v) const { return {m_.a * v.x + m_.b * v.y, m_.c * v.x + m_.d * v.y}; }

Vec2 Transform2::apply_normal(Vec2 n) const {
  // (M⁻¹)ᵀ = [inv.a inv.c; inv.b inv.d]
  return {inv_.a * n.x + inv_.c * n.y, inv_.b * n.x + inv_.d * n.y};
}

CosSin cos_sin_degrees(double degrees) {
  // No angle, no rotation (and no int conversion of a NaN quarter below, which is undefined).
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (!std::isfinite(degrees)) return {nan, nan};
  // Reduce to a quarter turn q and a remainder in [−45°, 45°]; both steps are exact (fmod is,
  // and so is subtracting a multiple of 90° from an angle within 45° of it), and a zero
  // remainder gives exact quarter turns.
  double turns = std::fmod(degrees, 360.0);
  const double quarter = std::nearbyint(turns / 90.0);
  const double rest = turns - 90.0 * quarter;
  const double radians = rest * (std::numbers::pi / 180.0);
  double c, s;
  portable::sin_cos_quarter_fast(radians, s, c);  // correctly rounded: the same bits everywhere
  switch (((static_cast<int>(quarter) % 4) + 4) % 4) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

}  // namespace epure::geo
