// The course's preamble: what u·v and u∧v say about two vectors — their norms, the cosine and
// sine of the signed angle θ from u to v, and θ itself, read with atan2 so that its sign (the
// orientation, from u∧v) comes out with it.
//
// Branches are the sign of u·v (acute / right / obtuse): that is what the course stresses
// (u·v = 0 ⇔ orthogonal), and each branch reads differently in the key. The orientation (the
// sign of u∧v) is left to chance, so a class set sees both turns within every branch.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "support/agrees.h"
#include "exercises/kind_method.h"
#include "geometry/vectors.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::Vec2;

struct Data {
  Vec2 u, v;
};

// A right angle on the grid is exact in the data; its cosine is zero up to the rounding of the
// one-decimal data in binary (about 1e-16), far below this.
constexpr double kRightAngleCos = 1e-12;

// Integer vectors of integer length (Pythagorean triples and the axes): the easy level's
// norms are whole, and cos and sin rational.
std::vector<Vec2> integer_norm_vectors(double max_component, double min_norm) {
  std::vector<Vec2> out;
  const auto m = static_cast<std::int64_t>(std::floor(max_component));
  for (std::int64_t x = -m; x <= m; ++x)
    for (std::int64_t y = -m; y <= m; ++y) {
      const std::int64_t n2 = x * x + y * y;
      const auto n = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(n2))));
      if (n * n == n2 && static_cast<double>(n) >= min_norm)
        out.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
  return out;
}

// k·w for a random k ≠ 0, with w the shortest grid vector along perp(u): perp(u) in grid steps,
// divided by the gcd of its components. `per_unit` grid steps make one unit (1, or 10 for the
// one-decimal grid).
std::optional<Vec2> perpendicular_on_grid(Vec2 u, int per_unit, double max_component, Rng& rng) {
  const std::int64_t ux = std::llround(u.x * per_unit), uy = std::llround(u.y * per_unit);
  const std::int64_t g = std::gcd(ux, uy);
  if (g == 0) return std::nullopt;
  const std::int64_t wx = -uy / g, wy = ux / g;
  const auto k_max = static_cast<std::int64_t>(
      std::floor(max_component * per_unit / static_cast<double>(std::max(std::abs(wx), std::abs(wy)))));
  if (k_max < 1) return std::nullopt;
  const std::int64_t k = rng.integer(1, k_max) * (rng.chance(0.5) ? -1 : 1);
  // divided (not multiplied by 0.1) so that the coordinates are the doubles grid_value gives
  return Vec2{static_cast<double>(k * wx) / per_unit, static_cast<double>(k * wy) / per_unit};
}

// A factor of a product as the key writes it: negative numbers in parentheses.
std::string factor(const NumberStyle& n, double x) {
  return x < 0 ? fmt::format("({})", n.datum(x)) : n.datum(x);
}

using method::AnswerType;

// The course's preamble, written once (method.h).
struct VectorsMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "vectors";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("u", d.u);
    v("v", d.v);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"dot", AnswerType::number},    {"cross", AnswerType::number}, {"norm_u", AnswerType::number},
      {"norm_v", AnswerType::number}, {"cos", AnswerType::number},   {"sin", AnswerType::number},
      {"angle_deg", AnswerType::number}};

  // what the exercise adds to the sheet's total when the spec does not set its points (points.h:
  // the sheet's questions share that total by their work)
  static constexpr double kPoints = 7;

  static constexpr std::string_view kMistakes[] = {"norm_not_rooted", "angle_unsigned", "cross_sign", "angle_radians"};

  // The student's hand method, in the course's order: u·v, u∧v, ‖u‖, ‖v‖, then cos and sin by
  // dividing by ‖u‖‖v‖, then θ = atan2(sin, cos), each rounded unless it stops within the
  // asked decimals.
  template <class M>
  static void method(M& m, const Data& d) {
    const auto u = m.in(d.u), v = m.in(d.v);
    const auto uv = m.number("dot", m.round("dot", dot(u, v)));
    const auto uxv = m.number("cross", m.round("cross", m.mistake("cross_sign", cross(u, v), cross(v, u))));
    const auto nu = m.number("norm_u", m.round("norm_u", m.mistake("norm_not_rooted", norm(u), norm2(u))));
    const auto nv = m.number("norm_v", m.round("norm_v", m.mistake("norm_not_rooted", norm(v), norm2(v))));
    const auto nn = nu * nv;
    const auto c = m.number("cos", m.round("cos", uv / nn));
    const auto s = m.number("sin", m.round("sin", uxv / nn));
    const auto theta = method::atan2_degrees(s, c);
    const auto radians = theta * m.in(std::numbers::pi / 180);
    m.number("angle_deg", m.mistake("angle_radians", m.mistake("angle_unsigned", theta, method::magnitude(theta)), radians));
  }

  // the solve contract (solve/solve.h)
  static void contract(const Data&, const solve::Fields& f, solve::Result& r) {
    const auto v = geo::compare_decimal_vectors(f.dpoint2("u"), f.dpoint2("v"));
    r.number("dot", v.dot).number("cross", v.cross).number("norm_u", v.norm_u).number("norm_v", v.norm_v);
    r.number("cos", v.cos).number("sin", v.sin).number("angle_deg", v.angle_deg);
  }

  static CoreAnswers core(const Data& d) {
    const auto r = geo::compare_vectors(d.u, d.v);
    CoreAnswers a;
    a.number("dot", r.dot).number("cross", r.cross).number("norm_u", r.norm_u).number("norm_v", r.norm_v);
    a.number("cos", r.cos).number("sin", r.sin).number("angle_deg", r.angle_deg);
    return a;
  }
};

class Vectors final : public MethodKind<VectorsMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"acute", 2}, {"right", 1}, {"obtuse", 2}};
  }
  std::map<std::string, double> default_constraints() const override {
    // |θ| at least min_angle_deg from 0° and 180° (never collinear); an acute or obtuse θ at
    // least right_margin_deg from 90°; both norms at least min_norm; components within
    // ±max_component (the figure around O); the tips at least min_tip_gap apart (their labels).
    return {{"min_angle_deg", 20.0}, {"right_margin_deg", 15.0}, {"min_norm", 2.0},
            {"max_component", 6.0}, {"min_tip_gap", 1.5}};
  }
  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    if (ctx.branch != "acute" && ctx.branch != "right" && ctx.branch != "obtuse")
      throw std::invalid_argument(fmt::format("vectors: no branch '{}'", ctx.branch));
    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    // hard: closer to collinear and to the right angle, but safely away from them
    const double min_angle = constraint(ctx, *this, "min_angle_deg") / (hard ? 2 : 1);
    const double right_margin = constraint(ctx, *this, "right_margin_deg") / (hard ? 2 : 1);
    const double min_norm = constraint(ctx, *this, "min_norm");
    const double max_component = constraint(ctx, *this, "max_component");
    const double min_tip_gap = constraint(ctx, *this, "min_tip_gap");
    const int per_unit = hard ? 10 : 1;
    const std::vector<Vec2> easy = level == Difficulty::easy
                                       ? integer_norm_vectors(max_component, min_norm)
                                       : std::vector<Vec2>{};
    if (level == Difficulty::easy && easy.empty())
      throw std::runtime_error("could not draw an instance meeting the constraints: vectors "
                               "(no integer vector of integer norm within max_component)");

    const auto draw_vector = [&]() -> Vec2 {
      if (level == Difficulty::easy)
        return easy[static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(easy.size()) - 1))];
      return {grid_value(rng, -max_component, max_component, level),
              grid_value(rng, -max_component, max_component, level)};
    };

    const Data d = draw_until(20000, "vectors (angle, norms, distance between the tips)", [&]() -> std::optional<Data> {
      Data x;
      x.u = draw_vector();
      if (geo::norm(x.u) < min_norm) return std::nullopt;
      if (ctx.branch == "right") {
        const auto v = perpendicular_on_grid(x.u, per_unit, max_component, rng);
        if (!v) return std::nullopt;
        x.v = *v;
      } else {
        x.v = draw_vector();
      }
      if (geo::norm(x.v) < min_norm) return std::nullopt;
      // standard asks for a square root somewhere: not both norms whole
      if (level == Difficulty::standard && is_whole(geo::norm(x.u)) && is_whole(geo::norm(x.v)))
        return std::nullopt;
      if (geo::norm(x.u - x.v) < min_tip_gap) return std::nullopt;
      const auto r = geo::compare_vectors(x.u, x.v);
      const double a = std::abs(r.angle_deg);
      if (a < min_angle || a > 180 - min_angle) return std::nullopt;
      bool ok = false;
      if (ctx.branch == "acute") ok = a <= 90 - right_margin;
      if (ctx.branch == "obtuse") ok = a >= 90 + right_margin;
      if (ctx.branch == "right") ok = std::abs(r.cos) <= kRightAngleCos;
      if (!ok) return std::nullopt;
      return x;
    });
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto r = geo::compare_vectors(d.u, d.v);

    const auto sheet_figure = [&](const KeySolution&) { return render::Figure{question_scene(d, ctx), 0.45}; };
    Begun begun = begin_sections(d, ctx, sheet_figure);
    ExerciseInstance& inst = begun.inst;
    const KeySolution& key = begun.key;
    const Questions& q = key.questions;

    const TextVars factors = {{"ux", factor(N, d.u.x)}, {"uy", factor(N, d.u.y)},
                              {"vx", factor(N, d.v.x)}, {"vy", factor(N, d.v.y)}};
    // u·v, u∧v, ‖u‖² and ‖v‖² are exact decimals of the data: written out in full
    TextVars dot_vars = factors;
    dot_vars.emplace_back("dot", N.datum(r.dot));
    inst.key.add(render::Paragraph{T.format("vectors.step.dot", dot_vars)});
    TextVars cross_vars = factors;
    cross_vars.emplace_back("cross", N.datum(r.cross));
    inst.key.add(render::Paragraph{T.format("vectors.step.cross", cross_vars)});
    inst.key.add(render::Paragraph{T.format(
        "vectors.step.norms", {{"nu2", N.datum(geo::norm2(d.u))},
                               {"norm_u", equals_value(ctx, r.norm_u, key.exact("norm_u"))},
                               {"nv2", N.datum(geo::norm2(d.v))},
                               {"norm_v", equals_value(ctx, r.norm_v, key.exact("norm_v"))}})});
    inst.key.add(render::Paragraph{T.format("vectors.step.cos", {{"cos", equals_value(ctx, r.cos, key.exact("cos"))}})});
    inst.key.add(render::Paragraph{T.format("vectors.step.sin", {{"sin", equals_value(ctx, r.sin, key.exact("sin"))}})});
    inst.key.add(render::Paragraph{
        T.format("vectors.step.angle", {{"angle", equals_value(ctx, r.angle_deg, key.exact("angle_deg"))}})});
    // the data's own case (the branch drawn, or the explorer's dragged vectors)
    const char* angle_case = std::abs(r.cos) <= kRightAngleCos ? "right" : r.cos > 0 ? "acute" : "obtuse";
    inst.key.add(render::Paragraph{T.get(fmt::format("vectors.step.{}", angle_case))});
    inst.key.add(render::Paragraph{T.get(r.cross > 0 ? "vectors.step.ccw" : "vectors.step.cw")});
    inst.key.add(render::Figure{key_scene(d, r, ctx), 0.4});
    add_lines(inst.key, q);
    return std::move(inst);
  }

  static render::Panel data_panel(const Data& d) {
    render::Panel panel;
    panel.view = view_around({{0, 0}, p2(d.u), p2(d.v)}, 1.0, 5.0);
    panel.add(render::Grid{1, true});
    panel.add(render::Arrow{{0, 0}, p2(d.u), render::Role::data});
    panel.add(render::Arrow{{0, 0}, p2(d.v), render::Role::data});
    return panel;
  }

  static void add_vector_labels(render::Panel& panel, const Data& d) {
    panel.add(render::Label{"\\vec{u}", p2(d.u)});
    panel.add(render::Label{"\\vec{v}", p2(d.v)});
  }

  render::Scene question_scene(const Data& d, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("vectors.title");
    s.description = ctx.texts.get("vectors.figure.question");
    render::Panel panel = data_panel(d);
    add_vector_labels(panel, d);
    s.panels.push_back(std::move(panel));
    return s;
  }

  render::Scene key_scene(const Data& d, const geo::VectorPair& r, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("vectors.title");
    s.description = ctx.texts.get("vectors.figure.key");
    render::Panel panel = data_panel(d);
    if (ctx.branch == "right") panel.add(render::RightAngle{{0, 0}, p2(d.u), p2(d.v), render::Role::construction});
    // The signed angle: an arc from u to v around O, with an arrowhead at v's end showing the
    // turn. Its radius keeps it clear of the right-angle mark and inside the shorter vector.
    const double radius = std::clamp(0.35 * std::min(r.norm_u, r.norm_v), 0.7, 1.5);
    const double from = std::atan2(d.u.y, d.u.x);
    const double sweep = r.angle_deg * std::numbers::pi / 180;
    const int pieces = std::max(8, static_cast<int>(std::abs(r.angle_deg) / 5));
    render::Polygon arc;
    arc.closed = false;
    arc.role = render::Role::construction;
    for (int i = 0; i <= pieces; ++i) {
      const double phi = from + sweep * i / pieces;
      arc.points.push_back({radius * std::cos(phi), radius * std::sin(phi)});
    }
    // the arrowhead on a chord of the arc's last ~0.4 units: long enough to carry a whole head,
    // short enough to sit on the arc
    const double head_from = from + sweep * (1 - std::min(0.3, 0.4 / (radius * std::abs(sweep))));
    const render::P2 tip = arc.points.back();
    panel.add(std::move(arc));
    panel.add(render::Arrow{{radius * std::cos(head_from), radius * std::sin(head_from)}, tip,
                            render::Role::construction});
    const double middle = from + sweep / 2;
    panel.add(render::Label{"θ", {radius * std::cos(middle), radius * std::sin(middle)},
                            render::Side::auto_, render::Role::result});
    add_vector_labels(panel, d);
    s.panels.push_back(std::move(panel));
    return s;
  }
};

}  // namespace

const ExerciseKind& vectors_kind() { return the_kind<Vectors>(); }

}  // namespace epure::kinds
