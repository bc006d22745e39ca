#include "exercises/kinds/transformed_common.h"
#include "support/portable.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace epure::kinds::transformed {

using geo::Point2;
using geo::Vec2;

namespace {

// A text of the kind: the spec's kind names the templates' prefix.
std::string key(const ExerciseContext& ctx, std::string_view rest) { return fmt::format("{}.{}", ctx.spec.kind, rest); }
// The names of the two sizes, as the statement and the diagram call them.
std::pair<std::string, std::string> size_names(Shape shape) {
  return shape == Shape::ellipse ? std::pair<std::string, std::string>{"a", "b"}
                                 : std::pair<std::string, std::string>{"w", "h"};
}

// Directions whose unit vector is rational (axes, Pythagorean triples): the easy level's û.
constexpr Vec2 kEasyDirections[] = {{1, 0}, {2, 0}, {0, 1}, {0, 2}, {3, 4}, {4, 3}, {6, 8}, {8, 6}};
// Angles whose cosine and sine are quadratic surds, other than the quarter turns.
constexpr int kStandardAngles[] = {30, 45, 60, 120, 135, 150};

// A coordinate on the difficulty's grid in [lo, hi], or nothing when the grid has none there.
std::optional<double> on_grid(Rng& rng, double lo, double hi, Difficulty level) {
  const double step = level == Difficulty::hard ? 0.1 : 1;
  if (std::floor(hi / step + 1e-9) < std::ceil(lo / step - 1e-9)) return std::nullopt;
  return grid_value(rng, lo, hi, level);
}

// Half the width and height of the figure's bounding box.
Vec2 half_extent(Shape shape, double sx, double sy, double angle_deg) {
  const auto [c, s] = geo::cos_sin_degrees(angle_deg);
  if (shape == Shape::ellipse) return {portable::hypot(sx * c, sy * s), portable::hypot(sx * s, sy * c)};
  return {sx * std::abs(c) + sy * std::abs(s), sx * std::abs(s) + sy * std::abs(c)};
}

}  // namespace

geo::Ray2 world_ray(const Data& d) { return geo::Ray2::unit(d.A, d.u); }

// ---- constraints -------------------------------------------------------------------------------

std::map<std::string, double> common_constraints() {
  return {{"margin", 0.15},    {"min_incidence", 0.25}, {"min_gap", 1.0},       {"max_aspect", 3.0},
          {"min_aspect", 1.2}, {"width", 12.0},         {"height", 10.0},      {"max_canonical", 6.0},
          {"max_amplification", 120.0}};
}

Limits limits(const ExerciseContext& ctx, const ExerciseKind& kind) {
  const double closer = ctx.spec.difficulty == Difficulty::hard ? 2 : 1;
  return {constraint(ctx, kind, "margin") / closer,
          constraint(ctx, kind, "min_incidence") / closer,
          constraint(ctx, kind, "min_gap"),
          constraint(ctx, kind, "max_aspect"),
          constraint(ctx, kind, "min_aspect"),
          constraint(ctx, kind, "width"),
          constraint(ctx, kind, "height"),
          constraint(ctx, kind, "max_canonical"),
          constraint(ctx, kind, "max_amplification") * method::written_half_step(ctx.decimals)};
}

std::optional<Data> draw_data(Rng& rng, Difficulty level, Shape shape, bool inside, const Limits& lim) {
  Data d;
  if (level == Difficulty::hard) {
    d.sx = grid_value(rng, 0.8, 4.5, level);
    d.sy = grid_value(rng, 0.8, 4.5, level);
  } else {
    const int largest = level == Difficulty::easy ? 4 : 5;
    d.sx = static_cast<double>(rng.integer(1, largest));
    d.sy = static_cast<double>(rng.integer(1, largest));
  }
  const double aspect = std::max(d.sx, d.sy) / std::min(d.sx, d.sy);
  if (aspect > lim.max_aspect || aspect < lim.min_aspect) return std::nullopt;

  switch (level) {
    case Difficulty::easy: d.angle_deg = rng.chance(0.5) ? 0 : 90; break;
    case Difficulty::standard:
      d.angle_deg = kStandardAngles[rng.integer(0, std::size(kStandardAngles) - 1)];
      break;
    case Difficulty::hard: d.angle_deg = static_cast<double>(rng.integer(0, 179)); break;
  }

  // the figure inside the drawing area, half a unit clear of its edges
  const Vec2 half = half_extent(shape, d.sx, d.sy, d.angle_deg);
  constexpr double kRoom = 0.5;
  const auto cx = on_grid(rng, half.x + kRoom, lim.width - half.x - kRoom, level);
  const auto cy = on_grid(rng, half.y + kRoom, lim.height - half.y - kRoom, level);
  if (!cx || !cy) return std::nullopt;
  d.C = {*cx, *cy};

  // A inside: somewhere in the figure's bounding box (the caller checks it is in the figure)
  const auto ax = inside ? on_grid(rng, d.C.x - half.x, d.C.x + half.x, level) : on_grid(rng, 0, lim.width, level);
  const auto ay = inside ? on_grid(rng, d.C.y - half.y, d.C.y + half.y, level) : on_grid(rng, 0, lim.height, level);
  if (!ax || !ay) return std::nullopt;
  d.A = {*ax, *ay};

  if (level == Difficulty::easy) {
    d.u = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
    if (rng.chance(0.5)) d.u.x = -d.u.x;
    if (rng.chance(0.5)) d.u.y = -d.u.y;
  } else {
    d.u = {grid_value(rng, -5, 5, level), grid_value(rng, -5, 5, level)};
    if (geo::norm(d.u) < 0.5) return std::nullopt;  // a short arrow is hard to read and to use
  }
  return d;
}

// ---- the method's shared parts ----------------------------------------------------------------

ExactCosSin exact_cos_sin(double degrees) {
  const auto r = rational_of(degrees);
  if (!r || !r->is_integer()) return {};
  const std::int64_t turn = ((r->num() % 360) + 360) % 360;
  const exact::Rational half(1, 2);
  exact::Surd c, s;
  switch (turn % 90) {
    case 0: c = exact::Surd(exact::Rational(1)), s = exact::Surd(exact::Rational(0)); break;
    case 30: c = exact::Surd(0, half, 3), s = exact::Surd(half); break;
    case 45: c = exact::Surd(0, half, 2), s = exact::Surd(0, half, 2); break;
    case 60: c = exact::Surd(half), s = exact::Surd(0, half, 3); break;
    default: return {};
  }
  for (std::int64_t q = 0; q < turn / 90; ++q) c = std::exchange(s, c), c = -c;  // a quarter turn more: (−s, c)
  return {c, s};
}

bool well_conditioned(const std::vector<double>& tolerances, const Limits& lim) {
  for (double t : tolerances)
    if (!(t <= lim.max_tolerance)) return false;
  return true;
}

// ---- texts -------------------------------------------------------------------------------------

TextVars data_vars(const ExerciseContext& ctx, const Data& d, Shape shape) {
  const auto& N = ctx.numbers;
  const auto [a, b] = size_names(shape);
  return {{"A", N.point(d.A.x, d.A.y)}, {"u", N.point(d.u.x, d.u.y)}, {"C", N.point(d.C.x, d.C.y)},
          {a, N.datum(d.sx)},           {b, N.datum(d.sy)},           {"angle", N.datum(d.angle_deg)}};
}

namespace {
// "1/2", "1/2.5", and "1" rather than "1/1"
std::string reciprocal(const NumberStyle& N, double x) {
  const auto r = rational_of(x);
  if (r && r->is_integer() && r->num() == 1) return "1";
  return "1/" + N.datum(x);
}

std::string inverse_text(const ExerciseContext& ctx, const Data& d, Shape shape) {
  const auto& N = ctx.numbers;
  const auto [a, b] = size_names(shape);
  // 0 − x rather than −x: no "−0"
  return ctx.texts.format(key(ctx, "inverse"),
                          {{"inv_" + a, reciprocal(N, d.sx)},
                           {"inv_" + b, reciprocal(N, d.sy)},
                           {"minus_angle", N.datum(0.0 - d.angle_deg)},
                           {"minus_C", N.point(0.0 - d.C.x, 0.0 - d.C.y)}});
}
}  // namespace

std::string link_text(const ExerciseContext& ctx, const Data& d, Shape shape) {
  return ctx.texts.format(key(ctx, "link"), {{"inverse", inverse_text(ctx, d, shape)}});
}

void step(render::Section& s, const ExerciseContext& ctx, std::string_view name, const TextVars& vars) {
  // the kind is the spec's: its texts are `<kind>.step.<name>`
  s.add(render::Paragraph{ctx.texts.format(fmt::format("{}.step.{}", ctx.spec.kind, name), vars)});
}

void frame_steps(render::Section& s, const ExerciseContext& ctx, const Data& d, Shape shape, const KeySolution& key) {
  const auto& N = ctx.numbers;
  step(s, ctx, "transform", {{"inverse", inverse_text(ctx, d, shape)}});
  step(s, ctx, "unit",
       {{"norm_u", equals_value(ctx, key.value("norm_u"), key.exact("norm_u"))},
        {"u_hat", shown_point(ctx, key.point("u_hat"), key.exact_x("u_hat"), key.exact_y("u_hat"))}});
  step(s, ctx, "cos_sin",
       {{"angle", N.datum(d.angle_deg)},
        {"cos", equals_value(ctx, key.value("cos"), key.exact("cos"))},
        {"sin", equals_value(ctx, key.value("sin"), key.exact("sin"))}});
  const Vec2 CA = d.A - d.C;
  step(s, ctx, "Ac",
       {{"CA", N.point(CA.x, CA.y)},
        {"rotated", shown_point(ctx, key.point("CA_rotated"), key.exact_x("CA_rotated"), key.exact_y("CA_rotated"))},
        {"Ac", shown_point(ctx, key.point("Ac"), key.exact_x("Ac"), key.exact_y("Ac"))}});
  step(s, ctx, "uc",
       {{"rotated", shown_point(ctx, key.point("u_rotated"), key.exact_x("u_rotated"), key.exact_y("u_rotated"))},
        {"uc", shown_point(ctx, key.point("uc"), key.exact_x("uc"), key.exact_y("uc"))}});
}

void world_steps(render::Section& s, const ExerciseContext& ctx, const KeySolution& key) {
  auto point = [&](std::string_view id) { return shown_point(ctx, key.point(id), key.exact_x(id), key.exact_y(id)); };
  step(s, ctx, "I", {{"I", point("I")}});
  step(s, ctx, "N", {{"Nc", point("Nc")}, {"n", point("n")}, {"N", point("N")}});
}

// ---- diagrams ----------------------------------------------------------------------------------

render::Panel world_panel(const Data& d, Shape shape, const Solved& s, bool ray_followed_to_hit) {
  const Vec2 u_hat = *geo::normalized(d.u);
  std::vector<render::P2> extent{p2(d.A), p2(d.C), p2(d.A + u_hat)};
  // the figure lies in the image of the canonical square
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0}) extent.push_back(p2(s.to_world.apply(Point2{x, y})));
  if (s.hit) extent.push_back(p2(s.hit->I + s.hit->N));

  render::Panel panel;
  panel.view = view_around(extent, 0.8, 6.0);
  panel.add(render::Grid{1, true});
  if (shape == Shape::ellipse) {
    panel.add(render::Ellipse{p2(d.C), d.sx, d.sy, d.angle_deg, render::Role::data});
  } else {
    std::vector<render::P2> corners;
    for (Point2 c : {Point2{1, 1}, Point2{-1, 1}, Point2{-1, -1}, Point2{1, -1}})
      corners.push_back(p2(s.to_world.apply(c)));
    panel.add(render::Polygon{corners, true, render::Role::data});
  }
  // the two semi-axes, named as the statement names the sizes
  const auto [a, b] = size_names(shape);
  const Point2 end_a = s.to_world.apply(Point2{1, 0}), end_b = s.to_world.apply(Point2{0, 1});
  panel.add(render::Segment{p2(d.C), p2(end_a), render::Role::muted, true});
  panel.add(render::Segment{p2(d.C), p2(end_b), render::Role::muted, true});
  panel.add(render::Label{a, p2(d.C + 0.5 * (end_a - d.C)), render::Side::auto_, render::Role::muted});
  panel.add(render::Label{b, p2(d.C + 0.5 * (end_b - d.C)), render::Side::auto_, render::Role::muted});
  panel.add(render::PointMark{p2(d.C), render::Role::data, render::Label{"C", p2(d.C)}});

  std::optional<render::P2> followed_to;
  if (ray_followed_to_hit && s.hit) followed_to = p2(s.hit->I);
  panel.add(render::Ray{p2(d.A), p2(u_hat), render::Role::data, followed_to});
  panel.add(render::Arrow{p2(d.A), p2(d.A + u_hat), render::Role::data});
  panel.add(render::Label{"û", p2(d.A + 0.5 * u_hat)});
  panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
  return panel;
}

void add_world_hit(render::Panel& panel, const geo::Hit2& hit) {
  panel.add(render::Arrow{p2(hit.I), p2(hit.I + hit.N), render::Role::normal});
  panel.add(render::Label{"\\vec{N}", p2(hit.I + hit.N), render::Side::auto_, render::Role::normal});
  panel.add(render::PointMark{p2(hit.I), render::Role::result,
                              render::Label{"I", p2(hit.I), render::Side::auto_, render::Role::result}});
}

render::Panel canonical_panel(const Solved& s) {
  const Point2 Ac = s.canonical_ray.origin;
  std::vector<render::P2> extent{{-1, -1}, {1, 1}, p2(Ac), p2(Ac + s.canonical_ray.direction)};
  if (s.canonical_hit) extent.push_back(p2(s.canonical_hit->I + s.canonical_hit->N));
  render::Panel panel;
  panel.view = view_around(extent, 0.6, 3.0);
  panel.add(render::Grid{1, true});
  return panel;
}

void add_canonical_ray(render::Panel& panel, const Solved& s) {
  const Point2 Ac = s.canonical_ray.origin;
  const Vec2 uc = s.canonical_ray.direction;
  std::optional<render::P2> followed_to;
  if (s.canonical_hit) followed_to = p2(s.canonical_hit->I);
  panel.add(render::Ray{p2(Ac), p2(uc), render::Role::data, followed_to});
  panel.add(render::Arrow{p2(Ac), p2(Ac + uc), render::Role::data});
  panel.add(render::Label{"\\vec{u}_{c}", p2(Ac + 0.5 * uc)});
  panel.add(render::PointMark{p2(Ac), render::Role::data, render::Label{"A_{c}", p2(Ac)}});
}

void add_canonical_hit(render::Panel& panel, const geo::Hit2& hit) {
  panel.add(render::Arrow{p2(hit.I), p2(hit.I + hit.N), render::Role::normal});
  panel.add(render::Label{"\\vec{N}_{c}", p2(hit.I + hit.N), render::Side::auto_, render::Role::normal});
  panel.add(render::PointMark{p2(hit.I), render::Role::result,
                              render::Label{"I_{c}", p2(hit.I), render::Side::auto_, render::Role::result}});
}

render::Scene question_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s) {
  render::Scene scene;
  scene.title = ctx.texts.get(key(ctx, "title"));
  scene.description = ctx.texts.get(key(ctx, "figure.question"));
  scene.panels.push_back(world_panel(d, shape, s, false));
  return scene;
}

render::Scene key_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s,
                        render::Panel canonical) {
  render::Scene scene;
  scene.title = ctx.texts.get(key(ctx, "title"));
  scene.description = ctx.texts.get(key(ctx, "figure.key"));
  render::Panel world = world_panel(d, shape, s, true);
  if (s.hit) add_world_hit(world, *s.hit);
  world.caption = ctx.texts.get(key(ctx, "panel.world"));
  canonical.caption = ctx.texts.get(key(ctx, "panel.canonical"));
  scene.panels.push_back(std::move(world));
  scene.panels.push_back(std::move(canonical));
  scene.links.push_back(link_text(ctx, d, shape));
  if (const std::string legend = key(ctx, "figure.legend.candidate"); ctx.texts.has(legend))
    legend_highlight(scene, ctx, legend, render::LegendEntry::Swatch::line);
  return scene;
}

}  // namespace epure::kinds::transformed
