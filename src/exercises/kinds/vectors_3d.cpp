// The course's preamble in space ("dans le repère canonique de ℝ³"): u·v, the cross product
// u∧v as a vector, the norms, cos θ = u·v/(‖u‖‖v‖), sin θ = ‖u∧v‖/(‖u‖‖v‖) and the unsigned
// angle θ in [0°, 180°]; then what the two products say: collinear (u∧v = 0), orthogonal
// (u·v = 0). The solve contract's `vectors` with three components.
//
// Branches: general, orthogonal, collinear.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "support/agrees.h"
#include "exercises/kind_method.h"
#include "exercises/kinds/space_common.h"
#include "geometry/vectors.h"

namespace epure::kinds {

namespace {

using geo::Vec3;

struct Data {
  Vec3 u, v;
};

using method::AnswerType;
constexpr method::Names3 kCross = {"cross.x", "cross.y", "cross.z"};

// The student's method decides on its rounded sine and cosine: collinear or orthogonal when
// they are zero up to this (the core decides exactly, vectors.h). Data on a one-decimal grid
// within ±10 that are not collinear have sin θ ≥ 0.01/300 (u∧v has hundredths, ‖u‖‖v‖ ≤ 300),
// far above it, and the method's exact evaluator gets exactly zero for collinear data.
constexpr double kCollinearSin = 1e-12;

// The core's comparison of the data: the values of their doubles (the key's numbers, as they
// were), the decisions exact on the decimals the sheet prints (collinear or orthogonal as written,
// whatever the doubles: vectors.h).
geo::VectorPair3 compared(const Data& d) {
  geo::VectorPair3 r = geo::compare_vectors_3d(d.u, d.v);
  const geo::VectorPair3 written = geo::compare_decimal_vectors_3d(geo::written_point(d.u), geo::written_point(d.v));
  r.collinear = written.collinear;
  r.orthogonal = written.orthogonal;
  return r;
}

// A factor of a product as the key writes it: negative numbers in parentheses.
std::string factor(const NumberStyle& n, double x) { return x < 0 ? fmt::format("({})", n.datum(x)) : n.datum(x); }

struct Vectors3dMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "vectors_3d";
  static constexpr std::string_view kSolveKind = "vectors";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("u", d.u);
    v("v", d.v);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"dot", AnswerType::number},        {"cross.x", AnswerType::number},   {"cross.y", AnswerType::number},
      {"cross.z", AnswerType::number},    {"norm_u", AnswerType::number},    {"norm_v", AnswerType::number},
      {"cos", AnswerType::number},        {"sin", AnswerType::number},       {"angle_deg", AnswerType::number},
      {"collinear", AnswerType::boolean}, {"orthogonal", AnswerType::boolean}};

  static constexpr double kPoints = 9;

  // the middle component's sign first: a whole cross_sign mistake gets that component wrong the
  // same way, and is named on the first one (x) anyway
  static constexpr std::string_view kMistakes[] = {"cross_middle_sign", "cross_sign", "norm_not_rooted",
                                                   "angle_radians"};

  // By hand: u·v; u∧v component by component (the middle one is z_u x_v − x_u z_v); the norms;
  // cos and sin by dividing by ‖u‖‖v‖ (sin from the norm of u∧v, so sin ≥ 0); θ from both.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less_equal;
    const auto u = m.in(d.u), v = m.in(d.v);
    const auto uv = m.number("dot", m.round("dot", dot(u, v)));
    const auto right = cross(u, v);
    const method::V3<typename M::Number> middle_wrong{right.x, -right.y, right.z};
    const auto w = m.point(kCross, m.round(kCross, m.mistake("cross_middle_sign",
                                                             m.mistake("cross_sign", right, cross(v, u)),
                                                             middle_wrong)));
    const auto nu = m.number("norm_u", m.round("norm_u", m.mistake("norm_not_rooted", norm(u), norm2(u))));
    const auto nv = m.number("norm_v", m.round("norm_v", m.mistake("norm_not_rooted", norm(v), norm2(v))));
    const auto nn = nu * nv;
    const auto c = m.number("cos", m.round("cos", uv / nn));
    const auto nw = m.round("norm_cross", norm(w));
    const auto s = m.number("sin", m.round("sin", nw / nn));
    const auto theta = method::atan2_degrees(s, c);
    m.number("angle_deg", m.mistake("angle_radians", theta, theta * m.in(std::numbers::pi / 180)));
    const auto eps = m.in(kCollinearSin);
    m.boolean("collinear", less_equal(s, eps));
    m.boolean("orthogonal", less_equal(method::magnitude(c), eps));
  }

  // the solve contract (solve/solve.h): `vectors` with three components
  static void contract(const Data&, const solve::Fields& f, solve::Result& r) {
    const auto w = geo::compare_decimal_vectors_3d(f.dpoint3("u"), f.dpoint3("v"));
    r.number("dot", w.dot).point("cross", w.cross).number("norm_u", w.norm_u).number("norm_v", w.norm_v);
    r.number("cos", w.cos).number("sin", w.sin).number("angle_deg", w.angle_deg);
    r.boolean("collinear", w.collinear).boolean("orthogonal", w.orthogonal);
  }

  static CoreAnswers core(const Data& d) {
    const auto r = compared(d);
    CoreAnswers a;
    a.number("dot", r.dot).vec(kCross, r.cross).number("norm_u", r.norm_u).number("norm_v", r.norm_v);
    a.number("cos", r.cos).number("sin", r.sin).number("angle_deg", r.angle_deg);
    a.boolean("collinear", r.collinear).boolean("orthogonal", r.orthogonal);
    return a;
  }
};

std::string branch_of(const geo::VectorPair3& r) {
  if (r.collinear) return "collinear";
  if (r.orthogonal) return "orthogonal";
  return "general";
}

class Vectors3d final : public MethodKind<Vectors3dMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"general", 2}, {"orthogonal", 1}, {"collinear", 1}};
  }
  std::map<std::string, double> default_constraints() const override {
    // θ at least min_angle_deg from 0° and 180° and, when not right, from 90° by right_margin_deg;
    // norms at least min_norm, components within ±max_component.
    return {{"min_angle_deg", 20.0}, {"right_margin_deg", 10.0}, {"min_norm", 2.0}, {"max_component", 5.0}};
  }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const std::string& branch = ctx.branch;
    if (branch != "general" && branch != "orthogonal" && branch != "collinear")
      throw std::invalid_argument(fmt::format("vectors_3d: no branch '{}'", branch));
    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    const double min_angle = constraint(ctx, *this, "min_angle_deg") / (hard ? 2 : 1);
    const double right_margin = constraint(ctx, *this, "right_margin_deg") / (hard ? 2 : 1);
    const double min_norm = constraint(ctx, *this, "min_norm");
    // widened (a large set has used up the usual ranges): longer components
    const double max_c = constraint(ctx, *this, "max_component") + 2 * ctx.widening;
    const int per_unit = hard ? 10 : 1;
    auto grid = [&]() { return grid_value(rng, -max_c, max_c, level); };
    auto fits = [&](Vec3 w) { return std::abs(w.x) <= max_c && std::abs(w.y) <= max_c && std::abs(w.z) <= max_c; };
    auto whole_norm = [](Vec3 w) { return is_whole(geo::norm(w)); };

    const Data d = draw_until(200000, "vectors_3d (angle, norms, components)", [&]() -> std::optional<Data> {
      Data x;
      x.u = {grid(), grid(), grid()};
      if (geo::norm(x.u) < min_norm) return std::nullopt;
      const std::int64_t U[3] = {std::llround(x.u.x * per_unit), std::llround(x.u.y * per_unit),
                                 std::llround(x.u.z * per_unit)};
      if (branch == "collinear") {
        // v = m·(u / gcd) on the grid, m ≠ 0
        const std::int64_t g = std::gcd(std::gcd(U[0], U[1]), U[2]);
        const std::int64_t m = rng.integer(1, 4) * (rng.chance(0.5) ? -1 : 1);
        x.v = {double(m * U[0] / g) / per_unit, double(m * U[1] / g) / per_unit, double(m * U[2] / g) / per_unit};
        if (m == g) return std::nullopt;  // v = u: one arrow over the other
      } else if (branch == "orthogonal") {
        // v = u∧w / gcd for a small integer w: on the grid and orthogonal to u exactly
        const std::int64_t W[3] = {rng.integer(-2, 2), rng.integer(-2, 2), rng.integer(-2, 2)};
        std::int64_t p[3] = {U[1] * W[2] - U[2] * W[1], U[2] * W[0] - U[0] * W[2], U[0] * W[1] - U[1] * W[0]};
        const std::int64_t g = std::gcd(std::gcd(p[0], p[1]), p[2]);
        if (g == 0) return std::nullopt;
        x.v = {double(p[0] / g) / per_unit, double(p[1] / g) / per_unit, double(p[2] / g) / per_unit};
        if (hard && rng.chance(0.5)) x.v = {x.v.x * 2, x.v.y * 2, x.v.z * 2};
      } else {
        x.v = {grid(), grid(), grid()};
      }
      if (!fits(x.v) || geo::norm(x.v) < min_norm) return std::nullopt;
      if (level == Difficulty::easy && !(whole_norm(x.u) && whole_norm(x.v))) return std::nullopt;
      if (level == Difficulty::standard && whole_norm(x.u) && whole_norm(x.v)) return std::nullopt;
      const auto r = compared(x);
      if (branch_of(r) != branch) return std::nullopt;
      if (branch == "general") {
        if (r.angle_deg < min_angle || r.angle_deg > 180 - min_angle) return std::nullopt;
        if (std::abs(r.angle_deg - 90) < right_margin) return std::nullopt;
      }
      return x;
    });
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto r = compared(d);
    const std::string branch = branch_of(r);

    const auto sheet_figure = [&](const KeySolution&) { return render::Figure{scene(d, r, ctx, false), 0.8}; };
    Begun begun = begin_sections(d, ctx, sheet_figure);
    ExerciseInstance& inst = begun.inst;
    const KeySolution& key = begun.key;
    const Questions& q = key.questions;

    const TextVars f = {{"ux", factor(N, d.u.x)}, {"uy", factor(N, d.u.y)}, {"uz", factor(N, d.u.z)},
                        {"vx", factor(N, d.v.x)}, {"vy", factor(N, d.v.y)}, {"vz", factor(N, d.v.z)}};
    auto with = [&](TextVars vars, TextVars more) {
      vars.insert(vars.end(), more.begin(), more.end());
      return vars;
    };
    auto step = [&](std::string_view id, const TextVars& vars) {
      inst.key.add(render::Paragraph{T.format(fmt::format("vectors_3d.step.{}", id), vars)});
    };
    step("dot", with(f, {{"dot", N.datum(r.dot)}}));
    step("cross", with(f, {{"cx", N.datum(r.cross.x)}, {"cy", N.datum(r.cross.y)}, {"cz", N.datum(r.cross.z)},
                           {"cross", N.point(r.cross.x, r.cross.y, r.cross.z)}}));
    step("norms", {{"nu2", N.datum(geo::norm2(d.u))},
                   {"norm_u", equals_value(ctx, r.norm_u, key.exact("norm_u"))},
                   {"nv2", N.datum(geo::norm2(d.v))},
                   {"norm_v", equals_value(ctx, r.norm_v, key.exact("norm_v"))}});
    step("cos", {{"cos", equals_value(ctx, r.cos, key.exact("cos"))}});
    step("sin", {{"nw2", N.datum(geo::norm2(r.cross))},
                 {"norm_cross", equals_value(ctx, key.value("norm_cross"), key.exact("norm_cross"))},
                 {"sin", equals_value(ctx, r.sin, key.exact("sin"))}});
    step("angle", {{"angle", equals_value(ctx, r.angle_deg, key.exact("angle_deg"))}});
    step(branch, {});
    inst.key.add(render::Figure{scene(d, r, ctx, true), 1.0});
    add_lines(inst.key, q);
    return std::move(inst);
  }

  // The axonometric view: u and v from the origin, u∧v to its direction (two units long).
  static render::Panel space_view(const Data& d, const geo::VectorPair3& r, const ExerciseContext& ctx) {
    using render::Role;
    using space::p3;
    const auto& T = ctx.texts;
    const render::Camera cam = space::camera();
    const double nw = geo::norm(r.cross);
    const geo::Vec3 w = nw > 0 ? (2.0 / nw) * r.cross : geo::Vec3{};
    std::vector<render::P3> pts = {{0, 0, 0}, p3(d.u), p3(d.v)};
    if (nw > 0) pts.push_back(p3(w));
    render::Panel panel = space::view_panel(cam, pts, 5, 1.5);
    space::add_drop(panel, cam, p3(d.u));
    space::add_drop(panel, cam, p3(d.v));
    const render::P2 o = cam.project({0, 0, 0});
    panel.add(render::Arrow{o, cam.project(p3(d.u)), Role::data});
    panel.add(render::Arrow{o, cam.project(p3(d.v)), Role::data});
    if (nw > 0) {
      panel.add(render::Arrow{o, cam.project(p3(w)), Role::result});
      panel.add(render::Label{T.get("vectors_3d.figure.cross"), cam.project(p3(w)), render::Side::auto_, Role::result});
    }
    panel.add(render::Label{"\\vec{u}", cam.project(p3(d.u))});
    panel.add(render::Label{"\\vec{v}", cam.project(p3(d.v))});
    panel.caption = T.get("vectors_3d.figure.caption");
    return panel;
  }

  // An épure, as the course's field draws space on paper: two orthographic views side by side,
  // the front view (elevation: x across, z up) and the top view (plan: x across, y up), each over
  // a unit grid, so that every component is read in true size and lengths can be compared (an
  // axonometric view foreshortens: u of length 5.4 came out shorter than v of length 3). On the
  // key, the direction of u∧v too, two units long.
  render::Scene scene(const Data& d, const geo::VectorPair3& r, const ExerciseContext& ctx, bool key) const {
    using render::Role;
    const auto& T = ctx.texts;
    render::Scene s;
    s.title = T.get("vectors_3d.title");
    s.description = T.get(key ? "vectors_3d.figure.key" : "vectors_3d.figure.question");
    const double nw = geo::norm(r.cross);
    struct Drawn {
      geo::Vec3 v;
      std::string label;
      Role role;
    };
    std::vector<Drawn> vectors = {{d.u, "\\vec{u}", Role::data}, {d.v, "\\vec{v}", Role::data}};
    if (key && nw > 0) vectors.push_back({(2.0 / nw) * r.cross, T.get("vectors_3d.figure.cross"), Role::result});
    // the view's two axes: 0 = x, 1 = y, 2 = z
    auto view = [&](int across, int up, const char* across_name, const char* up_name, const std::string& caption) {
      auto component = [](const geo::Vec3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; };
      auto in_view = [&](const geo::Vec3& v) { return render::P2{component(v, across), component(v, up)}; };
      std::vector<render::P2> pts = {{0, 0}, {1, 1}};
      for (const auto& w : vectors) pts.push_back(in_view(w.v));
      render::Panel panel;
      panel.view = view_around(pts, 1.0, 5.0);
      panel.add(render::Grid{1, true});
      for (const auto& w : vectors) {
        const render::P2 tip = in_view(w.v);
        // a vector seen end on is a point in this view: marked, not drawn as an arrow
        if (std::hypot(tip.x, tip.y) < 1e-9) continue;
        panel.add(render::Arrow{{0, 0}, tip, w.role});
      }
      for (const auto& w : vectors) {
        const render::P2 tip = in_view(w.v);
        panel.add(render::Label{w.label, tip, render::Side::auto_, w.role});
      }
      // the axes' names at their positive ends, inside the view
      panel.add(render::Label{across_name, {panel.view.x_max - 0.3, 0}, render::Side::auto_, Role::muted});
      panel.add(render::Label{up_name, {0, panel.view.y_max - 0.3}, render::Side::auto_, Role::muted});
      panel.caption = caption;
      return panel;
    };
    // The key opens with the view in space (the explorer's handles and drags are set on its
    // camera); the sheet has the two views only.
    if (key) s.panels.push_back(space_view(d, r, ctx));
    s.panels.push_back(view(0, 2, "x", "z", T.get("vectors_3d.figure.front")));
    s.panels.push_back(view(0, 1, "x", "y", T.get("vectors_3d.figure.top")));
    return s;
  }
};

}  // namespace

const ExerciseKind& vectors_3d_kind() { return the_kind<Vectors3d>(); }

}  // namespace epure::kinds
