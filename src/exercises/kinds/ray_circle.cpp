// Exercise 3 of the course: the first point where a ray meets a circle, by projecting C on the
// ray (t_proj, P) and Pythagoras in the triangle C–P–I (PI = √(r² − d²)). Early rejections in the
// course's order: behind (A outside, t_proj < 0), then miss (d² > r²). Unlike the course's code,
// a ray that starts inside the circle hits it, on its way out.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kind_method.h"
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

std::string branch_of(const geo::RayCircle& rc) {
  if (rc.inside) return "inside";
  if (rc.hit) return "hit";
  return geo::to_string(*rc.reason);
}

geo::RayCircle solve_core(const Data& d) { return geo::intersect(geo::Ray2::unit(d.A, d.u), geo::Circle{d.C, d.r}); }

using method::AnswerType;
constexpr std::string_view kReasons[] = {"behind", "miss"};

// The course's exercise 3, written once (method.h).
struct RayCircle {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "ray_circle";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("u", d.u);
    v("C", d.C);
    v("r", d.r);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"t_proj", AnswerType::number}, {"d2", AnswerType::number}, {"inside", AnswerType::boolean},
      {"hit", AnswerType::boolean},   {"t", AnswerType::number},  {"I", AnswerType::point},
      {"N", AnswerType::point},       {"reason", AnswerType::choice, 1, kReasons}};

  static constexpr std::string_view kRoads[] = {"pythagoras_apc"};
  // what the exercise is worth on every sheet, whatever the branch (the spec may say otherwise)
  static constexpr double kPoints = 7;

  static constexpr std::string_view kMistakes[] = {"direction_not_unit", "far_intersection", "near_root_inside",
                                                   "normal_not_unit", "normal_inward"};

  // The student's road, in the course's order: û, t_proj = û·AC, P = A + t_proj·û, d² = CP²,
  // then Pythagoras in C–P–I, t = t_proj ∓ √(r² − d²), I = A + t·û, N = (I − C)/r. They round
  // û, t_proj, P, d², PI, t and I on the way.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using method::less_equal;
    const auto A = m.in(d.A), C = m.in(d.C), u = m.in(d.u);
    const auto r = m.in(d.r), zero = m.in(0.0), one = m.in(1.0);
    const auto AC = m.note("AC", C - A);
    const auto ac2 = m.note("ac2", norm2(AC));
    const auto r2 = m.note("r2", r * r);
    const auto inside = m.boolean("inside", less(ac2, r2));
    const auto n = dot(u, u);
    const auto length = m.note("norm_u", sqrt(n));
    const auto uh = m.round("u_hat", m.mistake("direction_not_unit", u / length, u));
    const auto t_proj = m.number("t_proj", m.round("t_proj", dot(uh, AC)));
    const auto P = m.round("P", A + t_proj * uh);
    // d² = CP², or by Pythagoras in the triangle A–P–C: AC² − t_proj²
    const auto d2 = m.number("d2", m.round("d2", m.road("pythagoras_apc", norm2(P - C), ac2 - t_proj * t_proj)));
    const auto ahead = !less(t_proj, zero);
    const auto hit = m.boolean("hit", inside || (ahead && less_equal(d2, r2)));
    if (!hit) {
      m.choice("reason", method::pick(ahead, "miss", "behind"));
      return;
    }
    const auto h2 = r2 - d2;
    const auto h = m.round("h", sqrt(h2));
    // from outside the ray meets the near point first; from inside it leaves at the far one
    const auto t = m.number("t", m.round("t", inside ? m.mistake("near_root_inside", t_proj + h, t_proj - h)
                                                     : m.mistake("far_intersection", t_proj - h, t_proj + h)));
    const auto along = (inside ? one : -one) * sqrt(h2 / n);
    const auto I = m.point("I", m.round("I", m.either(A + t * uh, P + along * u)));
    const auto IC = I - C;
    m.point("N", m.mistake("normal_inward", m.mistake("normal_not_unit", IC / r, IC), -(IC / r)));
  }

  static CoreAnswers core(const Data& d) {
    const auto rc = solve_core(d);
    CoreAnswers a;
    a.number("t_proj", rc.t_proj).number("d2", rc.d2).boolean("inside", rc.inside).boolean("hit", rc.hit.has_value());
    if (rc.hit) a.number("t", rc.hit->t).point("I", rc.hit->I).vec("N", rc.hit->N);
    else a.choice("reason", geo::to_string(*rc.reason));
    return a;
  }
};

class RayCircleKind final : public MethodKind<RayCircle> {
 public:
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
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}, {"N", 0, "I"}}; }

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
      const auto run = exact_run(x);
      const auto* h = run.step("h");
      return h && h->x.e && h->x.e->is_rational();
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
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return build(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto rc = solve_core(d);
    const std::string branch = branch_of(rc);

    ExerciseInstance inst = begin_instance(d, ctx);
    KeySolution key = solve(d, ctx);
    const Questions& q = key.questions;
    inst.questions = key.questions.take_questions();
    auto value = [&](std::string_view id) { return step_value(ctx, key.value(id), key.exact(id)); };
    auto point = [&](std::string_view id) { return step_point(ctx, key.point(id), key.exact_x(id), key.exact_y(id)); };

    const TextVars data_vars = {{"A", N.point(d.A.x, d.A.y)},
                                {"u", N.point(d.u.x, d.u.y)},
                                {"C", N.point(d.C.x, d.C.y)},
                                {"r", N.datum(d.r)}};
    // ---- the sheet
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      inst.sheet = begin_sheet_section(ctx, "ray_circle.title");
      inst.sheet.add(render::Paragraph{T.format("ray_circle.statement", data_vars)});
      inst.sheet.add(render::Figure{question_scene(d, rc, ctx), 0.55});
      add_fields(inst.sheet, q);
    }

    // ---- the key, step by step as the course does it
    inst.key = begin_key_section(ctx, "ray_circle.title");
    inst.key.add(render::Paragraph{T.format("ray_circle.data", data_vars)});
    auto step = [&](std::string_view key, const TextVars& vars = {}) {
      inst.key.add(render::Paragraph{T.format(fmt::format("ray_circle.step.{}", key), vars)});
    };
    const std::string r2 = value("r2"), d2 = value("d2");
    step("AC", {{"AC", N.point(rc.AC.x, rc.AC.y)}, {"ac2", value("ac2")}, {"r2", r2}});
    step(rc.inside ? "inside.yes" : "inside.no");
    step("unit", {{"norm_u", value("norm_u")}, {"u_hat", point("u_hat")}});
    step("t_proj", {{"t_proj", value("t_proj")}});
    if (rc.inside) step("ahead.inside");
    else if (branch == "behind") step("behind");
    else step("ahead.outside");
    step("P", {{"P", point("P")}});
    step("d2", {{"d2", d2}});
    if (branch == "miss") {
      step("miss", {{"d2", d2}, {"r2", r2}});
    } else if (branch != "behind") {
      step("pythagoras", {{"d2", d2}, {"r2", r2}, {"h", value("h")}});
      step(rc.inside ? "t.inside" : "t.outside", {{"t", value("t")}});
      step("I", {{"I", point("I")}});
      step("N", {{"N", point("N")}});
    }
    inst.key.add(render::Figure{key_scene(d, rc, branch, ctx), 0.45});
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

const ExerciseKind& ray_circle_kind() {
  static const RayCircleKind kind;
  return kind;
}

}  // namespace epure::kinds
