#include "check/judge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "geometry/projection.h"
#include "geometry/ray_3d.h"
#include "geometry/ray_circle.h"
#include "geometry/ray_square.h"
#include "geometry/ray_transformed.h"
#include "geometry/segments.h"

namespace epure::check {

namespace {

using geo::Point2;
using geo::Point3;
using geo::Vec2;
using geo::Vec3;

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kRelative = 1e-6;          // of the figure's size
constexpr double kNoise = 64 * kEps;        // of the data's scale
const double kNudge = std::ldexp(1.0, -40);  // "nearby data", of the data's scale

Point2 p2(const Inputs& in, int i) { return {in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1]}; }
Vec2 v2(const Inputs& in, int i) { return {in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1]}; }
Point3 p3(const Inputs& in, int i) {
  return {in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1], in[static_cast<std::size_t>(i) + 2]};
}
Vec3 v3(const Inputs& in, int i) {
  return {in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1], in[static_cast<std::size_t>(i) + 2]};
}

// Which inputs are a direction or an angle (not lengths: left out of the scale).
bool is_length(Fn fn, int i) {
  switch (fn) {
    case Fn::projection:
    case Fn::segments: return true;
    case Fn::circle:
    case Fn::circle_canonical:
    case Fn::square_canonical: return i != 2 && i != 3;
    case Fn::ellipse:
    case Fn::rectangle: return i != 2 && i != 3 && i != 8;
    case Fn::sphere:
    case Fn::cube_canonical: return i < 3 || i > 5;
  }
  return true;
}

double max_abs(const Inputs& in, int from, int to) {
  double m = 0;
  for (int i = from; i < to; ++i) m = std::max(m, std::abs(in[static_cast<std::size_t>(i)]));
  return m;
}

struct Sizes {
  double S, L, rho;
};

Sizes sizes(const Case& c) {
  const FunctionInfo& f = info(c.fn);
  double S = 0;
  for (int i = 0; i < f.inputs; ++i)
    if (is_length(c.fn, i)) S = std::max(S, std::abs(c.in[static_cast<std::size_t>(i)]));
  const Inputs& in = c.in;
  switch (c.fn) {
    case Fn::projection:
    case Fn::segments: return {S, S, 1};
    case Fn::circle: return {S, std::max(max_abs(in, 4, 7), 0.0), in[6]};
    case Fn::circle_canonical:
    case Fn::square_canonical:
    case Fn::cube_canonical: return {std::max(S, 1.0), 1, 1};
    case Fn::ellipse: {
      const double a = in[6], b = in[7];
      return {S, max_abs(in, 4, 8), std::min(a, b) * std::min(a, b) / std::max(a, b)};
    }
    case Fn::rectangle: return {S, max_abs(in, 4, 8), std::min(in[6], in[7])};
    case Fn::sphere: return {S, max_abs(in, 6, 10), in[9]};
  }
  return {S, S, 1};
}

Outcome hit2(const std::optional<geo::Hit2>& hit) {
  Outcome o;
  o.hit = hit.has_value();
  if (hit) o.out = {hit->I.x, hit->I.y, hit->N.x, hit->N.y, 0, 0};
  return o;
}
Outcome hit3(const std::optional<geo::Hit3>& hit) {
  Outcome o;
  o.hit = hit.has_value();
  if (hit) o.out = {hit->I.x, hit->I.y, hit->I.z, hit->N.x, hit->N.y, hit->N.z};
  return o;
}

// The core's answer; `exact`: its exact predicates, otherwise its reading of the data as
// decimals (within rounding of tangency is tangent, of an end is that end, …).
std::optional<Outcome> reference(const Case& c, bool exact) {
  const Inputs& in = c.in;
  try {
    switch (c.fn) {
      case Fn::projection: {
        const geo::Projection p = exact ? geo::project_exact(p2(in, 0), p2(in, 2), p2(in, 4))
                                        : geo::project(p2(in, 0), p2(in, 2), p2(in, 4));
        Outcome o;
        o.hit = true;
        o.out[0] = p.P.x, o.out[1] = p.P.y;
        return o;
      }
      case Fn::segments: {
        const geo::SegmentIntersection s = exact ? geo::intersect_segments_exact(p2(in, 0), p2(in, 2), p2(in, 4), p2(in, 6))
                                                 : geo::intersect_segments(p2(in, 0), p2(in, 2), p2(in, 4), p2(in, 6));
        Outcome o;
        o.hit = s.intersects();
        if (s.I) o.out[0] = s.I->x, o.out[1] = s.I->y;
        return o;
      }
      case Fn::circle: {
        const geo::Ray2 ray{p2(in, 0), v2(in, 2)};
        const geo::Circle circle{p2(in, 4), in[6]};
        return hit2((exact ? geo::intersect_exact(ray, circle) : geo::intersect(ray, circle)).hit);
      }
      case Fn::circle_canonical: {
        const geo::Ray2 ray{p2(in, 0), v2(in, 2)};
        return hit2((exact ? geo::intersect_canonical_circle_exact(ray) : geo::intersect_canonical_circle(ray)).hit);
      }
      case Fn::square_canonical: {
        const geo::Ray2 ray{p2(in, 0), v2(in, 2)};
        return hit2((exact ? geo::intersect_canonical_square_exact(ray) : geo::intersect_canonical_square(ray)).hit);
      }
      case Fn::ellipse: {
        const geo::Ray2 ray{p2(in, 0), v2(in, 2)};
        const geo::Ellipse e{p2(in, 4), in[6], in[7], in[8]};
        return hit2((exact ? geo::intersect_exact(ray, e) : geo::intersect(ray, e)).hit);
      }
      case Fn::rectangle: {
        const geo::Ray2 ray{p2(in, 0), v2(in, 2)};
        const geo::Rectangle r{p2(in, 4), in[6], in[7], in[8]};
        return hit2((exact ? geo::intersect_exact(ray, r) : geo::intersect(ray, r)).hit);
      }
      case Fn::sphere: {
        const geo::Ray3 ray{p3(in, 0), v3(in, 3)};
        const geo::Sphere s{p3(in, 6), in[9]};
        return hit3((exact ? geo::intersect_exact(ray, s) : geo::intersect(ray, s)).hit);
      }
      case Fn::cube_canonical: {
        const geo::Ray3 ray{p3(in, 0), v3(in, 3)};
        return hit3((exact ? geo::intersect_canonical_cube_exact(ray) : geo::intersect_canonical_cube(ray)).hit);
      }
    }
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return std::nullopt;
}

double distance(const Outcome& a, const Outcome& b, int from, int count) {
  double d = 0;
  for (int i = from; i < from + count; ++i)
    d = std::max(d, std::abs(a.out[static_cast<std::size_t>(i)] - b.out[static_cast<std::size_t>(i)]));
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

bool finite(const Outcome& o, int count) {
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(o.out[static_cast<std::size_t>(i)])) return false;
  return true;
}

// The outward normals of the sides (faces) the point J lies on, within `tol`: one, or two or
// three at a corner (an edge, a vertex). For the square, the cube and the rectangle.
std::vector<std::array<double, 3>> side_normals(const Case& c, const Outcome& ref, double tol) {
  std::vector<std::array<double, 3>> out;
  const Inputs& in = c.in;
  if (c.fn == Fn::square_canonical || c.fn == Fn::cube_canonical) {
    const int dim = c.fn == Fn::cube_canonical ? 3 : 2;
    for (int k = 0; k < dim; ++k)
      for (double s : {1.0, -1.0})
        if (std::abs(ref.out[static_cast<std::size_t>(k)] - s) <= tol) {
          std::array<double, 3> n{0, 0, 0};
          n[static_cast<std::size_t>(k)] = s;
          out.push_back(n);
        }
  } else if (c.fn == Fn::rectangle) {
    const double a = in[8] * std::numbers::pi / 180, co = std::cos(a), si = std::sin(a);
    const double dx = ref.out[0] - in[4], dy = ref.out[1] - in[5];
    const double x = (co * dx + si * dy) / in[6], y = (-si * dx + co * dy) / in[7];
    for (double s : {1.0, -1.0}) {
      if (std::abs(x - s) * in[6] <= tol) out.push_back({s * co, s * si, 0});
      if (std::abs(y - s) * in[7] <= tol) out.push_back({-s * si, s * co, 0});
    }
  }
  return out;
}

bool normal_agrees(const Case& c, const Outcome& ref, const Outcome& got, const Tolerance& tol) {
  const int dim = info(c.fn).dimension;
  if (distance(ref, got, dim, dim) <= tol.normal) return true;
  for (const auto& n : side_normals(c, ref, tol.point)) {
    double d = 0;
    for (int i = 0; i < dim; ++i)
      d = std::max(d, std::abs(n[static_cast<std::size_t>(i)] - got.out[static_cast<std::size_t>(dim + i)]));
    if (d <= tol.normal) return true;
  }
  return false;
}

// Segments whose AB∧CD is within the rounding of the data: parallel as the data were meant.
bool parallel_within_rounding(const Case& c) {
  const Inputs& in = c.in;
  const Vec2 AB = p2(in, 2) - p2(in, 0), CD = p2(in, 6) - p2(in, 4);
  const double S = sizes(c).S;
  const double v = geo::cross(AB, CD);
  // the data's rounding moves each difference by ε·S, the products by 2ε of themselves
  const double band = 8 * kEps * (S * (std::abs(AB.x) + std::abs(AB.y) + std::abs(CD.x) + std::abs(CD.y)) +
                                   std::abs(AB.x * CD.y) + std::abs(AB.y * CD.x));
  return std::abs(v) <= band;
}

}  // namespace

Tolerance tolerance_of(const Case& c) {
  const Sizes s = sizes(c);
  const double point = kRelative * s.L + kNoise * s.S;
  return {point, point / s.rho};
}

double data_scale(const Case& c) { return sizes(c).S; }

std::optional<Outcome> expected(const Case& c) { return reference(c, true); }

bool agrees(const Case& c, const Outcome& reference, const Outcome& got) {
  if (reference.hit != got.hit) return false;
  if (!reference.hit) return true;
  const FunctionInfo& f = info(c.fn);
  const Tolerance tol = tolerance_of(c);
  if (!finite(got, f.has_normal ? 2 * f.dimension : f.dimension)) return false;
  if (distance(reference, got, 0, f.dimension) > tol.point) return false;
  return !f.has_normal || normal_agrees(c, reference, got, tol);
}

bool exact_safe(const Case& c) {
  const FunctionInfo& f = info(c.fn);
  double m = 0;
  for (int i = 0; i < f.inputs; ++i) m = std::max(m, std::abs(c.in[static_cast<std::size_t>(i)]));
  if (!(m > 0) || !std::isfinite(m)) return false;
  const int e = std::ilogb(m);
  for (int i = 0; i < f.inputs; ++i) {
    const double x = c.in[static_cast<std::size_t>(i)];
    if (c.fn == Fn::ellipse || c.fn == Fn::rectangle) {
      // the angle: exact only at 0 (a student's cos and sin of 90° or 180° in radians are not)
      if (i == 8) {
        if (x != 0) return false;
        continue;
      }
    }
    const double scaled = std::ldexp(x, 8 - e);
    if (scaled != std::trunc(scaled)) return false;
  }
  return true;
}

Judgement judge(const Case& c, const Outcome& got) {
  Judgement j;
  const auto e = expected(c);
  if (!e) return j;  // no answer to compare with: never generated
  j.expected = *e;
  if (agrees(c, *e, got)) {
    j.right = true;
    return j;
  }
  if (c.fn == Fn::projection) return j;  // no decision, no room
  const bool safe = exact_safe(c);
  if (c.fn == Fn::segments && !safe && parallel_within_rounding(c)) {
    // parallel as the data were meant: false is right (the exact answer, above, too); no other
    j.right = j.in_band = !got.hit;
    return j;
  }
  if (safe) return j;
  if (const auto t = reference(c, false); t && agrees(c, *t, got)) {
    j.right = j.in_band = true;
    return j;
  }
  const FunctionInfo& f = info(c.fn);
  const double step = kNudge * sizes(c).S;
  for (int i = 0; i < f.inputs; ++i) {
    for (double sign : {1.0, -1.0}) {
      Case near = c;
      double& x = near.in[static_cast<std::size_t>(i)];
      // a direction or an angle is moved by 2^-40 of itself or of 1; a length by 2^-40·S
      x += sign * (is_length(c.fn, i) ? step : kNudge * std::max(1.0, std::abs(x)));
      if (const auto r = reference(near, true); r && agrees(c, *r, got)) {
        j.right = j.in_band = true;
        return j;
      }
    }
  }
  return j;
}

}  // namespace epure::check
