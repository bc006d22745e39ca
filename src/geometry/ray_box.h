#pragma once
// The course's square method written once for the square (2D) and the cube (3D). Internal to
// ray_square.cpp and ray_3d.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "geometry/box_faces.h"
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

// The same, every decision exact for the given doubles (predicates.h): epure solve's.
template <int Dim>
BoxResult<Dim> intersect_box_exact(const std::array<double, Dim>& A,
                             const std::array<double, Dim>& direction) {
  double largest_u = 0;
  for (int k = 0; k < Dim; ++k) largest_u = std::max(largest_u, std::abs(direction[k]));
  if (!(largest_u > 0)) throw DegenerateFigure("u", "zero direction");
  if (!std::isfinite(largest_u)) throw DegenerateFigure("u", "not a finite direction");

  // The direction brought near unit size by 2^-f (exact), so that no product below overflows or
  // underflows whatever its length; t is found in units of it and returned as t·2^-f.
  const int f = binary_exponent(largest_u);
  std::array<double, Dim> u;
  for (int k = 0; k < Dim; ++k) u[k] = times_pow2(direction[k], -f);
  largest_u = times_pow2(largest_u, -f);

  // Candidate sides: the closed outer half-planes that hold A, σ·A_k ≥ 1 — a comparison of
  // doubles, exact. A on a side is outside, its side a candidate.
  BoxResult<Dim> res;
  for (int sign : {+1, -1})
    for (int k = 0; k < Dim; ++k)
      if (!(sign * A[k] < 1.0)) res.faces.insert({k, sign});
  res.inside = res.faces.empty();

  // The gap from A to the plane of side (k, σ), measured along σ·e_k: |σ − A_k|, exact.
  auto gap = [&](Face face) {
    const exact::TwoTerm g = exact::two_difference(1.0, face.sign * A[face.axis]);
    return g.hi < 0 ? exact::TwoTerm{-g.hi, -g.lo} : g;
  };
  // The parameter of that plane, t = gap / |u_n|, is earlier for side j than for side k when
  // gap_j·|u_k| < gap_k·|u_j|: exact (predicates.h). Ties go to the first side listed (x).
  auto earlier = [&](Face j, exact::TwoTerm gap_j, Face k, exact::TwoTerm gap_k) {
    const exact::TwoTerm minus_k{-gap_k.hi, -gap_k.lo};
    return certain_sum_of_products(gap_j, std::abs(u[k.axis]), minus_k, std::abs(u[j.axis]))
               .sign < 0;
  };
  // The point where the ray meets the face's plane; A itself at t = 0.
  auto point_at = [&](double t, Face face) {
    std::array<double, Dim> I;
    const int n = face.axis;
    for (int k = 0; k < Dim; ++k)
      I[k] = t > 0 ? coordinate_on_face(A[k], face.sign, A[n], u[k], u[n]) : A[k];
    I[n] = face.sign;  // on the side by construction: keep it there to the last bit
    // on the side (decided exactly below): keep every coordinate within it
    for (int k = 0; k < Dim; ++k) I[k] = std::clamp(I[k], -1.0, 1.0);
    return I;
  };

  if (res.inside) {
    // Leave through the side met first: along each axis the ray heads to the side of its sign.
    std::optional<exact::TwoTerm> best_gap;
    for (int k = 0; k < Dim; ++k) {
      if (!(std::abs(u[k]) > 0)) continue;  // parallel to these sides: never meets them
      const Face face{k, u[k] > 0 ? +1 : -1};
      const exact::TwoTerm g = gap(face);
      if (!res.face || earlier(face, g, *res.face, *best_gap)) {
        res.face = face;
        best_gap = g;
      }
    }
    res.t = (res.face->sign - A[res.face->axis]) / u[res.face->axis];  // A_k + t·u_k = σ
    res.I = point_at(*res.t, *res.face);
    res.t = times_pow2(*res.t, -f);
    return res;
  }

  // From outside: only the candidate sides, each crossed where (A + t·u)·n = 1, t = gap / |u_n|,
  // if the ray heads into it (u·n < 0) and that point lies on the side: for every other axis j,
  // |A_j + t·u_j| ≤ 1, i.e. (1 ∓ A_j)·|u_n| ∓ gap·u_j ≥ 0 for both signs (exact).
  std::optional<exact::TwoTerm> best_gap;
  res.faces.for_each([&](Face face) {
    const double u_n = face.sign * u[face.axis];
    if (!(u_n < 0)) return;  // not heading into this side
    const exact::TwoTerm g = gap(face);
    for (int j = 0; j < Dim; ++j) {
      if (j == face.axis) continue;
      for (int side : {+1, -1}) {
        const exact::TwoTerm room = exact::two_difference(1.0, side * A[j]);  // 1 ∓ A_j
        if (certain_sum_of_products(room, -u_n, g, -side * u[j]).sign < 0) return;
      }
    }
    // Of two valid candidates the later is where the ray enters (slab rule); from outside that
    // happens only at a corner, at the same t, and there the x side is taken first.
    if (res.face) {
      const bool later = earlier(*res.face, *best_gap, face, g);
      const bool tie = !later && !earlier(face, g, *res.face, *best_gap);
      if (!later && !(tie && face.axis < res.face->axis)) return;
    }
    const double a_n = face.sign * A[face.axis];
    const double t = std::max(0.0, (1.0 - a_n) / u_n);
    res.t = t;
    res.face = face;
    res.I = point_at(t, face);
    best_gap = g;
  });
  if (res.t) res.t = times_pow2(*res.t, -f);
  return res;
}

}  // namespace epure::geo::detail
