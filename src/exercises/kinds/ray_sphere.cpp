// The course's exercise 3 in space: the first point where a ray meets a sphere, by the same
// method as the circle (the projection P of C on the ray, early rejections behind then miss,
// Pythagoras in C–P–I). The plane through the ray and C holds the whole construction: the key
// draws it in true size beside the 3D view, where it is exactly the 2D ray/circle figure.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/kind_method.h"
#include "exercises/kinds/space_common.h"
#include "geometry/ray_3d.h"

namespace epure::kinds {

namespace {

using geo::Point3;
using geo::Vec3;
using method::AnswerType;
using method::Names3;

struct Data {
  Point3 A;
  Vec3 u;
  Point3 C;
  double r;
};

// Directions of integer length: û and t_proj rational at the easy level (signs and the order of
// the components drawn on top).
constexpr Vec3 kEasyDirections[] = {{1, 0, 0}, {2, 0, 0}, {3, 4, 0}, {1, 2, 2}, {2, 3, 6}, {2, 1, 2}, {4, 4, 2}};

constexpr Names3 kAC = {"AC.x", "AC.y", "AC.z"}, kUh = {"u_hat.x", "u_hat.y", "u_hat.z"},
                 kP = {"P.x", "P.y", "P.z"}, kI = {"I.x", "I.y", "I.z"}, kN = {"N.x", "N.y", "N.z"};
constexpr std::string_view kReasons[] = {"behind", "miss"};

// The direction (below the horizontal, in radians) of the radius drawn in the 3D view.
constexpr double kRadiusAngle = 0.6;

geo::RaySphere solve_core(const Data& d) { return geo::intersect(geo::Ray3::unit(d.A, d.u), geo::Sphere{d.C, d.r}); }

std::string branch_of(const geo::RaySphere& rs) {
  if (rs.inside) return "inside";
  if (rs.hit) return "hit";
  return geo::to_string(*rs.reason);
}

struct RaySphereMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "ray_sphere";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("u", d.u);
    v("C", d.C);
    v("r", d.r);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"t_proj", AnswerType::number}, {"d2", AnswerType::number},  {"inside", AnswerType::boolean},
      {"hit", AnswerType::boolean},   {"t", AnswerType::number},   {"I.x", AnswerType::number, 0.5},
      {"I.y", AnswerType::number, 0.5}, {"I.z", AnswerType::number, 0.5}, {"N.x", AnswerType::number, 0.5},
      {"N.y", AnswerType::number, 0.5}, {"N.z", AnswerType::number, 0.5},
      {"reason", AnswerType::choice, 1, kReasons}};
  static constexpr std::string_view kRoads[] = {"pythagoras_apc"};
  static constexpr double kPoints = 8;
  static constexpr std::string_view kMistakes[] = {"direction_not_unit", "far_intersection", "near_root_inside",
                                                   "normal_not_unit", "normal_inward"};

  // As the circle: û, t_proj = û·AC, P = A + t_proj·û, d² = CP², Pythagoras, t = t_proj ∓ √(r² − d²),
  // I = A + t·û, N = (I − C)/r; every coordinate in space.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using method::less_equal;
    const auto A = m.in(d.A), C = m.in(d.C), u = m.in(d.u);
    const auto r = m.in(d.r), zero = m.in(0.0), one = m.in(1.0);
    const auto AC = m.note(kAC, C - A);
    const auto ac2 = m.note("ac2", norm2(AC));
    const auto r2 = m.note("r2", r * r);
    const auto inside = m.boolean("inside", less(ac2, r2));
    const auto n = dot(u, u);
    const auto length = m.note("norm_u", sqrt(n));
    const auto uh = m.round(kUh, m.mistake("direction_not_unit", u / length, u));
    const auto t_proj = m.number("t_proj", m.round("t_proj", dot(uh, AC)));
    const auto P = m.round(kP, A + t_proj * uh);
    const auto d2 = m.number("d2", m.round("d2", m.road("pythagoras_apc", norm2(P - C), ac2 - t_proj * t_proj)));
    const auto ahead = !less(t_proj, zero);
    const auto hit = m.boolean("hit", inside || (ahead && less_equal(d2, r2)));
    if (!hit) {
      m.choice("reason", method::pick(ahead, "miss", "behind"));
      return;
    }
    const auto h2 = r2 - d2;
    const auto h = m.round("h", sqrt(h2));
    const auto t = m.number("t", m.round("t", inside ? m.mistake("near_root_inside", t_proj + h, t_proj - h)
                                                     : m.mistake("far_intersection", t_proj - h, t_proj + h)));
    const auto along = (inside ? one : -one) * sqrt(h2 / n);
    const auto I = m.point(kI, m.round(kI, m.either(A + t * uh, P + along * u)));
    const auto IC = I - C;
    m.point(kN, m.mistake("normal_inward", m.mistake("normal_not_unit", IC / r, IC), -(IC / r)));
  }

  static CoreAnswers core(const Data& d) {
    const auto rs = solve_core(d);
    CoreAnswers a;
    a.number("t_proj", rs.t_proj).number("d2", rs.d2).boolean("inside", rs.inside).boolean("hit", rs.hit.has_value());
    if (rs.hit) a.number("t", rs.hit->t).point(kI, rs.hit->I).vec(kN, rs.hit->N);
    else a.choice("reason", geo::to_string(*rs.reason));
    return a;
  }
};

class RaySphereKind final : public MethodKind<RaySphereMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 3}, {"behind", 1}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override {
    return {{"tangent_margin", 0.15}, {"boundary_margin", 0.15}, {"t_proj_margin", 0.5}, {"t_min", 1.0},
            {"min_offset", 0.25},     {"min_radius", 2.0},       {"max_radius", 3.0}};
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
    if (!(r_lo > 0 && r_lo <= r_hi && r_hi <= 4))
      throw std::runtime_error("ray_sphere: need 0 < min_radius ≤ max_radius ≤ 4");
    const double tm_clear = hard ? tm / 4 : tm, bm_clear = hard ? bm / 3 : bm;
    // widened (a large set has used up the usual ranges): A and C further out
    const double w = 2 * ctx.widening;

    auto accept = [&](const Data& x) {
      const auto rs = solve_core(x);
      if (branch_of(rs) != ctx.branch) return false;
      const double ac = geo::norm(rs.AC) / x.r;
      const double dr = std::sqrt(rs.d2) / x.r;
      if (std::abs(rs.P.x) > 7 + w || std::abs(rs.P.y) > 7 + w || rs.P.z < -3 - w || rs.P.z > 8 + w) return false;
      if (dr < min_offset) return false;
      if (rs.inside) {
        if (ac > 1 - bm_clear || rs.hit->t < t_min) return false;
        return !hard || ac >= 1 - bm;
      }
      if (ac < 1 + bm_clear || std::abs(dr - 1) < tm_clear) return false;
      const bool near_tangent = std::abs(dr - 1) <= tm, near_sphere = ac <= 1 + bm;
      if (ctx.branch == "behind") return rs.t_proj <= -tpm && (!hard || near_tangent || near_sphere);
      if (rs.t_proj < tpm) return false;
      if (ctx.branch == "miss") return !hard || near_tangent;
      return rs.hit->t >= t_min && (!hard || near_tangent || near_sphere);
    };
    // easy: r² − d² the square of a rational
    auto pythagorean = [&](const Data& x) {
      if (level != Difficulty::easy || ctx.branch == "behind" || ctx.branch == "miss") return true;
      const auto run = exact_run(x);
      const auto* h = run.step("h");
      return h && h->x.e && h->x.e->is_rational();
    };

    const Data d = draw_until(200000, "ray_sphere (branch, tangency and boundary margins, t range)",
                              [&]() -> std::optional<Data> {
      Data x;
      x.r = grid_value(rng, r_lo, r_hi, level);
      x.C = {grid_value(rng, -3 - w, 3 + w, level), grid_value(rng, -3 - w, 3 + w, level), grid_value(rng, 0, 3 + w, level)};
      x.A = {grid_value(rng, -6 - w, 6 + w, level), grid_value(rng, -6 - w, 6 + w, level), grid_value(rng, -1 - w, 6 + w, level)};
      if (level == Difficulty::easy) {
        Vec3 e = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
        double c[3] = {e.x, e.y, e.z};
        // a random order of the components, then random signs
        for (int i = 2; i > 0; --i) std::swap(c[i], c[rng.integer(0, i)]);
        for (double& k : c)
          if (rng.chance(0.5)) k = -k;
        x.u = {c[0], c[1], c[2]};
      } else {
        const double m = hard ? 3 : 4;
        x.u = {grid_value(rng, -m, m, level), grid_value(rng, -m, m, level), grid_value(rng, -m, m, level)};
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
    const auto rs = solve_core(d);
    const std::string branch = branch_of(rs);

    ExerciseInstance inst = begin_instance(d, ctx);
    KeySolution key = solve(d, ctx);
    const Questions& q = key.questions;
    inst.questions = key.questions.take_questions();
    auto value = [&](std::string_view id) { return step_value(ctx, key.value(id), key.exact(id)); };
    auto point = [&](const Names3& ids) { return space::step_point3(ctx, key, ids); };

    const TextVars data_vars = {{"A", N.point(d.A.x, d.A.y, d.A.z)},
                                {"u", N.point(d.u.x, d.u.y, d.u.z)},
                                {"C", N.point(d.C.x, d.C.y, d.C.z)},
                                {"r", N.datum(d.r)}};
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      inst.sheet = begin_sheet_section(ctx, "ray_sphere.title");
      inst.sheet.add(render::Paragraph{T.format("ray_sphere.statement", data_vars)});
      inst.sheet.add(render::Figure{question_scene(d, rs, ctx), 0.5});
      add_fields(inst.sheet, q);
    }

    inst.key = begin_key_section(ctx, "ray_sphere.title");
    inst.key.add(render::Paragraph{T.format("ray_sphere.data", data_vars)});
    auto step = [&](std::string_view id, const TextVars& vars = {}) {
      inst.key.add(render::Paragraph{T.format(fmt::format("ray_sphere.step.{}", id), vars)});
    };
    const std::string r2 = value("r2"), d2 = value("d2");
    step("AC", {{"AC", N.point(rs.AC.x, rs.AC.y, rs.AC.z)}, {"ac2", value("ac2")}, {"r2", r2}});
    step(rs.inside ? "inside.yes" : "inside.no");
    step("unit", {{"norm_u", value("norm_u")}, {"u_hat", point(kUh)}});
    step("t_proj", {{"t_proj", value("t_proj")}});
    if (rs.inside) step("ahead.inside");
    else if (branch == "behind") step("behind");
    else step("ahead.outside");
    step("P", {{"P", point(kP)}});
    step("d2", {{"d2", d2}});
    if (branch == "miss") {
      step("miss", {{"d2", d2}, {"r2", r2}});
    } else if (branch != "behind") {
      step("pythagoras", {{"d2", d2}, {"r2", r2}, {"h", value("h")}});
      step(rs.inside ? "t.inside" : "t.outside", {{"t", value("t")}});
      step("I", {{"I", point(kI)}});
      step("N", {{"N", point(kN)}});
    }
    step("plane");
    inst.key.add(render::Figure{key_scene(d, rs, branch, ctx), 0.95});
    add_lines(inst.key, q);
    return inst;
  }

  // The 3D view with the data: the sphere's outline, the ray (dashed where the sphere hides it),
  // A and C.
  static render::Panel view(const Data& d, const geo::RaySphere& rs, const render::Camera& cam, bool key) {
    using render::Role;
    using space::p3;
    const Vec3 uh = d.u / geo::norm(d.u);
    const double reach = std::max(rs.t_proj, 0.0) + d.r + 2;
    const Point3 end = d.A + reach * uh;
    std::vector<render::P3> pts = {p3(d.A), p3(end), p3(d.C + Vec3{d.r, d.r, d.r}), p3(d.C + Vec3{-d.r, -d.r, -d.r})};
    if (key) pts.push_back(p3(rs.P));
    const render::Ball ball{p3(d.C), d.r};
    render::Panel panel = space::view_panel(cam, pts, 4, 1.5, ball);
    // the sphere's outline: the circle of radius r around C's projection, inside the view
    const render::P2 c = cam.project(p3(d.C));
    panel.view.x_min = std::min(panel.view.x_min, std::floor(c.x - d.r - 0.5));
    panel.view.x_max = std::max(panel.view.x_max, std::ceil(c.x + d.r + 0.5));
    panel.view.y_min = std::min(panel.view.y_min, std::floor(c.y - d.r - 0.5));
    panel.view.y_max = std::max(panel.view.y_max, std::ceil(c.y + d.r + 0.5));
    space::add_drop(panel, cam, p3(d.A));
    space::add_drop(panel, cam, p3(d.C));
    panel.add(render::Circle{cam.project(p3(d.C)), d.r, Role::data});
    // a radius parallel to the picture, hence in true size: the figure's scale
    const render::P2 rim{c.x + d.r * std::cos(-kRadiusAngle), c.y + d.r * std::sin(-kRadiusAngle)};
    panel.add(render::Segment{c, rim, Role::construction, false});
    panel.add(render::Label{"r", {(c.x + rim.x) / 2, (c.y + rim.y) / 2}, render::Side::auto_, Role::construction});
    if (key) render::add_segment(panel, cam, p3(rs.P), p3(d.C), Role::construction, ball);
    // behind: the ray's line back to P, which lies before A
    if (key && rs.t_proj < 0) render::add_segment(panel, cam, p3(rs.P), p3(d.A), Role::construction, ball);
    render::add_segment(panel, cam, p3(d.A), p3(end), Role::data, ball);
    panel.add(render::Arrow{cam.project(p3(d.A)), cam.project(p3(d.A + uh)), Role::construction});
    panel.add(render::Label{"û", cam.project(p3(d.A + uh)), render::Side::auto_, Role::construction});
    panel.add(render::PointMark{cam.project(p3(d.C)), Role::data, render::Label{"C", cam.project(p3(d.C))}});
    panel.add(render::PointMark{cam.project(p3(d.A)), Role::data, render::Label{"A", cam.project(p3(d.A))}});
    return panel;
  }

  render::Scene question_scene(const Data& d, const geo::RaySphere& rs, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("ray_sphere.title");
    s.description = ctx.texts.get("ray_sphere.figure.question");
    render::Panel panel = view(d, rs, space::camera(), false);
    panel.caption = ctx.texts.get("ray_sphere.figure.view");
    s.panels.push_back(std::move(panel));
    return s;
  }

  render::Scene key_scene(const Data& d, const geo::RaySphere& rs, const std::string& branch,
                          const ExerciseContext& ctx) const {
    using render::P2;
    using render::Role;
    using space::p3;
    const auto& T = ctx.texts;
    const render::Camera cam = space::camera();
    render::Scene s;
    s.title = T.get("ray_sphere.title");
    s.description = T.get(fmt::format("ray_sphere.figure.key.{}", branch));
    render::Panel v3 = view(d, rs, cam, true);
    v3.add(render::PointMark{cam.project(p3(rs.P)), Role::construction,
                             render::Label{"P", cam.project(p3(rs.P)), render::Side::auto_, Role::construction}});
    if (rs.hit) {
      const P2 I = cam.project(p3(rs.hit->I));
      v3.add(render::PointMark{I, Role::result, render::Label{"I", I, render::Side::auto_, Role::result}});
      const P2 tip = cam.project(p3(rs.hit->I + rs.hit->N));
      v3.add(render::Arrow{I, tip, Role::normal});
      v3.add(render::Label{T.get("ray_sphere.figure.N"), tip, render::Side::auto_, Role::normal});
    }
    v3.caption = T.get("ray_sphere.figure.view");
    s.panels.push_back(std::move(v3));

    // The plane of the ray and C in true size: A at the origin, û along the first axis, C above
    // it at the height d (the core's t_proj and d²).
    const double dd = std::sqrt(rs.d2);
    const P2 A{0, 0}, C{rs.t_proj, dd}, P{rs.t_proj, 0};
    render::Panel plane;
    std::vector<P2> pts = {A, {1, 0}, {C.x - d.r, C.y - d.r}, {C.x + d.r, C.y + d.r}, P};
    plane.view = view_around(pts, 1.0, 5.0);
    plane.add(render::Grid{1, false});
    auto outward = [](P2 a, P2 b, P2 c) {
      return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0 ? -0.35 : 0.35;
    };
    plane.add(render::Line{A, {1, 0}, Role::construction});
    std::optional<P2> I;
    if (rs.hit) {
      I = P2{rs.hit->t, 0};
      plane.add(render::Polygon{{C, P, *I}, true, Role::construction, true});
    }
    plane.add(render::Circle{C, d.r, Role::data});
    plane.add(render::Ray{A, {1, 0}, Role::data});
    plane.add(render::Segment{C, P, Role::construction, true});
    plane.add(render::RightAngle{P, {0, 1}, {1, 0}, Role::construction});
    if (I) {
      plane.add(render::Dimension{C, P, T.get("ray_sphere.figure.d"), outward(C, P, *I), Role::construction});
      plane.add(render::Dimension{P, *I, T.get("ray_sphere.figure.h"), outward(P, *I, C), Role::construction});
      plane.add(render::Dimension{*I, C, T.get("ray_sphere.figure.r"), outward(*I, C, P), Role::construction});
    } else if (branch == "miss") {
      const P2 R{C.x, C.y - d.r};
      plane.add(render::Segment{C, R, Role::construction});
      plane.add(render::Dimension{C, P, T.get("ray_sphere.figure.d"), 0.35, Role::construction});
      plane.add(render::Dimension{C, R, T.get("ray_sphere.figure.r"), -0.35, Role::construction});
    } else {
      plane.add(render::Tick{A, {1, 0}, std::string("0"), Role::construction});
      plane.add(render::Tick{P, {1, 0}, T.get("ray_sphere.figure.t_proj_negative"), Role::construction});
    }
    plane.add(render::PointMark{C, Role::data, render::Label{"C", C}});
    plane.add(render::PointMark{A, Role::data, render::Label{"A", A}});
    plane.add(render::PointMark{P, Role::construction, render::Label{"P", P, render::Side::auto_, Role::construction}});
    if (I) {
      plane.add(render::PointMark{*I, Role::result, render::Label{"I", *I, render::Side::auto_, Role::result}});
      const P2 tip{I->x + (I->x - C.x) / d.r, I->y + (I->y - C.y) / d.r};
      plane.add(render::Arrow{*I, tip, Role::normal});
      plane.add(render::Label{T.get("ray_sphere.figure.N"), tip, render::Side::auto_, Role::normal});
    }
    plane.caption = T.get("ray_sphere.figure.plane");
    s.panels.push_back(std::move(plane));
    s.links = {T.get("ray_sphere.figure.link")};
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_sphere_kind() {
  static const RaySphereKind kind;
  return kind;
}

}  // namespace epure::kinds
