#pragma once
// The course's square method written once for the square (2D) and the cube (3D). Internal to
// ray_square.cpp and ray_3d.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "geometry/box_faces.h"
#include "geometry/decimal.h"
#include "geometry/degenerate.h"
#include "geometry/exact.h"
#include "geometry/exponent.h"
#include "geometry/predicates.h"
#include "geometry/tolerance.h"
#include "geometry/vec.h"

namespace epure::geo::detail {

// A_k + (σ − A_n)·u_k / u_n: coordinate k of the point where the ray meets the plane x_n = σ,
// to about one rounding of the result. σ − A_n is kept exact, the product's and the quotient's
// rounding errors are carried, and A_k is added last: a ray from 1e8 lands on the unit square
// to the last digits of the landing point, not to ε·1e8.
inline double coordinate_on_face(double a_k, double sigma, double a_n, double u_k, double u_n) {
  const exact::TwoTerm gap = exact::two_difference(sigma, a_n);
  exact::TwoTerm product = exact::two_product(gap.hi, u_k);
  product.lo += gap.lo * u_k;
  const double quotient = product.hi / u_n;
  const double remainder = std::fma(-quotient, u_n, product.hi) + product.lo;  // exact, then ε²
  const exact::TwoTerm sum = exact::two_sum(a_k, quotient);
  return sum.hi + (sum.lo + remainder / u_n);
}

template <int Dim>
struct BoxResult {
  FaceSet<Dim> faces;
  bool inside = false;
  std::optional<double> t;
  std::array<double, Dim> I{};
  std::optional<Face> face;
};

template <int Dim>
BoxResult<Dim> intersect_box(const std::array<double, Dim>& A,
                             const std::array<double, Dim>& direction) {
  double largest_u = 0, largest_a = 1;
  for (int k = 0; k < Dim; ++k) {
    largest_u = std::max(largest_u, std::abs(direction[k]));
    largest_a = std::max(largest_a, std::abs(A[k]));
  }
  if (!(largest_u > 0)) throw DegenerateFigure("u", "zero direction");
  if (!std::isfinite(largest_u)) throw DegenerateFigure("u", "not a finite direction");

  // The direction brought near unit size by 2^-f (exact), so that no product below overflows or
  // underflows whatever its length; t is found in units of it and returned as t·2^-f.
  const int f = binary_exponent(largest_u);
  std::array<double, Dim> u;
  for (int k = 0; k < Dim; ++k) u[k] = times_pow2(direction[k], -f);
  largest_u = times_pow2(largest_u, -f);

  // A's coordinates are data or carried from another frame (a few ε of |A| off): a coordinate
  // that close to ±1 is on that side.
  const Near near{kRoundoff * largest_a};
  BoxResult<Dim> res;
  for (int sign : {+1, -1})
    for (int k = 0; k < Dim; ++k)
      if (!near.below(sign * A[k], 1.0)) res.faces.insert({k, sign});
  res.inside = res.faces.empty();

  // The point where the ray meets the face's plane; A itself at t = 0.
  auto point_at = [&](double t, Face face) {
    std::array<double, Dim> I;
    const int n = face.axis;
    for (int k = 0; k < Dim; ++k)
      I[k] = t > 0 ? coordinate_on_face(A[k], face.sign, A[n], u[k], u[n]) : A[k];
    I[n] = face.sign;  // on the side by construction: keep it there to the last bit
    return I;
  };

  if (res.inside) {
    // Leave through the side met first: along each axis the ray heads to the side of its sign.
    for (int k = 0; k < Dim; ++k) {
      if (!(std::abs(u[k]) > 0)) continue;  // parallel to these sides: never meets them
      const int sign = u[k] > 0 ? +1 : -1;
      const double t = (sign - A[k]) / u[k];  // A_k + t·u_k = σ
      if (!res.t || t < *res.t) {
        res.t = t;
        res.face = Face{k, sign};
      }
    }
    res.I = point_at(*res.t, *res.face);
    res.t = times_pow2(*res.t, -f);
    return res;
  }

  // From outside: only the candidate sides, each crossed where (A + t·u)·n = 1.
  res.faces.for_each([&](Face face) {
    const double u_n = face.sign * u[face.axis];
    if (!(u_n < 0)) return;  // not heading into this side
    const double a_n = face.sign * A[face.axis];
    const double t = std::max(0.0, (1.0 - a_n) / u_n);
    const auto I = point_at(t, face);
    // The point must lie on the side: every other coordinate within [-1, 1].
    const Near on_side{kRoundoff * std::max(largest_a, t * largest_u)};
    for (int k = 0; k < Dim; ++k)
      if (k != face.axis && on_side.above(std::abs(I[k]), 1.0)) return;
    // Of two valid candidates (a corner), the later one is where the ray enters (slab rule).
    if (!res.t || t > *res.t) {
      res.t = t;
      res.face = face;
      res.I = I;
    }
  });
  if (res.t) res.t = times_pow2(*res.t, -f);
  return res;
}

// c + s·x for a decimal datum x (decimal.h), c and s small integers: a gap 1 − A_k, a
// direction's coordinate. hi + lo within err of it; exactly, for the slow path.
struct Affine {
  double c = 0;
  double s = 1;
  const Decimal* x = nullptr;

  exact::TwoTerm value() const {
    const exact::TwoTerm a = exact::two_sum(c, s * x->hi);
    return exact::two_sum(a.hi, a.lo + s * x->lo);
  }
  double err() const {
    const exact::TwoTerm v = value();
    return x->error() + 0x1p-104 * std::abs(v.hi) + 0x1p-1074;
  }
  exact::ExactDecimal exact_value() const {
    exact::ExactDecimal v = exact::exact_value(*x);
    if (s < 0) v = -v;
    return c == 0 ? v : exact::exact_value(c) + v;
  }
};

// The exact sign of x1·y1 + x2·y2: a compensated evaluation, certain beyond its error and the
// decimals' rests' (predicates.h's filter), else exact decimals.
inline int sign_of_sum_of_products(const Affine& x1, const Affine& y1, const Affine& x2, const Affine& y2) {
  const exact::TwoTerm a = x1.value(), b = y1.value(), c = x2.value(), d = y2.value();
  exact::CompensatedSum sum;
  sum.add_product(a.hi, b.hi).add_product(c.hi, d.hi);
  sum.add((a.hi * b.lo + a.lo * b.hi) + (c.hi * d.lo + c.lo * d.hi));
  const double value = sum.two_term().hi;
  const double na = std::abs(a.hi) + std::abs(a.lo), nb = std::abs(b.hi) + std::abs(b.lo);
  const double nc = std::abs(c.hi) + std::abs(c.lo), nd = std::abs(d.hi) + std::abs(d.lo);
  const double terms = na * nb + nc * nd;
  const double ea = x1.err(), eb = y1.err(), ec = x2.err(), ed = y2.err();
  const double moved = 2 * (ea * (nb + eb) + eb * na + ec * (nd + ed) + ed * nc) + 0x1p-1060;
  if (std::abs(value) > kCompensatedFilter * terms + moved) return sign_of(value);
  return (x1.exact_value() * y1.exact_value() + x2.exact_value() * y2.exact_value()).sign();
}

// A double-double's few operations, for the values (each ε² of its operands off).
inline exact::TwoTerm dd_add(exact::TwoTerm a, exact::TwoTerm b) {
  const exact::TwoTerm s = exact::two_sum(a.hi, b.hi);
  return exact::two_sum(s.hi, s.lo + (a.lo + b.lo));
}
inline exact::TwoTerm dd_mul(exact::TwoTerm a, exact::TwoTerm b) {
  const exact::TwoTerm p = exact::two_product(a.hi, b.hi);
  return exact::two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
inline exact::TwoTerm dd_div(exact::TwoTerm a, exact::TwoTerm b) {
  const double q = a.hi / b.hi;
  const exact::TwoTerm r = dd_add(a, dd_mul({-q, 0}, b));  // a − q·b
  return exact::two_sum(q, r.hi / b.hi);
}

// The same, every decision exact for the numbers as written (decimal.h; doubles as
// themselves): epure solve's.
template <int Dim>
BoxResult<Dim> intersect_box_exact(const std::array<Decimal, Dim>& A,
                                   const std::array<Decimal, Dim>& direction) {
  double largest_u = 0;
  for (int k = 0; k < Dim; ++k) largest_u = std::max(largest_u, std::abs(direction[k].hi));
  if (!(largest_u > 0)) throw DegenerateFigure("u", "zero direction");
  if (!std::isfinite(largest_u)) throw DegenerateFigure("u", "not a finite direction");

  // The direction brought near unit size by 2^-f (exact), so that no product below overflows or
  // underflows whatever its length; t is found in units of it and returned as t·2^-f.
  const int f = binary_exponent(largest_u);
  std::array<Decimal, Dim> u;
  for (int k = 0; k < Dim; ++k) u[k] = times_pow2(direction[k], -f);
  const auto sign_u = [&](int k) { return u[k].hi != 0 ? sign_of(u[k].hi) : sign_of(u[k].lo); };
  const auto two = [](const Decimal& x) { return exact::TwoTerm{x.hi, x.lo}; };

  // Candidate sides: the closed outer half-planes that hold A, σ·A_k ≥ 1, exactly. A on a side
  // is outside, its side a candidate.
  const Decimal one = Decimal::of(1), minus_one = Decimal::of(-1);
  BoxResult<Dim> res;
  for (int sign : {+1, -1})
    for (int k = 0; k < Dim; ++k)
      if (sign > 0 ? compare(A[k], one) >= 0 : compare(A[k], minus_one) <= 0) res.faces.insert({k, sign});
  res.inside = res.faces.empty();

  // The gap from A to the plane of side (k, σ), measured along σ·e_k: |σ − A_k| = ±(1 − σ·A_k),
  // + inside, − from a candidate side.
  auto gap = [&](Face face) {
    const double s = res.inside ? 1 : -1;
    return Affine{s, -s * face.sign, &A[face.axis]};
  };
  auto abs_u = [&](int k) { return Affine{0, static_cast<double>(sign_u(k)), &u[k]}; };
  // The parameter of that plane, t = gap / |u_n|, is earlier for side j than for side k when
  // gap_j·|u_k| < gap_k·|u_j|: exact. Ties go to the first side listed (x).
  auto earlier = [&](Face j, Face k) {
    const Affine gk = gap(k);
    return sign_of_sum_of_products(gap(j), abs_u(k.axis), Affine{-gk.c, -gk.s, gk.x}, abs_u(j.axis)) < 0;
  };
  // t in units of u: (σ − A_n) / u_n.
  auto t_of = [&](Face face) {
    const int n = face.axis;
    return dd_div(dd_add({static_cast<double>(face.sign), 0}, {-A[n].hi, -A[n].lo}), two(u[n]));
  };
  // The point where the ray meets the face's plane; A itself at t = 0. A_k + (σ − A_n)·u_k / u_n
  // with the decimals' rests: a ray from 1e8 lands on the unit square to its last digits.
  auto point_at = [&](double t, Face face) {
    std::array<double, Dim> I;
    const int n = face.axis;
    const exact::TwoTerm along = t_of(face);
    for (int k = 0; k < Dim; ++k) {
      const exact::TwoTerm p = dd_add(two(A[k]), dd_mul(along, two(u[k])));
      I[k] = t > 0 ? p.hi + p.lo : A[k].hi;
    }
    I[n] = face.sign;  // on the side by construction: keep it there to the last bit
    // on the side (decided exactly below): keep every coordinate within it
    for (int k = 0; k < Dim; ++k) I[k] = std::clamp(I[k], -1.0, 1.0);
    return I;
  };

  if (res.inside) {
    // Leave through the side met first: along each axis the ray heads to the side of its sign.
    for (int k = 0; k < Dim; ++k) {
      if (sign_u(k) == 0) continue;  // parallel to these sides: never meets them
      const Face face{k, sign_u(k)};
      if (!res.face || earlier(face, *res.face)) res.face = face;
    }
    const exact::TwoTerm t = t_of(*res.face);
    res.t = t.hi + t.lo;
    res.I = point_at(*res.t, *res.face);
    res.t = times_pow2(*res.t, -f);
    return res;
  }

  // From outside: only the candidate sides, each crossed where (A + t·u)·n = 1, t = gap / |u_n|,
  // if the ray heads into it (u·n < 0) and that point lies on the side: for every other axis j,
  // |A_j + t·u_j| ≤ 1, i.e. (1 ∓ A_j)·|u_n| ∓ gap·u_j ≥ 0 for both signs (exact).
  res.faces.for_each([&](Face face) {
    if (!(face.sign * sign_u(face.axis) < 0)) return;  // not heading into this side
    const Affine g = gap(face);
    for (int j = 0; j < Dim; ++j) {
      if (j == face.axis) continue;
      for (int side : {+1, -1}) {
        const Affine room{1, static_cast<double>(-side), &A[j]};  // 1 ∓ A_j
        const Affine minus_g{-g.c, -g.s, g.x};
        if (sign_of_sum_of_products(room, abs_u(face.axis), minus_g, Affine{0, static_cast<double>(side), &u[j]}) < 0)
          return;
      }
    }
    // Of two valid candidates the later is where the ray enters (slab rule); from outside that
    // happens only at a corner, at the same t, and there the x side is taken first.
    if (res.face) {
      const bool later = earlier(*res.face, face);
      const bool tie = !later && !earlier(face, *res.face);
      if (!later && !(tie && face.axis < res.face->axis)) return;
    }
    const exact::TwoTerm t = t_of(face);
    res.t = std::max(0.0, t.hi + t.lo);
    res.face = face;
    res.I = point_at(*res.t, face);
  });
  if (res.t) res.t = times_pow2(*res.t, -f);
  return res;
}

template <int Dim>
BoxResult<Dim> intersect_box_exact(const std::array<double, Dim>& A, const std::array<double, Dim>& direction) {
  std::array<Decimal, Dim> a, u;
  for (int k = 0; k < Dim; ++k) a[k] = Decimal::of(A[k]), u[k] = Decimal::of(direction[k]);
  return intersect_box_exact<Dim>(a, u);
}

}  // namespace epure::geo::detail
