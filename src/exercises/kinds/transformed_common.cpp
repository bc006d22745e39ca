#include "exercises/kinds/transformed_common.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace epure::kinds::transformed {

using geo::Point2;
using geo::Vec2;

namespace {

std::string prefix(Shape shape) { return shape == Shape::ellipse ? "ray_ellipse" : "ray_rectangle"; }
std::string key(Shape shape, std::string_view rest) { return fmt::format("{}.{}", prefix(shape), rest); }
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
  if (shape == Shape::ellipse) return {std::hypot(sx * c, sy * s), std::hypot(sx * s, sy * c)};
  return {sx * std::abs(c) + sy * std::abs(s), sx * std::abs(s) + sy * std::abs(c)};
}

template <class F>
Ex lift(F&& f) {
  try {
    return Ex(f());
  } catch (const std::domain_error&) {  // different radicands, division by zero
  } catch (const exact::ExactOverflow&) {
  }
  return {};
}

exact::Surd divide(const exact::Surd& x, const exact::Surd& y) {
  if (y.is_rational()) return x / y.a();
  // (p + q√c)/(r + s√c) = (p + q√c)(r − s√c)/(r² − s²c); r² − s²c ≠ 0 since √c is irrational
  const exact::Surd conjugate(y.a(), -y.b(), y.c());
  return (x * conjugate) / (y.a() * y.a() - y.b() * y.b() * exact::Rational(y.c()));
}

// v rotated by −θ, given cos θ and sin θ: (c·x + s·y, −s·x + c·y).
ExVec rotate_back(const ExVec& v, const ExVec& cs) {
  return {cs.x * v.x + cs.y * v.y, cs.x * v.y - cs.y * v.x};
}

}  // namespace

std::string instance_text(const Data& d, Shape shape) {
  return InstanceWriter(prefix(shape))
      .point("A", d.A)
      .vec("u", d.u)
      .point("C", d.C)
      .pair(shape == Shape::ellipse ? "radii" : "half", d.sx, d.sy)
      .number("angle", d.angle_deg)
      .finish();
}

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
          constraint(ctx, kind, "max_amplification") * 0.5 * std::pow(10.0, -ctx.decimals)};
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

// ---- exact forms -------------------------------------------------------------------------------

Ex Ex::datum(double x) {
  if (auto r = rational_of(x)) return Ex(*r);
  return {};
}

Ex operator+(const Ex& x, const Ex& y) {
  if (!x.v_ || !y.v_) return {};
  return lift([&] { return *x.v_ + *y.v_; });
}
Ex operator-(const Ex& x, const Ex& y) {
  if (!x.v_ || !y.v_) return {};
  return lift([&] { return *x.v_ - *y.v_; });
}
Ex operator*(const Ex& x, const Ex& y) {
  if (!x.v_ || !y.v_) return {};
  return lift([&] { return *x.v_ * *y.v_; });
}
Ex operator/(const Ex& x, const Ex& y) {
  if (!x.v_ || !y.v_) return {};
  return lift([&] { return divide(*x.v_, *y.v_); });
}
Ex operator-(const Ex& x) {
  if (!x.v_) return {};
  return lift([&] { return -*x.v_; });
}
Ex sqrt(const Ex& x) {
  if (!x.is_rational() || x.v_->a().sign() < 0) return {};
  return lift([&] { return exact::Surd::sqrt(x.v_->a()); });
}

Ex dot(const ExVec& p, const ExVec& q) { return p.x * q.x + p.y * q.y; }

ExVec exact_cos_sin(double degrees) {
  const auto r = rational_of(degrees);
  if (!r || !r->is_integer()) return {};
  const std::int64_t turn = ((r->num() % 360) + 360) % 360;
  const exact::Rational half(1, 2);
  ExVec cs;
  switch (turn % 90) {
    case 0: cs = {Ex::integer(1), Ex::integer(0)}; break;
    case 30: cs = {Ex(exact::Surd(0, half, 3)), Ex(half)}; break;
    case 45: cs = {Ex(exact::Surd(0, half, 2)), Ex(exact::Surd(0, half, 2))}; break;
    case 60: cs = {Ex(half), Ex(exact::Surd(0, half, 3))}; break;
    default: return {};
  }
  for (std::int64_t q = 0; q < turn / 90; ++q) cs = {-cs.y, cs.x};  // a quarter turn more
  return cs;
}

ExactFrame exact_frame(const Data& d) {
  ExactFrame f;
  const ExVec u{Ex::datum(d.u.x), Ex::datum(d.u.y)};
  f.norm_u = sqrt(dot(u, u));
  f.u_hat = {u.x / f.norm_u, u.y / f.norm_u};
  f.cos_sin = exact_cos_sin(d.angle_deg);
  f.CA = {Ex::datum(d.A.x) - Ex::datum(d.C.x), Ex::datum(d.A.y) - Ex::datum(d.C.y)};
  const Ex sx = Ex::datum(d.sx), sy = Ex::datum(d.sy);
  f.CA_rotated = rotate_back(f.CA, f.cos_sin);
  f.Ac = {f.CA_rotated.x / sx, f.CA_rotated.y / sy};
  f.u_rotated = rotate_back(f.u_hat, f.cos_sin);
  f.uc = {f.u_rotated.x / sx, f.u_rotated.y / sy};
  return f;
}

ExactWorld exact_world(const Data& d, const ExactFrame& f, const Ex& t, const ExVec& Nc) {
  ExactWorld w;
  w.t = t;
  w.Nc = Nc;
  w.I = {Ex::datum(d.A.x) + t * f.u_hat.x, Ex::datum(d.A.y) + t * f.u_hat.y};
  // (M⁻¹)ᵀ = rotate(θ)·scale(1/sx, 1/sy)
  const ExVec scaled{Nc.x / Ex::datum(d.sx), Nc.y / Ex::datum(d.sy)};
  const Ex& c = f.cos_sin.x;
  const Ex& s = f.cos_sin.y;
  w.n = {c * scaled.x - s * scaled.y, s * scaled.x + c * scaled.y};
  const Ex length = sqrt(dot(w.n, w.n));
  w.N = {w.n.x / length, w.n.y / length};
  return w;
}

void cross_check(const Ex& e, double core, const char* what) {
  if (!e.has_value()) return;
  const double v = e.get()->value();
  if (!(std::abs(v - core) <= 1e-9 * std::max(1.0, std::abs(core))))
    throw std::logic_error(fmt::format("exact {} = {} disagrees with the core's {}", what, v, core));
}
void cross_check(const ExVec& e, Vec2 core, const char* what) {
  cross_check(e.x, core.x, what);
  cross_check(e.y, core.y, what);
}

bool well_conditioned(const std::vector<double>& tolerances, const Limits& lim) {
  for (double t : tolerances)
    if (!(t <= lim.max_tolerance)) return false;
  return true;
}

// ---- the student's method ----------------------------------------------------------------------

Rounding::Rounding(const Nudge& nudge, int decimals) : nudge_(nudge), scale_(std::pow(10.0, decimals)) {}

double Rounding::operator()(int k, double value) const {
  const double scaled = value * scale_;
  const bool short_enough = std::abs(scaled - std::nearbyint(scaled)) <= 1e-9 * std::max(1.0, std::abs(scaled));
  return short_enough ? value : nudge_.at(k, value);
}

StudentFrame student_frame(const Data& d, const Rounding& r) {
  StudentFrame f;
  const Vec2 u_hat = d.u / geo::norm(d.u);  // drawn data: never zero
  f.u_hat = {r(0, u_hat.x), r(1, u_hat.y)};
  const auto cs = geo::cos_sin_degrees(d.angle_deg);
  f.cos = r(2, cs.cos);
  f.sin = r(3, cs.sin);
  const Vec2 CA = d.A - d.C;
  f.Ac = {r(4, (f.cos * CA.x + f.sin * CA.y) / d.sx), r(5, (f.cos * CA.y - f.sin * CA.x) / d.sy)};
  f.uc = {r(6, (f.cos * f.u_hat.x + f.sin * f.u_hat.y) / d.sx),
          r(7, (f.cos * f.u_hat.y - f.sin * f.u_hat.x) / d.sy)};
  return f;
}

std::vector<double> student_world(const Data& d, const StudentFrame& f, double t, Vec2 Nc) {
  const Point2 I = d.A + t * f.u_hat;
  const Vec2 scaled{Nc.x / d.sx, Nc.y / d.sy};
  const Vec2 n{f.cos * scaled.x - f.sin * scaled.y, f.sin * scaled.x + f.cos * scaled.y};
  const Vec2 N = n / geo::norm(n);  // a non-zero normal through an invertible map
  return {I.x, I.y, N.x, N.y};
}

// ---- questions ---------------------------------------------------------------------------------

std::vector<std::string> fields() { return {"Ac", "uc", "inside", "hit", "t", "I", "N"}; }

void ask(Questions& q, const Solved& s, const std::vector<double>& tol, const ExactFrame& f,
         const ExactWorld& w) {
  q.point("Ac", s.canonical_ray.origin, tol[0], tol[1], f.Ac.x.get(), f.Ac.y.get());
  q.vector("uc", s.canonical_ray.direction, tol[2], tol[3], f.uc.x.get(), f.uc.y.get());
  q.boolean("inside", s.inside);
  q.boolean("hit", s.hit.has_value());
  if (!s.hit) return;
  q.number("t", s.hit->t, tol[4], w.t.get());
  q.point("I", s.hit->I, tol[5], tol[6], w.I.x.get(), w.I.y.get());
  q.vector("N", s.hit->N, tol[7], tol[8], w.N.x.get(), w.N.y.get());
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
  return ctx.texts.format(key(shape, "inverse"),
                          {{"inv_" + a, reciprocal(N, d.sx)},
                           {"inv_" + b, reciprocal(N, d.sy)},
                           {"minus_angle", N.datum(0.0 - d.angle_deg)},
                           {"minus_C", N.point(0.0 - d.C.x, 0.0 - d.C.y)}});
}
}  // namespace

std::string link_text(const ExerciseContext& ctx, const Data& d, Shape shape) {
  return ctx.texts.format(key(shape, "link"), {{"inverse", inverse_text(ctx, d, shape)}});
}

void step(render::Section& s, const ExerciseContext& ctx, std::string_view name, const TextVars& vars) {
  // the kind is the spec's: ray_ellipse or ray_rectangle
  s.add(render::Paragraph{ctx.texts.format(fmt::format("{}.step.{}", ctx.spec.kind, name), vars)});
}

void frame_steps(render::Section& s, const ExerciseContext& ctx, const Data& d, Shape shape,
                 const Solved& solved, const ExactFrame& f) {
  const auto& N = ctx.numbers;
  step(s, ctx, "transform", {{"inverse", inverse_text(ctx, d, shape)}});
  const Vec2 u_hat = *geo::normalized(d.u);
  step(s, ctx, "unit",
       {{"norm_u", equals_value(ctx, geo::norm(d.u), f.norm_u.get())},
        {"u_hat", shown_point(ctx, geo::to_point(u_hat), f.u_hat.x.get(), f.u_hat.y.get())}});
  const auto cs = geo::cos_sin_degrees(d.angle_deg);
  step(s, ctx, "cos_sin",
       {{"angle", N.datum(d.angle_deg)},
        {"cos", equals_value(ctx, cs.cos, f.cos_sin.x.get())},
        {"sin", equals_value(ctx, cs.sin, f.cos_sin.y.get())}});
  const auto back = geo::Transform2::rotate_degrees(0.0 - d.angle_deg);
  const Vec2 CA = d.A - d.C;
  const Vec2 CA_rotated = back.apply(CA);
  step(s, ctx, "Ac",
       {{"CA", N.point(CA.x, CA.y)},
        {"rotated", shown_point(ctx, geo::to_point(CA_rotated), f.CA_rotated.x.get(), f.CA_rotated.y.get())},
        {"Ac", shown_point(ctx, solved.canonical_ray.origin, f.Ac.x.get(), f.Ac.y.get())}});
  const Vec2 u_rotated = back.apply(u_hat);
  step(s, ctx, "uc",
       {{"rotated", shown_point(ctx, geo::to_point(u_rotated), f.u_rotated.x.get(), f.u_rotated.y.get())},
        {"uc", shown_point(ctx, geo::to_point(solved.canonical_ray.direction), f.uc.x.get(), f.uc.y.get())}});
}

void world_steps(render::Section& s, const ExerciseContext& ctx, const Data&, Shape,
                 const Solved& solved, const ExactWorld& w) {
  const geo::Hit2& hit = *solved.hit;
  const Vec2 Nc = solved.canonical_hit->N;
  const Vec2 n = solved.to_world.apply_normal(Nc);
  step(s, ctx, "I", {{"I", shown_point(ctx, hit.I, w.I.x.get(), w.I.y.get())}});
  step(s, ctx, "N",
       {{"Nc", shown_point(ctx, geo::to_point(Nc), w.Nc.x.get(), w.Nc.y.get())},
        {"n", shown_point(ctx, geo::to_point(n), w.n.x.get(), w.n.y.get())},
        {"N", shown_point(ctx, geo::to_point(hit.N), w.N.x.get(), w.N.y.get())}});
}

// ---- diagrams ----------------------------------------------------------------------------------

render::Panel world_panel(const Data& d, Shape shape, const Solved& s) {
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

  panel.add(render::Ray{p2(d.A), p2(u_hat), render::Role::data});
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
  panel.add(render::Ray{p2(Ac), p2(uc), render::Role::data});
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
  scene.title = ctx.texts.get(key(shape, "title"));
  scene.description = ctx.texts.get(key(shape, "figure.question"));
  scene.panels.push_back(world_panel(d, shape, s));
  return scene;
}

render::Scene key_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s,
                        render::Panel canonical) {
  render::Scene scene;
  scene.title = ctx.texts.get(key(shape, "title"));
  scene.description = ctx.texts.get(key(shape, "figure.key"));
  render::Panel world = world_panel(d, shape, s);
  if (s.hit) add_world_hit(world, *s.hit);
  world.caption = ctx.texts.get(key(shape, "panel.world"));
  canonical.caption = ctx.texts.get(key(shape, "panel.canonical"));
  scene.panels.push_back(std::move(world));
  scene.panels.push_back(std::move(canonical));
  scene.links.push_back(link_text(ctx, d, shape));
  return scene;
}

}  // namespace epure::kinds::transformed
