#include "geometry/predicates.h"

#include <algorithm>

#include "geometry/decimal.h"
#include "geometry/expansion.h"
#include "support/fma_clones.h"

namespace epure::geo {

namespace {

using exact::Expansion;

// The exact value of hi + lo.
Expansion of(double hi, double lo) { return Expansion(hi) + Expansion(lo); }

Certain certain(const Expansion& e) {
  const exact::TwoTerm v = e.two_term();
  return {e.sign(), v.hi, v.lo};
}

struct Exact2 {
  Expansion x, y;
};
struct Exact3 {
  Expansion x, y, z;
};
Exact2 of(const ExactVec2& v) { return {of(v.hi.x, v.lo.x), of(v.hi.y, v.lo.y)}; }
Exact3 of(const ExactVec3& v) {
  return {of(v.hi.x, v.lo.x), of(v.hi.y, v.lo.y), of(v.hi.z, v.lo.z)};
}

// A double-double: hi + lo, |lo| ≤ ulp(hi)/2, each operation ε² of its operands off.
struct DD {
  double hi = 0, lo = 0;
};
DD normalized(double hi, double lo) {
  const exact::TwoTerm s = exact::two_sum(hi, lo);
  return {s.hi, s.lo};
}
DD operator+(DD a, DD b) {
  const exact::TwoTerm s = exact::two_sum(a.hi, b.hi);
  return normalized(s.hi, s.lo + (a.lo + b.lo));
}
DD operator-(DD a) { return {-a.hi, -a.lo}; }
DD operator*(DD a, DD b) {
  const exact::TwoTerm p = exact::two_product(a.hi, b.hi);
  return normalized(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
DD square(DD a) { return a * a; }
DD dd(double x) { return {x, 0}; }
DD dd_product(double a, double b) {
  const exact::TwoTerm p = exact::two_product(a, b);
  return {p.hi, p.lo};
}

// The discriminant's double-double value and the sum of its terms' magnitudes: certain beyond
// 2^-40 of them (well above the double-double's own error, ~16 ε² of them: see the header).
constexpr double kDiscriminantFilter = 0x1p-40;

Certain finish(DD value, double terms, Certain (*slow)(const void*), const void* data) {
  // the low part too: the lengths solve prints (ray_ball.h) take r² − d² to ε² of itself
  if (std::abs(value.hi) > kDiscriminantFilter * terms) return {sign_of(value.hi), value.hi, value.lo};
  return slow(data);
}

// ---- The slow path on decimals: every coordinate as an exact decimal (decimal.h), so that the
// sign is the one of the numbers as written, whatever their binary rounding.
using exact::ExactDecimal;

ExactDecimal exact_coordinate(const Decimal* to, const Decimal* from, int i, int shift, double hi, double lo) {
  if (!to) return exact::exact_value(hi) + exact::exact_value(lo);
  ExactDecimal x = exact::exact_value(to[i]);
  if (from) x = x - exact::exact_value(from[i]);
  return exact::times_pow2(x, shift);
}
struct Decimal2 {
  ExactDecimal x, y;
};
struct Decimal3 {
  ExactDecimal x, y, z;
};
Decimal2 decimal_of(const ExactVec2& v) {
  return {exact_coordinate(v.to, v.from, 0, v.shift, v.hi.x, v.lo.x),
          exact_coordinate(v.to, v.from, 1, v.shift, v.hi.y, v.lo.y)};
}
Decimal3 decimal_of(const ExactVec3& v) {
  return {exact_coordinate(v.to, v.from, 0, v.shift, v.hi.x, v.lo.x),
          exact_coordinate(v.to, v.from, 1, v.shift, v.hi.y, v.lo.y),
          exact_coordinate(v.to, v.from, 2, v.shift, v.hi.z, v.lo.z)};
}
ExactDecimal decimal_of(const DecimalScalar& r) {
  if (!r.exact) return exact::exact_value(r.hi) + exact::exact_value(r.lo);
  return exact::times_pow2(exact::exact_value(*r.exact), r.shift);
}
Certain certain(const ExactDecimal& x) {
  const exact::TwoTerm v = exact::two_term(x);
  return {x.sign(), v.hi, v.lo};
}
// Whether a slow path must read decimals: the binary expansions are exact only for doubles.
bool decimal(const ExactVec2& v) { return v.to != nullptr; }
bool decimal(const ExactVec3& v) { return v.to != nullptr; }
bool decimal(const DecimalScalar& r) { return r.exact != nullptr && r.lo != 0; }

}  // namespace

namespace detail {

Certain exact_dot(const ExactVec2& u, const ExactVec2& v) {
  if (decimal(u) || decimal(v)) {
    const Decimal2 a = decimal_of(u), b = decimal_of(v);
    return certain(a.x * b.x + a.y * b.y);
  }
  const Exact2 a = of(u), b = of(v);
  return certain(a.x * b.x + a.y * b.y);
}
Certain exact_cross(const ExactVec2& u, const ExactVec2& v) {
  if (decimal(u) || decimal(v)) {
    const Decimal2 a = decimal_of(u), b = decimal_of(v);
    return certain(a.x * b.y - a.y * b.x);
  }
  const Exact2 a = of(u), b = of(v);
  return certain(a.x * b.y - a.y * b.x);
}
Certain exact_cross(const ExactVec3& u, const ExactVec3& v, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  if (decimal(u) || decimal(v)) {
    const Decimal3 a = decimal_of(u), b = decimal_of(v);
    const ExactDecimal* ac[] = {&a.x, &a.y, &a.z};
    const ExactDecimal* bc[] = {&b.x, &b.y, &b.z};
    return certain(*ac[i] * *bc[j] - *ac[j] * *bc[i]);
  }
  const Exact3 a = of(u), b = of(v);
  const Expansion* ac[] = {&a.x, &a.y, &a.z};
  const Expansion* bc[] = {&b.x, &b.y, &b.z};
  return certain(*ac[i] * *bc[j] - *ac[j] * *bc[i]);
}
Certain exact_dot(const ExactVec3& u, const ExactVec3& v) {
  if (decimal(u) || decimal(v)) {
    const Decimal3 a = decimal_of(u), b = decimal_of(v);
    return certain(a.x * b.x + a.y * b.y + a.z * b.z);
  }
  const Exact3 a = of(u), b = of(v);
  return certain(a.x * b.x + a.y * b.y + a.z * b.z);
}
Certain exact_excess(const ExactVec2& v, const DecimalScalar& r) {
  if (decimal(v) || decimal(r)) {
    const Decimal2 a = decimal_of(v);
    const ExactDecimal rr = decimal_of(r);
    return certain(a.x * a.x + a.y * a.y - rr * rr);
  }
  const Exact2 a = of(v);
  return certain(a.x * a.x + a.y * a.y - Expansion::product(r.hi, r.hi));
}
Certain exact_excess(const ExactVec3& v, const DecimalScalar& r) {
  if (decimal(v) || decimal(r)) {
    const Decimal3 a = decimal_of(v);
    const ExactDecimal rr = decimal_of(r);
    return certain(a.x * a.x + a.y * a.y + a.z * a.z - rr * rr);
  }
  const Exact3 a = of(v);
  return certain(a.x * a.x + a.y * a.y + a.z * a.z - Expansion::product(r.hi, r.hi));
}
Certain exact_discriminant(const ExactVec2& u, const ExactVec2& v, const DecimalScalar& r) {
  if (decimal(u) || decimal(v) || decimal(r)) {
    const Decimal2 a = decimal_of(v), w = decimal_of(u);
    const ExactDecimal rr = decimal_of(r);
    const ExactDecimal c = w.x * a.y - w.y * a.x;
    return certain((w.x * w.x + w.y * w.y) * (rr * rr) - c * c);
  }
  const Exact2 a = of(v), w = of(u);
  const Expansion c = w.x * a.y - w.y * a.x;
  return certain((w.x * w.x + w.y * w.y) * Expansion::product(r.hi, r.hi) - c * c);
}
Certain exact_discriminant(const ExactVec3& u, const ExactVec3& v, const DecimalScalar& r) {
  if (decimal(u) || decimal(v) || decimal(r)) {
    const Decimal3 a = decimal_of(v), w = decimal_of(u);
    const ExactDecimal rr = decimal_of(r);
    const ExactDecimal nx = w.y * a.z - w.z * a.y, ny = w.z * a.x - w.x * a.z, nz = w.x * a.y - w.y * a.x;
    return certain((w.x * w.x + w.y * w.y + w.z * w.z) * (rr * rr) - (nx * nx + ny * ny + nz * nz));
  }
  const Exact3 a = of(v), w = of(u);
  const Expansion nx = w.y * a.z - w.z * a.y, ny = w.z * a.x - w.x * a.z, nz = w.x * a.y - w.y * a.x;
  return certain((w.x * w.x + w.y * w.y + w.z * w.z) * Expansion::product(r.hi, r.hi) -
                 (nx * nx + ny * ny + nz * nz));
}
Certain exact_sum_of_products(exact::TwoTerm x1, double y1, exact::TwoTerm x2, double y2) {
  return certain(of(x1.hi, x1.lo) * Expansion(y1) + of(x2.hi, x2.lo) * Expansion(y2));
}

}  // namespace detail

namespace {

// (r + r')² = r² + (2r + r')·r' as a double-double: r' a decimal's rest (decimal_vec.h)
DD squared(const DecimalScalar& r) {
  const DD rr = dd_product(r.hi, r.hi);
  return r.lo == 0 ? rr : rr + dd((2 * r.hi + r.lo) * r.lo);
}

// How far the rests of decimal data (their err) may move ‖u‖²r² − ‖u∧v‖², over 2^-40 (the
// filter's factor): ‖u∧v‖ = c moves by ‖u‖₁err_v + ‖v‖₁err_u, ‖u‖²r² by a relative 2err_u/|u| + 2err_r/r.
double moved_by(double c, double nu, double nv, double err_u, double err_v, double q, double largest_u,
                const DecimalScalar& r) {
  if (err_u == 0 && err_v == 0 && r.err == 0) return 0;
  const double dc = nu * err_v + nv * err_u + 2 * err_u * err_v;
  const double dq = q * (4 * err_u / largest_u + 4 * r.err / r.hi);
  return 0x1p42 * (2 * (c + dc) * dc + dq) + 0x1p-1000;
}

}  // namespace

EPURE_FMA_CLONES Certain certain_discriminant(const ExactVec2& w, const ExactVec2& v, const DecimalScalar& r) {
  // c = u∧v as a double-double, then ‖u‖²·r² − c²; u's rest (a decimal datum's) beside v's
  const Vec2 u = w.hi, ul = w.lo;
  const DD c = dd_product(u.x, v.hi.y) + -dd_product(u.y, v.hi.x) +
               dd((u.x * v.lo.y - u.y * v.lo.x) + (ul.x * v.hi.y - ul.y * v.hi.x));
  const DD uu = dd_product(u.x, u.x) + dd_product(u.y, u.y) + dd(2 * (u.x * ul.x + u.y * ul.y));
  const DD rr = squared(r);
  const DD q = uu * rr, cc = square(c);
  const DD value = q + -cc;
  struct Data {
    const ExactVec2* u;
    const ExactVec2* v;
    const DecimalScalar* r;
  } data{&w, &v, &r};
  // c's own error (ε² of its products) doubled by the square
  const double c_terms = std::abs(u.x * v.hi.y) + std::abs(u.y * v.hi.x);
  // what the decimals' rests may move it by (nothing between doubles)
  const double moved = moved_by(std::abs(c.hi), std::abs(u.x) + std::abs(u.y), std::abs(v.hi.x) + std::abs(v.hi.y),
                                w.err, v.err, q.hi, std::max(std::abs(u.x), std::abs(u.y)), r);
  return finish(value, q.hi + cc.hi + 2 * std::abs(c.hi) * c_terms + moved,
                [](const void* p) {
                  const auto* d = static_cast<const Data*>(p);
                  return detail::exact_discriminant(*d->u, *d->v, *d->r);
                },
                &data);
}

EPURE_FMA_CLONES Certain certain_discriminant(const ExactVec3& w, const ExactVec3& v, const DecimalScalar& r) {
  auto pair = [](double ui, double ui_lo, double uj, double uj_lo, double vi_hi, double vi_lo, double vj_hi,
                 double vj_lo) {
    // ui·vj − uj·vi
    return dd_product(ui, vj_hi) + -dd_product(uj, vi_hi) +
           dd((ui * vj_lo - uj * vi_lo) + (ui_lo * vj_hi - uj_lo * vi_hi));
  };
  const Vec3 u = w.hi, ul = w.lo;
  const DD nx = pair(u.y, ul.y, u.z, ul.z, v.hi.y, v.lo.y, v.hi.z, v.lo.z);
  const DD ny = pair(u.z, ul.z, u.x, ul.x, v.hi.z, v.lo.z, v.hi.x, v.lo.x);
  const DD nz = pair(u.x, ul.x, u.y, ul.y, v.hi.x, v.lo.x, v.hi.y, v.lo.y);
  const DD uu = dd_product(u.x, u.x) + dd_product(u.y, u.y) + dd_product(u.z, u.z) +
                dd(2 * (u.x * ul.x + u.y * ul.y + u.z * ul.z));
  const DD q = uu * squared(r), nn = square(nx) + square(ny) + square(nz);
  const DD value = q + -nn;
  struct Data {
    const ExactVec3* u;
    const ExactVec3* v;
    const DecimalScalar* r;
  } data{&w, &v, &r};
  const double n_terms = plain_norm(Vec3{std::abs(u.x), std::abs(u.y), std::abs(u.z)}) *
                         plain_norm(v.hi) * 2;
  const double moved =
      moved_by(std::sqrt(nn.hi), std::abs(u.x) + std::abs(u.y) + std::abs(u.z),
               std::abs(v.hi.x) + std::abs(v.hi.y) + std::abs(v.hi.z), w.err, v.err, q.hi,
               std::max({std::abs(u.x), std::abs(u.y), std::abs(u.z)}), r);
  return finish(value, q.hi + nn.hi + 2 * std::sqrt(nn.hi) * n_terms + moved,
                [](const void* p) {
                  const auto* d = static_cast<const Data*>(p);
                  return detail::exact_discriminant(*d->u, *d->v, *d->r);
                },
                &data);
}

}  // namespace epure::geo
