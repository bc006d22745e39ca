// Exercise 3 of the course: the first point where a ray meets a circle, by projecting C on the
// ray (t_proj, P) and Pythagoras in the triangle C–P–I (PI = √(r² − d²)). Early rejections in the
// course's order: behind (A outside, t_proj < 0), then miss (d² > r²). Unlike the course's code,
// a ray that starts inside the circle hits it, on its way out.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kind_support.h"
#include "exercises/kinds/registry.h"
#include "geometry/ray_circle.h"

namespace epure::kinds {

namespace {

using exact::Rational;
using exact::Surd;
using geo::Point2;
using geo::Vec2;

struct Data {
  Point2 A;
  Vec2 u;
  Point2 C;
  double r;
};

// Directions of rational length (Pythagorean triples and axes), so that û and t_proj are
// rational at the easy level. Signs are drawn on top.
constexpr Vec2 kEasyDirections[] = {{1, 0}, {0, 1}, {2, 0}, {0, 2},  {3, 4},
                                    {4, 3}, {6, 8}, {8, 6}, {5, 12}, {12, 5}};

// Beyond this radicand (numerator × denominator under the root) an exact form is neither short
// nor cheap: Surd reduces √c by trial division. Such answers are given in decimals only.
constexpr std::int64_t kMaxRadicand = 100'000'000;

// √r as a Surd; throws ExactOverflow when the radicand is too large to be worth it.
Surd bounded_sqrt(Rational r) {
  if (r.num() > kMaxRadicand / r.den()) throw exact::ExactOverflow();
  return Surd::sqrt(r);
}

// Runs one exact computation; empty when it overflows or needs two different radicands.
template <class F>
auto attempt(F&& f) -> std::optional<decltype(f())> {
  try {
    return f();
  } catch (const exact::ExactOverflow&) {
  } catch (const std::domain_error&) {
  }
  return std::nullopt;
}

// An exact form must agree with the core's double: it is an independent second computation, and
// a sheet is issued only when both agree.
void check_agrees(const std::optional<Surd>& e, double core, const char* what) {
  if (e && !(std::abs(e->value() - core) <= 1e-9 * std::max(1.0, std::abs(core))))
    throw std::logic_error(fmt::format("ray_circle: exact {} = {} disagrees with the core's {}", what,
                                       e->value(), core));
}

// A value as a worked step shows it: its exact form when short, with its decimal value when that
// is not the same number written otherwise ("37/5 = 7.4", "−6√5/5 ≈ −2.68"); the decimal alone
// when the exact form is long (one-decimal data give fractions like 376996/25925).
std::string step_value(const ExerciseContext& ctx, double value, const std::optional<Surd>& e) {
  const std::string rounded = ctx.numbers.rounded(value, ctx.decimals);
  if (!e) return rounded;
  try {
    const std::string pretty = e->pretty();
    if (pretty.size() > 16 || e->a().den() > 1000 || e->b().den() > 1000) return rounded;
    const std::string exact = ctx.numbers.localise(pretty);
    if (!e->is_rational()) return fmt::format("{} ≈ {}", exact, rounded);
    const std::int64_t den = e->a().den();
    if (den == 1) return exact;
    std::int64_t pow10 = 1;
    for (int i = 0; i < ctx.decimals; ++i) pow10 *= 10;
    if (pow10 % den == 0) return fmt::format("{} = {}", exact, ctx.numbers.datum(value, ctx.decimals));
    return fmt::format("{} ≈ {}", exact, rounded);
  } catch (const exact::ExactOverflow&) {
    return rounded;
  }
}

std::string step_point(const ExerciseContext& ctx, Point2 p, const std::optional<Surd>& ex,
                       const std::optional<Surd>& ey) {
  return fmt::format("({}{} {})", step_value(ctx, p.x, ex), ctx.numbers.decimal_comma ? "\u00a0;" : ",",
                     step_value(ctx, p.y, ey));
}

std::string branch_of(const geo::RayCircle& rc) {
  if (rc.inside) return "inside";
  if (rc.hit) return "hit";
  return geo::to_string(*rc.reason);
}

// The exact values of the worked solution, from the rational data.
struct Exact {
  std::optional<Rational> ac2, r2, d2;
  std::optional<Surd> norm_u, ux, uy, t_proj, px, py, d2s, h, t, ix, iy, nx, ny;
};

Exact exact_values(const Data& d, bool inside) {
  Exact e;
  const auto ax = rational_of(d.A.x), ay = rational_of(d.A.y), ux = rational_of(d.u.x),
             uy = rational_of(d.u.y), cx = rational_of(d.C.x), cy = rational_of(d.C.y),
             r = rational_of(d.r);
  if (!(ax && ay && ux && uy && cx && cy && r)) return e;
  try {
    const Rational acx = *cx - *ax, acy = *cy - *ay;
    const Rational n = *ux * *ux + *uy * *uy;
    const Rational dot = *ux * acx + *uy * acy, cross = *ux * acy - *uy * acx;
    e.ac2 = acx * acx + acy * acy;
    e.r2 = *r * *r;
    e.d2 = cross * cross / n;  // (u∧AC)² / u·u
    e.d2s = Surd(*e.d2);
    // P = A + (u·AC / u·u)·u: rational whatever the length of u
    const Rational k = dot / n;
    e.px = Surd(*ax + k * *ux);
    e.py = Surd(*ay + k * *uy);
    e.norm_u = attempt([&] { return bounded_sqrt(n); });
    if (e.norm_u) {
      e.ux = attempt([&] { return *e.norm_u * Surd(*ux / n); });
      e.uy = attempt([&] { return *e.norm_u * Surd(*uy / n); });
      e.t_proj = attempt([&] { return *e.norm_u * Surd(k); });
    }
    const Rational h2 = *e.r2 - *e.d2;
    if (h2.sign() < 0) return e;  // a miss: no Pythagoras
    const Rational sign(inside ? 1 : -1);
    e.h = attempt([&] { return bounded_sqrt(h2); });
    if (e.t_proj && e.h) e.t = attempt([&] { return *e.t_proj + *e.h * Surd(sign); });
    // I = P ± √(h²/u·u)·u, N = (I − C)/r
    const auto along = attempt([&] { return bounded_sqrt(h2 / n) * Surd(sign); });
    if (!along) return e;
    e.ix = attempt([&] { return *e.px + *along * Surd(*ux); });
    e.iy = attempt([&] { return *e.py + *along * Surd(*uy); });
    if (e.ix) e.nx = attempt([&] { return (*e.ix - Surd(*cx)) / *r; });
    if (e.iy) e.ny = attempt([&] { return (*e.iy - Surd(*cy)) / *r; });
  } catch (const exact::ExactOverflow&) {
  }
  return e;
}

// True when x is written exactly with `decimals` decimals: a student's rounding leaves it as is.
bool on_decimal_grid(double x, int decimals) {
  const double scaled = x * std::pow(10.0, decimals);
  return std::abs(scaled - std::nearbyint(scaled)) <= 1e-9 * std::max(1.0, std::abs(scaled));
}

// The student's method, in the course's order, rounding û, t_proj, P, d², PI, t and I: the
// answers t_proj, d² and, with a hit, t, I and N. An intermediate that already has at most
// `decimals` decimals (û = (0.6, 0.8)) is written as it is: rounding does not move it.
StudentMethod student_method(const Data& d, bool hit, bool from_inside, int decimals) {
  return [d, hit, from_inside, decimals](const Nudge& nudge) {
    auto rounded = [&](int k, double v) { return on_decimal_grid(v, decimals) ? v : nudge.at(k, v); };
    const double length = geo::norm(d.u);
    const Vec2 uh{rounded(0, d.u.x / length), rounded(1, d.u.y / length)};
    const Vec2 AC = d.C - d.A;
    const double t_proj = rounded(2, uh.x * AC.x + uh.y * AC.y);
    const Point2 P{rounded(3, d.A.x + t_proj * uh.x), rounded(4, d.A.y + t_proj * uh.y)};
    const Vec2 CP = P - d.C;
    const double d2 = rounded(5, CP.x * CP.x + CP.y * CP.y);
    if (!hit) return std::vector<double>{t_proj, d2};
    const double h = rounded(6, std::sqrt(d.r * d.r - d2));
    const double t = rounded(7, from_inside ? t_proj + h : t_proj - h);
    const Point2 I{rounded(8, d.A.x + t * uh.x), rounded(9, d.A.y + t * uh.y)};
    return std::vector<double>{t_proj, d2, t, I.x, I.y, (I.x - d.C.x) / d.r, (I.y - d.C.y) / d.r};
  };
}

// Unnudged, the student's method is the core's answer by another road: tolerances derived from
// a method that disagrees would grade against the wrong figure.
void check_method(const StudentMethod& method, const geo::RayCircle& rc) {
  std::vector<double> core = {rc.t_proj, rc.d2};
  if (rc.hit) core.insert(core.end(), {rc.hit->t, rc.hit->I.x, rc.hit->I.y, rc.hit->N.x, rc.hit->N.y});
  const auto mine = method(Nudge{});
  for (std::size_t i = 0; i < core.size(); ++i)
    if (!(std::abs(mine[i] - core[i]) <= 1e-9 * std::max(1.0, std::abs(core[i]))))
      throw std::logic_error(fmt::format("ray_circle: the student's method gives {} where the core gives {}",
                                         mine[i], core[i]));
}

class RayCircleKind final : public ExerciseKind {
 public:
  std::string_view name() const override { return "ray_circle"; }
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 3}, {"behind", 1}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override {
    return {
        {"tangent_margin", 0.15},   // |d/r − 1| at least this: a clear hit or a clear miss
        {"boundary_margin", 0.15},  // |AC/r − 1| at least this: A clearly inside or outside
        {"t_proj_margin", 0.5},     // |t_proj| at least this from outside: clearly ahead or behind
        {"t_min", 1.0},             // the hit at least this far along the ray
        {"min_offset", 0.25},       // d/r at least this: C off the ray's line, a real triangle CPI
        {"min_radius", 2.0},
        {"max_radius", 4.0},
    };
  }
  std::vector<std::string> fields() const override {
    return {"t_proj", "d2", "inside", "hit", "t", "I", "N", "reason"};
  }
  std::vector<SheetField> sheet_fields() const override {
    return {{"t_proj", render::AnswerField::Kind::number, {}}, {"d2", render::AnswerField::Kind::number, {}},
            {"inside", render::AnswerField::Kind::boolean, {}},   {"hit", render::AnswerField::Kind::boolean, {}},
            {"t", render::AnswerField::Kind::number, {}},         {"I", render::AnswerField::Kind::point, {}},
            {"N", render::AnswerField::Kind::point, {}},          {"reason", render::AnswerField::Kind::choice, {"behind", "miss"}}};
  }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    const double tm = constraint(ctx, *this, "tangent_margin");
    const double bm = constraint(ctx, *this, "boundary_margin");
    const double tpm = constraint(ctx, *this, "t_proj_margin") / (hard ? 3 : 1);
    const double t_min = constraint(ctx, *this, "t_min") / (hard ? 3 : 1);
    const double min_offset = constraint(ctx, *this, "min_offset");
    const double r_lo = constraint(ctx, *this, "min_radius");
    const double r_hi = constraint(ctx, *this, "max_radius");
    // the circle must fit in the drawing area [-1, 11] × [-1, 9]
    if (!(r_lo > 0 && r_lo <= r_hi && r_hi <= 5))
      throw std::runtime_error("ray_circle: need 0 < min_radius ≤ max_radius ≤ 5");
    // hard: close to tangency or to the circle, yet on the clear side of these margins
    const double tm_clear = hard ? tm / 4 : tm, bm_clear = hard ? bm / 3 : bm;

    auto accept = [&](const Data& x) {
      const auto rc = geo::intersect(geo::Ray2::unit(x.A, x.u), geo::Circle{x.C, x.r});
      if (branch_of(rc) != ctx.branch) return false;
      const double ac = geo::norm(rc.AC) / x.r;  // A's distance to C, in radii
      const double dr = std::sqrt(rc.d2) / x.r;   // the line's distance to C, in radii
      if (rc.P.x < -1 || rc.P.x > 11 || rc.P.y < -1 || rc.P.y > 9) return false;
      if (dr < min_offset) return false;
      if (rc.inside) {
        if (ac > 1 - bm_clear || rc.hit->t < t_min) return false;
        return !hard || ac >= 1 - bm;
      }
      if (ac < 1 + bm_clear || std::abs(dr - 1) < tm_clear) return false;
      const bool near_tangent = std::abs(dr - 1) <= tm, near_circle = ac <= 1 + bm;
      if (ctx.branch == "behind") return rc.t_proj <= -tpm && (!hard || near_tangent || near_circle);
      if (rc.t_proj < tpm) return false;
      if (ctx.branch == "miss") return !hard || near_tangent;
      return rc.hit->t >= t_min && (!hard || near_tangent || near_circle);
    };
    // easy: Pythagoras gives a rational PI (r² − d² is the square of a rational)
    auto pythagorean = [&](const Data& x) {
      if (level != Difficulty::easy || ctx.branch == "behind" || ctx.branch == "miss") return true;
      const auto e = exact_values(x, ctx.branch == "inside");
      return e.h && e.h->is_rational();
    };

    const Data d = draw_until(200000, "ray_circle (branch, tangency and boundary margins, t range)",
                              [&]() -> std::optional<Data> {
      Data x;
      x.r = grid_value(rng, r_lo, r_hi, level);
      x.C = {grid_value(rng, x.r - 1, 11 - x.r, level), grid_value(rng, x.r - 1, 9 - x.r, level)};
      x.A = {grid_value(rng, 0, 10, level), grid_value(rng, 0, 8, level)};
      if (level == Difficulty::easy) {
        x.u = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
        if (rng.chance(0.5)) x.u.x = -x.u.x;
        if (rng.chance(0.5)) x.u.y = -x.u.y;
      } else {
        const double m = hard ? 3 : 4;
        x.u = {grid_value(rng, -m, m, level), grid_value(rng, -m, m, level)};
        if (geo::norm(x.u) < 1) return std::nullopt;
      }
      if (!accept(x) || !pythagorean(x)) return std::nullopt;
      return x;
    });
    if (auto taken = already_taken(ctx, instance_text(d))) return *std::move(taken);
    return build(d, ctx);
  }

 private:
  static std::string instance_text(const Data& d) {
    return InstanceWriter("ray_circle").point("A", d.A).vec("u", d.u).point("C", d.C).number("r", d.r).finish();
  }

  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto rc = geo::intersect(geo::Ray2::unit(d.A, d.u), geo::Circle{d.C, d.r});
    const std::string branch = branch_of(rc);

    ExerciseInstance inst;
    inst.n = ctx.n;
    inst.kind = std::string(name());
    inst.branch = ctx.branch;
    inst.instance = instance_text(d);
    inst.solution = solve_instance(inst.instance);
    inst.fingerprint = fingerprint(inst.instance);

    const Exact e = exact_values(d, rc.inside);
    check_agrees(e.t_proj, rc.t_proj, "t_proj");
    check_agrees(e.d2s, rc.d2, "d2");
    if (rc.hit) {
      check_agrees(e.t, rc.hit->t, "t");
      check_agrees(e.ix, rc.hit->I.x, "I.x");
      check_agrees(e.iy, rc.hit->I.y, "I.y");
      check_agrees(e.nx, rc.hit->N.x, "N.x");
      check_agrees(e.ny, rc.hit->N.y, "N.y");
    }

    const StudentMethod method = student_method(d, rc.hit.has_value(), rc.inside, ctx.decimals);
    check_method(method, rc);
    const auto tol = derive_abs_tolerances(method, 10, ctx.decimals);

    const bool hit = rc.hit.has_value();
    Questions q(ctx);
    q.number("t_proj", rc.t_proj, tol[0], e.t_proj);
    q.number("d2", rc.d2, tol[1], e.d2s);
    q.boolean("inside", rc.inside);
    q.boolean("hit", hit);
    if (hit) {
      q.number("t", rc.hit->t, tol[2], e.t);
      q.point("I", rc.hit->I, tol[3], tol[4], e.ix, e.iy);
      q.vector("N", rc.hit->N, tol[5], tol[6], e.nx, e.ny);
    } else {
      q.choice("reason", geo::to_string(*rc.reason), {"behind", "miss"});
    }
    inst.questions = q.take_questions();

    const TextVars data_vars = {{"A", N.point(d.A.x, d.A.y)},
                                {"u", N.point(d.u.x, d.u.y)},
                                {"C", N.point(d.C.x, d.C.y)},
                                {"r", N.datum(d.r)}};
    // ---- the sheet
    inst.sheet = begin_sheet_section(ctx, "ray_circle.title");
    inst.sheet.add(render::Paragraph{T.format("ray_circle.statement", data_vars)});
    inst.sheet.add(render::Figure{question_scene(d, rc, ctx), 0.55});
    add_fields(inst.sheet, q);

    // ---- the key, step by step as the course does it
    inst.key = begin_key_section(ctx, "ray_circle.title");
    inst.key.add(render::Paragraph{T.format("ray_circle.statement", data_vars)});
    auto step = [&](std::string_view key, const TextVars& vars = {}) {
      inst.key.add(render::Paragraph{T.format(fmt::format("ray_circle.step.{}", key), vars)});
    };
    const std::string r2 = step_value(ctx, d.r * d.r, e.r2 ? std::optional<Surd>(*e.r2) : std::nullopt);
    const std::string d2 = step_value(ctx, rc.d2, e.d2s);
    step("AC", {{"AC", N.point(rc.AC.x, rc.AC.y)},
                {"ac2", step_value(ctx, geo::norm2(rc.AC), e.ac2 ? std::optional<Surd>(*e.ac2) : std::nullopt)},
                {"r2", r2}});
    step(rc.inside ? "inside.yes" : "inside.no");
    const Vec2 uh = d.u / geo::norm(d.u);
    step("unit", {{"norm_u", step_value(ctx, geo::norm(d.u), e.norm_u)},
                  {"u_hat", step_point(ctx, geo::to_point(uh), e.ux, e.uy)}});
    step("t_proj", {{"t_proj", step_value(ctx, rc.t_proj, e.t_proj)}});
    if (rc.inside) step("ahead.inside");
    else if (branch == "behind") step("behind");
    else step("ahead.outside");
    step("P", {{"P", step_point(ctx, rc.P, e.px, e.py)}});
    step("d2", {{"d2", d2}});
    if (branch == "miss") {
      step("miss", {{"d2", d2}, {"r2", r2}});
    } else if (branch != "behind") {
      step("pythagoras", {{"d2", d2}, {"r2", r2}, {"h", step_value(ctx, *rc.half_chord, e.h)}});
      step(rc.inside ? "t.inside" : "t.outside", {{"t", step_value(ctx, rc.hit->t, e.t)}});
      step("I", {{"I", step_point(ctx, rc.hit->I, e.ix, e.iy)}});
      step("N", {{"N", step_point(ctx, geo::to_point(rc.hit->N), e.nx, e.ny)}});
    }
    inst.key.add(render::Figure{key_scene(d, rc, branch, ctx), 0.6});
    add_lines(inst.key, q);
    return inst;
  }

  static render::Panel data_panel(const Data& d, const geo::RayCircle& rc) {
    render::Panel panel;
    const Vec2 uh = d.u / geo::norm(d.u);
    panel.view = view_around({p2(d.A), p2(d.A + uh), {d.C.x - d.r, d.C.y - d.r},
                              {d.C.x + d.r, d.C.y + d.r}, p2(rc.P)},
                             1.0, 5.0);
    panel.add(render::Grid{1, true});
    return panel;
  }

  render::Scene question_scene(const Data& d, const geo::RayCircle& rc, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("ray_circle.title");
    s.description = ctx.texts.get("ray_circle.figure.question");
    render::Panel panel = data_panel(d, rc);
    panel.add(render::Circle{p2(d.C), d.r, render::Role::data});
    panel.add(render::Ray{p2(d.A), p2(d.u), render::Role::data});
    panel.add(render::PointMark{p2(d.C), render::Role::data, render::Label{"C", p2(d.C)}});
    panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
    s.panels.push_back(std::move(panel));
    return s;
  }

  render::Scene key_scene(const Data& d, const geo::RayCircle& rc, const std::string& branch,
                          const ExerciseContext& ctx) const {
    using render::Role;
    const auto& T = ctx.texts;
    render::Scene s;
    s.title = T.get("ray_circle.title");
    s.description = T.get(fmt::format("ray_circle.figure.key.{}", branch));
    render::Panel panel = data_panel(d, rc);
    const Vec2 uh = d.u / geo::norm(d.u);
    // a side a→b of the triangle gets its dimension on the side away from the third vertex c
    auto outward = [](Point2 a, Point2 b, Point2 c) { return geo::cross(b - a, c - a) > 0 ? -0.35 : 0.35; };

    // the ray's whole line: P may lie behind A
    panel.add(render::Line{p2(d.A), p2(d.A + d.u), Role::construction});
    if (rc.hit) {
      const Point2 I = rc.hit->I;
      panel.add(render::Polygon{{p2(d.C), p2(rc.P), p2(I)}, true, Role::construction, true});
    }
    panel.add(render::Circle{p2(d.C), d.r, Role::data});
    panel.add(render::Ray{p2(d.A), p2(d.u), Role::data});
    panel.add(render::Segment{p2(d.C), p2(rc.P), Role::construction, true});
    panel.add(render::RightAngle{p2(rc.P), p2(d.C - rc.P), p2(d.u), Role::construction});
    panel.add(render::Arrow{p2(d.A), p2(d.A + uh), Role::construction});
    panel.add(render::Label{T.get("ray_circle.figure.u_hat"), p2(d.A + uh), render::Side::auto_,
                            Role::construction});
    if (rc.hit) {
      const Point2 I = rc.hit->I;
      panel.add(render::Dimension{p2(d.C), p2(rc.P), T.get("ray_circle.figure.d"),
                                  outward(d.C, rc.P, I), Role::construction});
      panel.add(render::Dimension{p2(rc.P), p2(I), T.get("ray_circle.figure.h"),
                                  outward(rc.P, I, d.C), Role::construction});
      panel.add(render::Dimension{p2(I), p2(d.C), T.get("ray_circle.figure.r"),
                                  outward(I, d.C, rc.P), Role::construction});
    } else if (branch == "miss") {
      // d > r: the radius towards P stops short of P
      const Vec2 to_P = rc.P - d.C;
      const Point2 R = d.C + (d.r / geo::norm(to_P)) * to_P;
      panel.add(render::Segment{p2(d.C), p2(R), Role::construction});
      panel.add(render::Dimension{p2(d.C), p2(rc.P), T.get("ray_circle.figure.d"), 0.35, Role::construction});
      panel.add(render::Dimension{p2(d.C), p2(R), T.get("ray_circle.figure.r"), -0.35, Role::construction});
    } else {
      // behind: P lies before A on the line, at a negative parameter
      panel.add(render::Tick{p2(d.A), p2(d.u), std::string("0"), Role::construction});
      panel.add(render::Tick{p2(rc.P), p2(d.u), T.get("ray_circle.figure.t_proj_negative"), Role::construction});
    }
    panel.add(render::PointMark{p2(d.C), Role::data, render::Label{"C", p2(d.C)}});
    panel.add(render::PointMark{p2(d.A), Role::data, render::Label{"A", p2(d.A)}});
    panel.add(render::PointMark{p2(rc.P), Role::construction,
                                render::Label{"P", p2(rc.P), render::Side::auto_, Role::construction}});
    if (rc.hit) {
      const Point2 I = rc.hit->I;
      panel.add(render::PointMark{p2(I), Role::result, render::Label{"I", p2(I), render::Side::auto_, Role::result}});
      panel.add(render::Arrow{p2(I), p2(I + rc.hit->N), Role::normal});
      panel.add(render::Label{T.get("ray_circle.figure.N"), p2(I + rc.hit->N), render::Side::auto_, Role::normal});
    }
    s.panels.push_back(std::move(panel));
    return s;
  }
};

}  // namespace

namespace testing {
// The student's method without nudges, for the tests to compare with the core.
std::vector<double> ray_circle_student_answers(geo::Point2 A, geo::Vec2 u, geo::Point2 C, double r) {
  const auto rc = geo::intersect(geo::Ray2::unit(A, u), geo::Circle{C, r});
  return student_method(Data{A, u, C, r}, rc.hit.has_value(), rc.inside, 2)(Nudge{});
}
}  // namespace testing

const ExerciseKind& ray_circle_kind() {
  static const RayCircleKind kind;
  return kind;
}

}  // namespace epure::kinds
