// Exercise 1 of the course: the projection P of C on the line (AB), t = AB·AC / AB·AB, and
// where P falls (before A, between A and B, after B).
#include <fmt/format.h>

#include <cmath>

#include "exercises/kind_method.h"
#include "geometry/projection.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::Vec2;

struct Data {
  Point2 A, B, C;
};

// Directions whose squared length divides 100, so that t = AB·AC / AB·AB is a terminating
// decimal: the easy level's hand-computable answers.
constexpr Vec2 kEasyDirections[] = {{2, 0}, {4, 0}, {5, 0}, {0, 2}, {0, 4}, {0, 5},
                                    {3, 4}, {4, 3}, {6, 8}, {8, 6}, {1, 2}, {2, 1}};

using method::AnswerType;
constexpr std::string_view kPositions[] = {"before", "between", "after"};

// The course's exercise 1, written once (method.h).
struct ProjectionMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "projection";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("B", d.B);
    v("C", d.C);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"t", AnswerType::number},
      {"P", AnswerType::point},
      {"position", AnswerType::choice, method::kTickWork, kPositions}};

  // what the exercise adds to the sheet's total when the spec does not set its points (points.h:
  // the sheet's questions share that total by their work)
  static constexpr double kPoints = 5;

  static constexpr std::string_view kMistakes[] = {"t_unsquared_norm", "t_not_divided"};

  // t = AB·AC / AB·AB, rounded; P = A + t·AB; P's place on the line from t.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    const auto A = m.in(d.A), B = m.in(d.B), C = m.in(d.C);
    const auto AB = m.note("AB", B - A), AC = m.note("AC", C - A);
    const auto ab_ac = m.note("ab_ac", dot(AB, AC)), ab_ab = m.note("ab_ab", dot(AB, AB));
    const auto ratio = m.mistake("t_not_divided", m.mistake("t_unsquared_norm", ab_ac / ab_ab, ab_ac / sqrt(ab_ab)), ab_ac);
    const auto t = m.number("t", m.round("t", ratio));
    m.point("P", A + t * AB);
    const auto before = less(t, m.in(0.0)), after = less(m.in(1.0), t);
    m.choice("position", {before ? "before" : after ? "after" : "between", before.deps | after.deps});
  }

  // the solve contract (solve/solve.h)
  static void contract(const Data&, const solve::Fields& f, solve::Result& r) {
    const auto p = geo::project_exact(f.dpoint2("A"), f.dpoint2("B"), f.dpoint2("C"));
    r.number("t", p.t).point("P", p.P).string("position", geo::to_string(p.position));
  }

  static CoreAnswers core(const Data& d) {
    const auto p = geo::project_exact(geo::written_point(d.A), geo::written_point(d.B), geo::written_point(d.C));
    CoreAnswers a;
    a.number("t", p.t).point("P", p.P).choice("position", geo::to_string(p.position));
    return a;
  }
};

class Projection final : public MethodKind<ProjectionMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"before", 1}, {"between", 2}, {"after", 1}};
  }
  std::map<std::string, double> default_constraints() const override {
    // t at least this far from 0 and 1; C at least this far from the line; |AB| at least
    return {{"t_margin", 0.15}, {"min_distance", 1.0}, {"min_length", 3.0}, {"max_t", 2.0}};
  }
  std::vector<DrawnField> drawn() const override { return {{"P", 0, {}}}; }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    // hard: close to the degenerate cases, but safely away from them
    const double t_margin = constraint(ctx, *this, "t_margin") / (hard ? 3 : 1);
    const double min_distance = constraint(ctx, *this, "min_distance") / (hard ? 3 : 1);
    const double min_length = constraint(ctx, *this, "min_length");
    const double max_t = constraint(ctx, *this, "max_t");

    const Data d = draw_until(20000, "projection (t range, distance of C, length of AB)", [&]() -> std::optional<Data> {
      Data x;
      x.A = {grid_value(rng, 0, 10, level), grid_value(rng, 0, 8, level)};
      Vec2 AB;
      if (level == Difficulty::easy) {
        AB = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
        if (rng.chance(0.5)) AB = -AB;
      } else {
        AB = {grid_value(rng, -8, 8, level), grid_value(rng, -8, 8, level)};
      }
      x.B = x.A + AB;
      x.C = {grid_value(rng, 0, 10, level), grid_value(rng, 0, 8, level)};
      if (x.B.x < 0 || x.B.x > 10 || x.B.y < 0 || x.B.y > 8) return std::nullopt;
      if (geo::norm(AB) < min_length) return std::nullopt;
      const auto p = geo::project_exact(geo::written_point(x.A), geo::written_point(x.B), geo::written_point(x.C));
      if (geo::norm(x.C - p.P) < min_distance) return std::nullopt;
      const double t = p.t;
      bool ok = false;
      if (ctx.branch == "before") ok = t <= -t_margin && t >= -(max_t - 1);
      if (ctx.branch == "between") ok = t >= t_margin && t <= 1 - t_margin;
      if (ctx.branch == "after") ok = t >= 1 + t_margin && t <= max_t;
      if (!ok) return std::nullopt;
      // P must stay in the drawing area with room for its label
      if (p.P.x < -1 || p.P.x > 11 || p.P.y < -1 || p.P.y > 9) return std::nullopt;
      return x;
    });
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto p = geo::project_exact(geo::written_point(d.A), geo::written_point(d.B), geo::written_point(d.C));

    const auto sheet_figure = [&](const KeySolution&) { return render::Figure{question_scene(d, ctx), 0.55}; };
    Begun begun = begin_sections(d, ctx, sheet_figure);
    ExerciseInstance& inst = begun.inst;
    const KeySolution& key = begun.key;
    const Questions& q = key.questions;

    const Vec2 AB = p.AB, AC = p.AC;
    inst.key.add(render::Paragraph{T.format(
        "projection.step.vectors", {{"AB", N.point(AB.x, AB.y)}, {"AC", N.point(AC.x, AC.y)}})});
    inst.key.add(render::Paragraph{T.format(
        "projection.step.dots", {{"ab_ac", shown(ctx, p.ab_dot_ac, key.exact("ab_ac"))},
                                 {"ab_ab", shown(ctx, p.ab_dot_ab, key.exact("ab_ab"))}})});
    inst.key.add(render::Paragraph{T.format("projection.step.t", {{"t", shown(ctx, p.t, key.exact("t"))}})});
    inst.key.add(render::Paragraph{
        T.format("projection.step.P", {{"P", shown_point(ctx, p.P, key.exact_x("P"), key.exact_y("P"))}})});
    inst.key.add(render::Paragraph{T.get(fmt::format("projection.step.position.{}", geo::to_string(p.position)))});
    inst.key.add(render::Figure{key_scene(d, p, ctx), 0.45});
    add_lines(inst.key, q);
    return std::move(inst);
  }

  static render::Panel data_panel(const Data& d, const geo::Projection& p) {
    render::Panel panel;
    panel.view = view_around({p2(d.A), p2(d.B), p2(d.C), p2(p.P)}, 1.0, 5.0);
    panel.add(render::Grid{1, true});
    return panel;
  }

  render::Scene question_scene(const Data& d, const ExerciseContext& ctx) const {
    const auto p = geo::project_exact(geo::written_point(d.A), geo::written_point(d.B), geo::written_point(d.C));
    render::Scene s;
    s.title = ctx.texts.get("projection.title");
    s.description = ctx.texts.format("projection.figure.question", {});
    render::Panel panel = data_panel(d, p);
    panel.add(render::Segment{p2(d.A), p2(d.B), render::Role::data});
    panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
    panel.add(render::PointMark{p2(d.B), render::Role::data, render::Label{"B", p2(d.B)}});
    panel.add(render::PointMark{p2(d.C), render::Role::data, render::Label{"C", p2(d.C)}});
    s.panels.push_back(std::move(panel));
    return s;
  }

  render::Scene key_scene(const Data& d, const geo::Projection& p, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("projection.title");
    s.description = ctx.texts.format("projection.figure.key", {});
    render::Panel panel = data_panel(d, p);
    panel.add(render::Line{p2(d.A), p2(d.B), render::Role::construction});
    panel.add(render::Segment{p2(d.A), p2(d.B), render::Role::data});
    panel.add(render::Segment{p2(d.C), p2(p.P), render::Role::construction, true});
    panel.add(render::RightAngle{p2(p.P), p2(d.C - p.P), p2(p.AB), render::Role::construction});
    panel.add(render::Tick{p2(d.A), p2(p.AB), "0", render::Role::construction});
    panel.add(render::Tick{p2(d.B), p2(p.AB), "1", render::Role::construction});
    panel.add(render::Tick{p2(p.P), p2(p.AB),
                           "t = " + ctx.numbers.rounded(p.t, ctx.decimals), render::Role::result});
    panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
    panel.add(render::PointMark{p2(d.B), render::Role::data, render::Label{"B", p2(d.B)}});
    panel.add(render::PointMark{p2(d.C), render::Role::data, render::Label{"C", p2(d.C)}});
    panel.add(render::PointMark{p2(p.P), render::Role::result, render::Label{"P", p2(p.P), render::Side::auto_, render::Role::result}});
    s.panels.push_back(std::move(panel));
    return s;
  }
};

}  // namespace

const ExerciseKind& projection_kind() { return the_kind<Projection>(); }

}  // namespace epure::kinds
