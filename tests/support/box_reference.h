#pragma once
// The expected answer of ray/canonical square and ray/canonical cube, computed independently of
// src/geometry by the slab method (Kay and Kajiya) in quadruple precision, from the data as
// given (the direction not normalised). Used by ray_square_test.cpp, ray_3d_test.cpp and
// ray_transformed_test.cpp (the rectangle in its own frame).
#include <array>
#include <optional>
#include <utility>

#include "support/real.h"

namespace epure::test {

template <int Dim>
struct BoxExpected {
  bool inside = false;                // every |A_k| < 1
  std::array<bool, 2 * Dim> faces{};  // +x, +y(, +z), −x, −y(, −z): σ·A_k ≥ 1
  std::optional<Real> t;              // a length along the ray
  int axis = -1, sign = 0;            // the face hit
  std::array<Real, Dim> I{};
  // How close the figure is to a branch boundary, in units of the square: the smallest of
  // |σ·A_k − 1| and, with a hit, the distance of I's other coordinates from ±1 and the gap
  // between the entry and exit of the slabs. The tests leave out figures where this is below
  // the data's rounding (those are pinned case by case).
  Real margin = 1;
};

// From quadruple-precision data (a figure carried into the canonical frame by the test).
template <int Dim>
BoxExpected<Dim> box_reference_real(const std::array<Real, Dim>& A,
                                    const std::array<Real, Dim>& u) {
  BoxExpected<Dim> e;
  Real length2 = 0;
  for (int k = 0; k < Dim; ++k) length2 += u[k] * u[k];
  const Real length = sqrt(length2);
  e.inside = true;
  for (int k = 0; k < Dim; ++k) {
    if (A[k] >= 1) e.faces[k] = true;
    if (A[k] <= -1) e.faces[Dim + k] = true;
    if (abs(A[k]) >= 1) e.inside = false;
    e.margin = min(e.margin, abs(abs(A[k]) - 1));
  }
  // t in units of u: each slab k is entered at min((±1 − A_k)/u_k) and left at the max
  Real enter = -1e300, leave = 1e300;
  int enter_axis = -1, leave_axis = -1;
  for (int k = 0; k < Dim; ++k) {
    if (u[k] == 0) {
      if (abs(A[k]) > 1) return e;  // parallel to the slab, outside it: no hit
      continue;
    }
    Real lo = (-1 - A[k]) / u[k], hi = (1 - A[k]) / u[k];
    if (lo > hi) std::swap(lo, hi);
    if (lo > enter) {
      enter = lo;
      enter_axis = k;
    }
    if (hi < leave) {
      leave = hi;
      leave_axis = k;
    }
  }
  Real t;
  int axis;
  if (e.inside) {
    t = leave;
    axis = leave_axis;
  } else {
    if (enter > leave || enter < 0) {
      e.margin = min(e.margin, abs(enter - leave) * length);
      return e;
    }
    t = enter;
    axis = enter_axis;
  }
  e.margin = min(e.margin, abs(enter - leave) * length);
  e.t = t * length;
  e.axis = axis;
  e.sign = (u[axis] > 0) == e.inside ? 1 : -1;
  for (int k = 0; k < Dim; ++k) {
    e.I[k] = k == axis ? Real(e.sign) : A[k] + t * u[k];
    if (k != axis) e.margin = min(e.margin, abs(abs(e.I[k]) - 1));
  }
  return e;
}

// From the data as the functions under test receive them.
template <int Dim>
BoxExpected<Dim> box_reference(const std::array<double, Dim>& a, const std::array<double, Dim>& d) {
  std::array<Real, Dim> A{}, u{};
  for (int k = 0; k < Dim; ++k) {
    A[k] = a[k];
    u[k] = d[k];
  }
  return box_reference_real<Dim>(A, u);
}

}  // namespace epure::test
