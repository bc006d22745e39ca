#include "geometry/predicates.h"

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

}  // namespace

namespace detail {

Certain exact_dot(const ExactVec2& u, const ExactVec2& v) {
  const Exact2 a = of(u), b = of(v);
  return certain(a.x * b.x + a.y * b.y);
}
Certain exact_cross(const ExactVec2& u, const ExactVec2& v) {
  const Exact2 a = of(u), b = of(v);
  return certain(a.x * b.y - a.y * b.x);
}
Certain exact_dot(const ExactVec3& u, const ExactVec3& v) {
  const Exact3 a = of(u), b = of(v);
  return certain(a.x * b.x + a.y * b.y + a.z * b.z);
}
Certain exact_excess(const ExactVec2& v, double r) {
  const Exact2 a = of(v);
  return certain(a.x * a.x + a.y * a.y - Expansion::product(r, r));
}
Certain exact_excess(const ExactVec3& v, double r) {
  const Exact3 a = of(v);
  return certain(a.x * a.x + a.y * a.y + a.z * a.z - Expansion::product(r, r));
}
Certain exact_discriminant(Vec2 u, const ExactVec2& v, double r) {
  const Exact2 a = of(v);
  const Expansion ux(u.x), uy(u.y);
  const Expansion c = ux * a.y - uy * a.x;
  return certain((ux * ux + uy * uy) * Expansion::product(r, r) - c * c);
}
Certain exact_discriminant(Vec3 u, const ExactVec3& v, double r) {
  const Exact3 a = of(v);
  const Expansion ux(u.x), uy(u.y), uz(u.z);
  const Expansion nx = uy * a.z - uz * a.y, ny = uz * a.x - ux * a.z, nz = ux * a.y - uy * a.x;
  return certain((ux * ux + uy * uy + uz * uz) * Expansion::product(r, r) -
                 (nx * nx + ny * ny + nz * nz));
}
Certain exact_sum_of_products(exact::TwoTerm x1, double y1, exact::TwoTerm x2, double y2) {
  return certain(of(x1.hi, x1.lo) * Expansion(y1) + of(x2.hi, x2.lo) * Expansion(y2));
}

}  // namespace detail

EPURE_FMA_CLONES Certain certain_discriminant(Vec2 u, const ExactVec2& v, double r) {
  // c = u∧v as a double-double, then ‖u‖²·r² − c²
  const DD c = dd_product(u.x, v.hi.y) + -dd_product(u.y, v.hi.x) +
               dd(u.x * v.lo.y - u.y * v.lo.x);
  const DD uu = dd_product(u.x, u.x) + dd_product(u.y, u.y);
  const DD rr = dd_product(r, r);
  const DD q = uu * rr, cc = square(c);
  const DD value = q + -cc;
  struct Data {
    Vec2 u;
    const ExactVec2* v;
    double r;
  } data{u, &v, r};
  // c's own error (ε² of its products) doubled by the square
  const double c_terms = std::abs(u.x * v.hi.y) + std::abs(u.y * v.hi.x);
  return finish(value, q.hi + cc.hi + 2 * std::abs(c.hi) * c_terms,
                [](const void* p) {
                  const auto* d = static_cast<const Data*>(p);
                  return detail::exact_discriminant(d->u, *d->v, d->r);
                },
                &data);
}

EPURE_FMA_CLONES Certain certain_discriminant(Vec3 u, const ExactVec3& v, double r) {
  auto pair = [](double ui, double uj, double vi_hi, double vi_lo, double vj_hi, double vj_lo) {
    // ui·vj − uj·vi
    return dd_product(ui, vj_hi) + -dd_product(uj, vi_hi) + dd(ui * vj_lo - uj * vi_lo);
  };
  const DD nx = pair(u.y, u.z, v.hi.y, v.lo.y, v.hi.z, v.lo.z);
  const DD ny = pair(u.z, u.x, v.hi.z, v.lo.z, v.hi.x, v.lo.x);
  const DD nz = pair(u.x, u.y, v.hi.x, v.lo.x, v.hi.y, v.lo.y);
  const DD uu = dd_product(u.x, u.x) + dd_product(u.y, u.y) + dd_product(u.z, u.z);
  const DD q = uu * dd_product(r, r), nn = square(nx) + square(ny) + square(nz);
  const DD value = q + -nn;
  struct Data {
    Vec3 u;
    const ExactVec3* v;
    double r;
  } data{u, &v, r};
  const double n_terms = plain_norm(Vec3{std::abs(u.x), std::abs(u.y), std::abs(u.z)}) *
                         plain_norm(v.hi) * 2;
  return finish(value, q.hi + nn.hi + 2 * std::sqrt(nn.hi) * n_terms,
                [](const void* p) {
                  const auto* d = static_cast<const Data*>(p);
                  return detail::exact_discriminant(d->u, *d->v, d->r);
                },
                &data);
}

}  // namespace epure::geo
