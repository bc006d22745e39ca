#pragma once
// The course's square method written once for the square (2D) and the cube (3D). Internal to
// ray_square.cpp and ray_3d.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "geometry/box_faces.h"
#include "geometry/degenerate.h"
#include "geometry/tolerance.h"

namespace epure::geo::detail {

template <int Dim>
struct BoxResult {
  FaceSet<Dim> faces;
  bool inside = false;
  std::optional<double> t;
  std::array<double, Dim> I{};
  std::optional<Face> face;
};

template <int Dim>
BoxResult<Dim> intersect_box(const std::array<double, Dim>& A, const std::array<double, Dim>& u) {
  double largest_u = 0, largest_a = 1;
  for (int k = 0; k < Dim; ++k) {
    largest_u = std::max(largest_u, std::abs(u[k]));
    largest_a = std::max(largest_a, std::abs(A[k]));
  }
  if (!(largest_u > 0)) throw DegenerateFigure("u", "zero direction");

  // A's coordinates are data or carried from another frame (a few ε of |A| off): a coordinate
  // that close to ±1 is on that side.
  const Near near{kRoundoff * largest_a};
  BoxResult<Dim> res;
  for (int sign : {+1, -1})
    for (int k = 0; k < Dim; ++k)
      if (!near.below(sign * A[k], 1.0)) res.faces.insert({k, sign});
  res.inside = res.faces.empty();

  auto point_at = [&](double t, Face face) {
    std::array<double, Dim> I;
    for (int k = 0; k < Dim; ++k) I[k] = A[k] + t * u[k];
    I[face.axis] = face.sign;  // on the side by construction: keep it there to the last bit
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
  return res;
}

}  // namespace epure::geo::detail
