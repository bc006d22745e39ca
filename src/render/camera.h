#pragma once
// Space on a flat panel: an orthographic axonometric camera (the isometric view of French
// technical drawing) that projects 3D points into a Panel's 2D coordinates, with what an épure's
// 3D view draws: labelled axes, a light grid on a reference plane, and segments split into their
// visible parts (solid) and the parts a solid hides (dashed, so that grayscale print tells them
// apart). Knows nothing of exercises: solids are balls and axis-aligned boxes.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "render/scene.h"

namespace epure::render {

struct P3 {
  double x = 0, y = 0, z = 0;
};
inline P3 operator+(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline P3 operator-(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline P3 operator*(double k, P3 a) { return {k * a.x, k * a.y, k * a.z}; }
inline double dot3(P3 a, P3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Orthographic: a point goes to (p·right, p·up); `toward` (right × up) points at the viewer.
// Lengths parallel to the picture keep their size, and a ball's outline is a circle of its radius.
class Camera {
 public:
  // The isometric view from (+x, +y, +z): x comes down to the left, y down to the right, z up.
  static Camera isometric() {
    const double s2 = std::sqrt(2.0), s3 = std::sqrt(3.0), s6 = std::sqrt(6.0);
    return Camera({-1 / s2, 1 / s2, 0}, {-1 / s6, -1 / s6, 2 / s6}, {1 / s3, 1 / s3, 1 / s3});
  }
  // The orthographic view from azimuth a (from +x towards +y) and elevation e (above the plane
  // z = 0), in degrees: z stays vertical. From (30°, 25°), x comes down to the left, y goes right
  // and slightly down, and no two corners of a cube centred at the origin fall on one point (as
  // the isometric view's front and back corners do).
  static Camera axonometric(double azimuth_deg, double elevation_deg) {
    const double a = azimuth_deg * (3.14159265358979323846 / 180), e = elevation_deg * (3.14159265358979323846 / 180);
    const P3 toward{std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
    const P3 right{-std::sin(a), std::cos(a), 0};
    const P3 up{-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)};
    return Camera(right, up, toward);
  }
  P2 project(P3 p) const { return {dot3(p, right_), dot3(p, up_)}; }
  // larger is nearer the viewer
  double depth(P3 p) const { return dot3(p, toward_); }
  P3 toward() const { return toward_; }

 private:
  Camera(P3 right, P3 up, P3 toward) : right_(right), up_(up), toward_(toward) {}
  P3 right_, up_, toward_;
};

// How close to a solid's surface a point counts as on it (not hidden), in the panel's units: far
// below what a drawing shows, far above the rounding of the coordinates.
inline constexpr double kSurfaceGap = 1e-9;
// A view direction's component below this is parallel to a box's slab.
inline constexpr double kParallelSlab = 1e-15;

// A solid that hides what lies behind it.
struct Ball {
  P3 c;
  double r;
};
struct AlignedBox {
  P3 lo, hi;
};

// Whether p is hidden by the solid: inside it, or behind it (the line of sight from p towards
// the viewer enters it). Points on the surface itself (within `eps`) are not hidden.
inline bool hides(const Ball& b, const Camera& cam, P3 p, double eps = kSurfaceGap) {
  const P3 cp = p - b.c;
  const double c2 = dot3(cp, cp) - b.r * b.r;
  if (c2 < -eps) return true;
  // p + s·toward, s > 0: s² + 2s(cp·toward) + c2 = 0
  const double k = dot3(cp, cam.toward());
  const double disc = k * k - c2;
  if (disc <= eps) return false;
  const double s_far = -k + std::sqrt(disc);
  return s_far > eps && -k > eps;
}
inline bool hides(const AlignedBox& b, const Camera& cam, P3 p, double eps = kSurfaceGap) {
  const double o[3] = {p.x, p.y, p.z}, d[3] = {cam.toward().x, cam.toward().y, cam.toward().z};
  const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
  double s_in = 0, s_out = 1e300;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < kParallelSlab) {
      if (o[k] <= lo[k] + eps || o[k] >= hi[k] - eps) return false;
      continue;
    }
    double a = (lo[k] - o[k]) / d[k], c = (hi[k] - o[k]) / d[k];
    if (a > c) std::swap(a, c);
    s_in = std::max(s_in, a);
    s_out = std::min(s_out, c);
  }
  return s_out - s_in > eps && s_out > eps;
}

// The segment a→b in space, drawn in `role`: its visible stretches solid, the stretches a solid
// hides dashed (found on 240 samples, each change of state refined by bisection).
template <class Solid>
void add_segment(Panel& panel, const Camera& cam, P3 a, P3 b, Role role, const Solid& solid) {
  constexpr int kSamples = 240;
  auto at = [&](double s) { return a + s * (b - a); };
  auto hidden = [&](double s) { return hides(solid, cam, at(s)); };
  double start = 0;
  bool state = hidden(0.0);
  auto flush = [&](double end, bool was_hidden) {
    if (end - start <= kSurfaceGap) return;  // a sliver left by the bisection at an end
    panel.add(Segment{cam.project(at(start)), cam.project(at(end)), role, was_hidden});
  };
  for (int i = 1; i <= kSamples; ++i) {
    const double s = double(i) / kSamples;
    const bool h = hidden(s);
    if (h == state) continue;
    double lo = double(i - 1) / kSamples, hi = s;
    for (int k = 0; k < 30; ++k) {
      const double mid = (lo + hi) / 2;
      (hidden(mid) == state ? lo : hi) = mid;
    }
    flush(lo, state);
    start = lo;
    state = h;
  }
  flush(1.0, state);
}

// A light grid on the plane z = 0, from -n to n in whole steps, under everything else.
inline void add_floor_grid(Panel& panel, const Camera& cam, int n) {
  for (int k = -n; k <= n; ++k) {
    panel.add(Segment{cam.project({double(k), double(-n), 0}), cam.project({double(k), double(n), 0}), Role::muted, false});
    panel.add(Segment{cam.project({double(-n), double(k), 0}), cam.project({double(n), double(k), 0}), Role::muted, false});
  }
}

// Nothing that hides: add_segment draws the whole segment solid.
struct NoSolid {};
inline bool hides(const NoSolid&, const Camera&, P3) { return false; }

// The axes from the origin, `length` long, each with its name at the tip; dashed where `solid`
// hides them.
template <class Solid = NoSolid>
void add_axes(Panel& panel, const Camera& cam, double length, const Solid& solid = {}) {
  const P3 tips[] = {{length, 0, 0}, {0, length, 0}, {0, 0, length}};
  const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const P3 neck = 0.8 * tips[k];
    add_segment(panel, cam, {0, 0, 0}, neck, Role::construction, solid);
    panel.add(Arrow{cam.project(neck), cam.project(tips[k]), Role::construction});
    panel.add(Label{names[k], cam.project(tips[k]), Side::auto_, Role::construction});
  }
}

// A view box around the projections of the points, with a margin, snapped to whole units.
inline Box view_of(const Camera& cam, const std::vector<P3>& points, double margin) {
  Box b{1e300, 1e300, -1e300, -1e300};
  for (const P3& p : points) {
    const P2 q = cam.project(p);
    b.x_min = std::min(b.x_min, q.x);
    b.y_min = std::min(b.y_min, q.y);
    b.x_max = std::max(b.x_max, q.x);
    b.y_max = std::max(b.y_max, q.y);
  }
  return {std::floor(b.x_min - margin), std::floor(b.y_min - margin), std::ceil(b.x_max + margin),
          std::ceil(b.y_max + margin)};
}

}  // namespace epure::render
