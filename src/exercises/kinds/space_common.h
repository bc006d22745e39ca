#pragma once
// What the kinds in space share: a 3D point as the key writes it, the core's points as the
// camera's, and the épure's 3D view begun (isometric camera, floor grid, labelled axes).
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "exercises/kind_support.h"
#include "geometry/vec.h"
#include "render/camera.h"

namespace epure::kinds::space {

inline render::P3 p3(geo::Point3 p) { return {p.x, p.y, p.z}; }
inline render::P3 p3(geo::Vec3 v) { return {v.x, v.y, v.z}; }

// "(1/3, −2, √2/2)": each coordinate shown as the key's steps show a value (exact when short).
inline std::string shown_point3(const ExerciseContext& ctx, geo::Point3 p, const std::optional<exact::Surd>& ex,
                                const std::optional<exact::Surd>& ey, const std::optional<exact::Surd>& ez) {
  const char* sep = ctx.numbers.decimal_comma ? "\u00a0;" : ",";
  return fmt::format("({}{} {}{} {})", shown(ctx, p.x, ex), sep, shown(ctx, p.y, ey), sep, shown(ctx, p.z, ez));
}

// A 3D step or answer recorded under three names, as the key shows it.
template <class Key>
std::string step_point3(const ExerciseContext& ctx, const Key& key, const method::Names3& ids) {
  return shown_point3(ctx, {key.value(ids[0]), key.value(ids[1]), key.value(ids[2])}, key.exact(ids[0]),
                      key.exact(ids[1]), key.exact(ids[2]));
}

// An easy direction in space: one of `directions` (integer length), its components in a random
// order, then random signs.
template <std::size_t N>
geo::Vec3 easy_direction(Rng& rng, const geo::Vec3 (&directions)[N]) {
  const geo::Vec3 e = directions[rng.integer(0, N - 1)];
  double c[3] = {e.x, e.y, e.z};
  for (int i = 2; i > 0; --i) std::swap(c[i], c[rng.integer(0, i)]);
  for (double& k : c)
    if (rng.chance(0.5)) k = -k;
  return {c[0], c[1], c[2]};
}

// The camera of every 3D view: orthographic, so that a sphere's outline is a circle of its
// radius, from an azimuth and elevation that keep a cube's corners apart.
inline render::Camera camera() { return render::Camera::axonometric(30, 25); }

// The 3D view's panel: around the given points, with the floor grid (z = 0) over ±grid and the
// axes `axis` long (dashed where `solid` hides them).
template <class Solid = render::NoSolid>
render::Panel view_panel(const render::Camera& cam, std::vector<render::P3> points, int grid, double axis,
                         const Solid& solid = {}) {
  render::Panel panel;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) points.push_back({double(sx * grid), double(sy * grid), 0});
  points.push_back({axis, 0, 0});
  points.push_back({0, axis, 0});
  points.push_back({0, 0, axis});
  panel.view = render::view_of(cam, points, 0.8);
  render::add_floor_grid(panel, cam, grid);
  render::add_axes(panel, cam, axis, solid);
  return panel;
}

// A point's height shown by a thin dashed line down to its foot on the floor z = 0, marked.
inline void add_drop(render::Panel& panel, const render::Camera& cam, render::P3 p) {
  if (std::abs(p.z) < 1e-9) return;
  const render::P3 foot{p.x, p.y, 0};
  panel.add(render::Segment{cam.project(p), cam.project(foot), render::Role::muted, true});
  panel.add(render::PointMark{cam.project(foot), render::Role::muted, std::nullopt});
}

}  // namespace epure::kinds::space
