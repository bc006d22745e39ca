#pragma once
// The course's ray/circle method written once for the circle (2D) and the sphere (3D): both are
// "points at distance r from C". Internal to ray_circle.cpp and ray_3d.cpp.
#include <algorithm>
#include <cmath>

#include "geometry/degenerate.h"
#include "geometry/tolerance.h"
#include "geometry/vec.h"

namespace epure::geo::detail {

// The part of AC perpendicular to the ray's line, and its length d = CP. In 2D the signed
// distance comes from one fma-exact cross product, which keeps d to the last digits when the
// ray is nearly tangent; in 3D from the cross product's norm.
struct Offset2 {
  Vec2 w;
  double d;
};
inline Offset2 offset_from_line(Vec2 u, double length_u, Vec2 AC, double /*t_proj*/) {
  double s = cross(u, AC) / length_u;  // AC = t_proj·u + s·perp(û)
  return {s * perp(u / length_u), std::abs(s)};
}
struct Offset3 {
  Vec3 w;
  double d;
};
inline Offset3 offset_from_line(Vec3 u, double length_u, Vec3 AC, double t_proj) {
  return {AC - t_proj * u, norm(cross(u, AC)) / length_u};
}

template <class Result, class Hit, class Ray, class Point>
Result intersect_ball(const Ray& ray, Point C, double r) {
  if (!(r > 0) || !std::isfinite(r)) throw DegenerateFigure("r", "must be > 0");
  const auto u = ray.direction;
  const double length_u = norm(u);
  if (!(length_u > 0)) throw DegenerateFigure("u", "zero direction");
  const Point A = ray.origin;

  Result res{};
  res.AC = C - A;
  const double ac = norm(res.AC);
  // P = A + t_proj·u with (AC − t_proj·u)·u = 0
  res.t_proj = dot(u, res.AC) / (length_u * length_u);
  res.P = A + res.t_proj * u;
  const auto offset = offset_from_line(u, length_u, res.AC, res.t_proj);
  const double d = offset.d;
  res.d2 = d * d;

  // AC and d are exact to a few ε of ‖AC‖: compare lengths with r within that.
  const Near near{kRoundoff * std::max(r, ac)};
  res.inside = near.below(ac, r);
  const bool on_circle = near.on(ac, r);
  // behind: outside and pointing away from C (the course's first test, t_proj < 0)
  if (!res.inside && Near{kRoundoff * ac / length_u}.below(res.t_proj, 0.0)) {
    res.reason = NoHit::behind;
    return res;
  }
  // miss: the line passes farther than r from C (d² > r²)
  if (near.above(d, r)) {
    res.reason = NoHit::miss;
    return res;
  }
  // Pythagoras in CPI: PI² = r² − d², factored to keep its digits near tangency.
  const double h = std::sqrt(std::max(0.0, (r - d) * (r + d)));
  res.half_chord = h;
  const double h_param = h / length_u;
  // The roots t_proj ∓ h have the product c = (‖AC‖² − r²) / u·u. Each root is taken in the
  // form that does not cancel (the smaller one as c over the larger, when both are positive).
  const double c = on_circle ? 0.0 : (ac - r) * (ac + r) / (length_u * length_u);
  double t;
  double along;  // (t − t_proj)·‖u‖: −h at the entry, +h at the exit
  if (res.inside) {
    t = res.t_proj >= 0 ? res.t_proj + h_param : c / (res.t_proj - h_param);
    along = h;
  } else {
    const double sum = res.t_proj + h_param;
    t = sum > 0 ? std::max(0.0, c / sum) : 0.0;
    along = -h;
  }
  // I − C = (t − t_proj)·u − w, of length r: no cancellation, whatever the size of AC.
  const auto radial = (along / length_u) * u - offset.w;
  const double radial_length = norm(radial);
  Hit hit{};
  hit.t = t;
  hit.I = A + t * u;
  hit.N = radial_length > 0 ? radial / radial_length : -1.0 * (res.AC / ac);
  res.hit = hit;
  return res;
}

}  // namespace epure::geo::detail
