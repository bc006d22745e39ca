#pragma once
// What the two transformed kinds share (the ellipse and the rectangle), the course's open
// questions answered by transformations. The figure is a canonical one (the unit circle, the
// square [-1,1]²) placed by T = translate(C) ∘ rotate(θ) ∘ scale(sx, sy), with (sx, sy) the radii
// (a, b) or the half-sizes (w, h). The student carries the ray into the canonical frame with T⁻¹
// (A_c = T⁻¹(A), u_c = T⁻¹ applied to û as a vector, not renormalised, so t names the same point
// in both frames), solves the course's canonical problem there, and brings the hit back: I = A +
// t·û and the normal by the inverse transpose. Each kind file holds its schema, its questions and
// its method's canonical part (kind_method.h); this file holds the data and their drawing, the
// method's frame change and way back (written once for both, with their named mistakes), the
// shared worked steps and the shared parts of the diagrams. The kind's name (and the prefix of its
// texts) is the spec's: nothing here names a kind.
#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "exercises/kind_method.h"
#include "exercises/kinds/ray_branch.h"
#include "geometry/affine.h"
#include "geometry/ray_transformed.h"
#include "geometry/turned_written.h"
#include "support/portable.h"

namespace epure::kinds::transformed {

enum class Shape { ellipse, rectangle };

struct Data {
  geo::Point2 A;
  geo::Vec2 u;
  geo::Point2 C;
  double sx = 1, sy = 1;  // radii (a, b) or half-sizes (w, h)
  double angle_deg = 0;   // counter-clockwise rotation of the sx-axis
};

// The solve input's fields: A, u, C, the sizes as one pair named `sizes` ("radii" or "half"),
// the angle. The data keep the sizes as two numbers, so a read fills them from the pair.
template <class V, class D>
void schema(V& v, D& d, std::string_view sizes) {
  v("A", d.A);
  v("u", d.u, role::from("A"));
  v("C", d.C);
  Pair p{d.sx, d.sy};
  v(sizes, p, role::axes_about("C", "angle"));
  if constexpr (!std::is_const_v<D>) {
    d.sx = p.a;
    d.sy = p.b;
  }
  v("angle", d.angle_deg);
}

// The questions both kinds ask, in the sheet's order; t, I, N only with a hit.
inline constexpr method::QuestionDecl kQuestions[] = {
    {"Ac", method::AnswerType::point},    {"uc", method::AnswerType::point}, {"inside", method::AnswerType::boolean},
    {"hit", method::AnswerType::boolean}, {"t", method::AnswerType::number}, {"I", method::AnswerType::point},
    {"N", method::AnswerType::point}};

// The frame change's mistakes, then a kind's own: its kMistakes, in the order grading tries them.
inline constexpr std::string_view kFrameMistakes[] = {
    "rotation_sign",      "translation_forgotten", "transform_order",   "uc_renormalised", "direction_not_unit",
    "direction_translated", "not_back_to_world",   "normal_inward",     "normal_not_unit"};

template <std::size_t N = 0>
constexpr std::array<std::string_view, std::size(kFrameMistakes) + N> frame_mistakes_then(
    const std::array<std::string_view, N>& own = {}) {
  std::array<std::string_view, std::size(kFrameMistakes) + N> all{};
  std::size_t i = 0;
  for (auto m : kFrameMistakes) all[i++] = m;
  for (auto m : own) all[i++] = m;
  return all;
}

// What both kinds declare alike, for MethodKind (kind_method.h): the data and their schema (the
// sizes under the kind's kSizes), the questions, the worth.
template <class Kind>
struct Family {
  using Data = transformed::Data;
  template <class V, class D>
  static void schema(V& v, D& d) {
    transformed::schema(v, d, Kind::kSizes);
  }
  static constexpr auto& kQuestions = transformed::kQuestions;
  // what the exercise adds to the sheet's total when the spec does not set its points (points.h:
  // the sheet's questions share that total by their work)
  static constexpr double kPoints = 7;
};

// The core's answer, whichever the canonical figure: what the shared parts need.
struct Solved {
  geo::Transform2 to_world;
  geo::Ray2 canonical_ray;  // (A_c, u_c)
  bool inside = false;
  std::optional<geo::Hit2> hit;            // world frame
  std::optional<geo::Hit2> canonical_hit;  // canonical frame: I_c, N_c
};
template <class Result>
Solved solved_of(const Result& r) {
  return {r.to_world, r.canonical_ray, r.inside, r.hit, r.canonical.hit};
}
geo::Ray2 world_ray(const Data& d);  // (A, û): t is a length

// The core's answers to kQuestions.
template <class Result>
CoreAnswers core_answers(const Result& r) {
  CoreAnswers a;
  a.point("Ac", r.canonical_ray.origin).vec("uc", r.canonical_ray.direction);
  a.boolean("inside", r.inside).boolean("hit", r.hit.has_value());
  if (r.hit) a.number("t", r.hit->t).point("I", r.hit->I).vec("N", r.hit->N);
  return a;
}

// The solve contract: inside, hit; then t, I, N (the figure's own intersection), decided on the
// decimals written (turned_written.h: exactly at multiples of 30° and 45° and for equal radii,
// by a certified filter at other angles, a line it cannot tell refused; README, "What a number
// means").
template <class Figure>
void solve_contract(const Data& d, const Figure& figure, std::string_view sizes, const solve::Fields& f,
                    solve::Result& r) {
  const auto [ray, length] = solve::raw_ray<geo::Ray2>(d.A, d.u);
  const auto direction = solve::raw_direction(f.dpoint2("u")).first;
  const geo::DPoint2 size = f.dpoint2(sizes);
  const geo::WrittenTurned written{f.dpoint2("A"), f.dpoint2("u"), f.dpoint2("C"), size[0], size[1], f.decimal("angle")};
  const auto e = geo::intersect_written(written, direction, ray, figure);
  r.boolean("inside", e.inside).hit(e.hit, length);
}

// ---- the method's shared parts ---------------------------------------------------------------

// cos θ and sin θ exactly, for θ a whole multiple of 30° or 45°; none otherwise.
struct ExactCosSin {
  std::optional<exact::Surd> cos, sin;
};
ExactCosSin exact_cos_sin(double degrees);

// cos θ and sin θ of the figure's angle, as geo::cos_sin_degrees gives them (correctly rounded).
// Grading runs the method a few dozen times on one figure (once per named mistake), and the
// certified sine is most of a run's time: the last angle's pair is kept, per thread.
inline geo::CosSin figure_cos_sin(double degrees) {
  thread_local double last_degrees = std::numeric_limits<double>::quiet_NaN();
  thread_local geo::CosSin last{};
  if (portable::bit_cast<std::uint64_t>(degrees) != portable::bit_cast<std::uint64_t>(last_degrees)) {
    last = geo::cos_sin_degrees(degrees);
    last_degrees = degrees;
  }
  return last;
}

// A value the student reads from a table (cos 30° = √3/2), not one computed from the data: its
// exact form is given along with it under the exact evaluator.
template <class M>
typename M::Number table_value(const M& m, double x, const std::optional<exact::Surd>& e) {
  if constexpr (std::is_same_v<typename M::Number, method::Exact>) return method::Exact{x, e};
  else return m.in(x);
}

// What the frame change leaves the canonical part and the way back.
template <class M>
struct Frame {
  typename M::Vec A, uh;
  typename M::Number sx, sy, cos, sin;
  typename M::Vec Ac, uc;
};

// The frame change by hand, the answers A_c and u_c: û = u/‖u‖, cos θ and sin θ, then
// A_c = S⁻¹·R(−θ)·(A − C) and u_c = S⁻¹·R(−θ)·û, not renormalised. The student rounds û, cos θ,
// sin θ, A_c and u_c. Mistakes: the rotation the wrong way, the translation forgotten, scale and
// rotation undone in the wrong order, u used without normalising it, the direction translated
// like a point, u_c renormalised.
template <class M>
Frame<M> frame_change(M& m, const Data& d) {
  using Vec = typename M::Vec;
  Frame<M> f;
  f.A = m.in(d.A);
  const auto C = m.in(d.C), u = m.in(d.u);
  f.sx = m.in(d.sx);
  f.sy = m.in(d.sy);
  const auto length = m.note("norm_u", sqrt(dot(u, u)));
  f.uh = m.round("u_hat", m.mistake("direction_not_unit", u / length, u));
  const auto cs = figure_cos_sin(d.angle_deg);
  // the exact forms only where an evaluator keeps them (the key's worked steps), not on each of
  // grading's runs
  ExactCosSin ecs;
  if constexpr (std::is_same_v<typename M::Number, method::Exact>) ecs = exact_cos_sin(d.angle_deg);
  f.cos = m.round("cos", table_value(m, cs.cos, ecs.cos));
  f.sin = m.round("sin", table_value(m, cs.sin, ecs.sin));
  // R(−θ)·v = (c·x + s·y, c·y − s·x); with the wrong sign it is R(θ)
  const auto sin = m.mistake("rotation_sign", f.sin, -f.sin);
  auto back = [&](const Vec& v) -> Vec { return {f.cos * v.x + sin * v.y, f.cos * v.y - sin * v.x}; };
  auto unscale = [&](const Vec& v) -> Vec { return {v.x / f.sx, v.y / f.sy}; };
  // T⁻¹ applied to A as a vector: the translation forgotten
  const auto CA = m.mistake("translation_forgotten", f.A - C, f.A);
  const auto CA_rotated = m.note("CA_rotated", back(CA));
  f.Ac = m.point("Ac", m.round("Ac", m.mistake("transform_order", unscale(CA_rotated), back(unscale(CA)))));
  // T⁻¹ applied to û as a point: the direction translated
  const auto u_rotated = m.note("u_rotated", back(m.mistake("direction_translated", f.uh, f.uh - C)));
  const auto uc = unscale(u_rotated);
  f.uc = m.point("uc", m.round("uc", m.mistake("uc_renormalised", uc, uc / norm(uc))));
  return f;
}

// Back to the world, the answers I and N: I = A + t·û (t is a length along û in both frames)
// and N = normalise(R(θ)·S⁻¹·N_c), the inverse transpose, with the student's rounded û, cos θ
// and sin θ. Mistakes: the answers left in the canonical frame (I_c, N_c), the normal pointing
// inward, not normalised, or carried by T = R(θ)·S instead of the inverse transpose.
template <class M>
void back_to_world(M& m, const Frame<M>& f, const typename M::Number& t, const typename M::Vec& Ic,
                   const typename M::Vec& Nc) {
  using Vec = typename M::Vec;
  m.point("I", m.mistake("not_back_to_world", f.A + t * f.uh, Ic));
  auto rotate = [&](const Vec& v) -> Vec { return {f.cos * v.x - f.sin * v.y, f.sin * v.x + f.cos * v.y}; };
  m.note("Nc", Nc);
  const auto n = m.note("n", rotate({Nc.x / f.sx, Nc.y / f.sy}));
  const auto N = n / norm(n);
  const auto by_T = rotate({Nc.x * f.sx, Nc.y * f.sy});
  const auto wrong_transform = by_T / norm(by_T);
  m.point("N", m.mistake("normal_inward",
                         m.mistake("normal_not_unit",
                                   m.mistake("normal_wrong_transform", m.mistake("not_back_to_world", N, Nc),
                                             wrong_transform),
                                   n),
                         -N));
}

// ---- constraints -------------------------------------------------------------------------------

// The constraints both kinds have, with their defaults.
std::map<std::string, double> common_constraints();

struct Limits {
  double margin;         // canonical clearance from the boundary: clear hit, clear miss, A clearly in or out
  double min_incidence;  // the ray meets the boundary at least this steeply (sine of the angle)
  double min_gap;        // world distance from A to I, so their labels stand apart
  double max_aspect;     // sx/sy or sy/sx at most
  double min_aspect;     // and at least: an ellipse that is not a circle
  double width, height;  // the drawing area [0, width] × [0, height]
  double max_canonical;  // |A_c| in the canonical frame at most, so the unit figure stays visible
  double max_tolerance;  // the largest derived tolerance of an answer: a well-conditioned instance
};
// The spec's values or the defaults; hard instances are allowed twice as close to the
// degenerate cases (margins halved), still safely away from them. `max_amplification` bounds
// how many rounding steps δ = ½·10^−decimals an answer may move when the student rounds as told:
// a figure where honest rounding moves t by a whole unit is ill-conditioned, not hard.
Limits limits(const ExerciseContext& ctx, const ExerciseKind& kind);

// Draws the data of one attempt per difficulty (easy: angle 0° or 90°, integer data, û rational;
// standard: integer data, angle a multiple of 30° or 45°; hard: one decimal, any whole-degree
// angle), with the figure and A inside the drawing area and the aspect ratio within limits.
// Empty when this attempt fails those checks; the branch is checked by the caller.
std::optional<Data> draw_data(Rng& rng, Difficulty level, Shape shape, bool inside, const Limits& lim);

// Whether every tolerance the method derives (a Dual run: how far each answer moves when the
// student rounds as told) is within the limit.
bool well_conditioned(const std::vector<double>& tolerances, const Limits& lim);
template <class Kind>
bool well_conditioned(const Data& d, int decimals, const Limits& lim) {
  method::Run<method::Dual> dual({Kind::kQuestions, decimals});
  Kind::method(dual, d);
  return well_conditioned(method::tolerances(dual), lim) && method::carried_within(dual);
}

// ---- texts -------------------------------------------------------------------------------------

// The statement's data, named as the kind's templates name them (${a}, ${b} or ${w}, ${h}).
TextVars data_vars(const ExerciseContext& ctx, const Data& d, Shape shape);
// "T^{-1} = scale(1/2, 1/3) ∘ rotate(−30°) ∘ translate((−4, −5))", from the kind's `link`.
std::string link_text(const ExerciseContext& ctx, const Data& d, Shape shape);
// A worked step's paragraph: the kind's template `step.<name>`.
void step(render::Section& s, const ExerciseContext& ctx, std::string_view name, const TextVars& vars = {});
// The frame change: T⁻¹, û, cos θ and sin θ, A_c, u_c, with the values of the key's method.
void frame_steps(render::Section& s, const ExerciseContext& ctx, const Data& d, Shape shape, const KeySolution& key);
// Back to the world: I, then the normal by the inverse transpose.
void world_steps(render::Section& s, const ExerciseContext& ctx, const KeySolution& key);

// ---- diagrams ----------------------------------------------------------------------------------

// The world frame on a grid: the figure, C, its two semi-axes labelled, A, the ray and û; in a
// key (ray_followed_to_hit) the ray is solid only up to its hit.
render::Panel world_panel(const Data& d, Shape shape, const Solved& s, bool ray_followed_to_hit);
// The hit in the world frame: I and the normal N.
void add_world_hit(render::Panel& panel, const geo::Hit2& hit);
// The canonical frame's view and grid around the unit figure, A_c and the hit.
render::Panel canonical_panel(const Solved& s);
// The canonical ray: A_c, the ray along u_c, the arrow u_c.
void add_canonical_ray(render::Panel& panel, const Solved& s);
// I_c and N_c.
void add_canonical_hit(render::Panel& panel, const geo::Hit2& hit);

// The question's scene (the world frame with the data) and the key's (world and canonical frames
// side by side, T⁻¹ between them).
render::Scene question_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s);
render::Scene key_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s,
                        render::Panel canonical);

// ---- the instance ------------------------------------------------------------------------------

// The instance of drawn data, laid out as both kinds lay it: the sheet (the statement with the
// data, the world frame's figure, the answer fields) and the key (the frame change, the
// canonical part as the method told it, the way back with a hit, the two frames' figure).
template <class Kind>
ExerciseInstance assemble(const Data& d, const ExerciseContext& ctx, Shape shape, const Solved& s,
                          render::Panel canonical) {
  using Base = MethodKind<Kind>;
  const std::string kind(Kind::kName);
  ExerciseInstance inst = Base::begin_instance(d, ctx);
  KeySolution key = Base::key_solution(d, ctx);
  inst.questions = key.questions.take_questions();
  const TextVars data = data_vars(ctx, d, shape);
  if (ctx.sheet) {  // not for the explorer's views, which show the key only
    inst.sheet = begin_sheet_section(ctx, kind + ".title");
    inst.sheet.add(render::Paragraph{ctx.texts.format(kind + ".statement", data)});
    inst.sheet.add(render::Figure{question_scene(ctx, d, shape, s), 0.55});
    add_fields(inst.sheet, key.questions);
  }
  inst.key = begin_key_section(ctx, kind + ".title");
  inst.key.add(render::Paragraph{ctx.texts.format(kind + ".data", data)});
  frame_steps(inst.key, ctx, d, shape, key);
  replay_steps(inst.key, ctx, key, Kind::kName);
  if (s.hit) world_steps(inst.key, ctx, key);
  inst.key.add(render::Figure{key_scene(ctx, d, shape, s, std::move(canonical)), 0.95});
  add_lines(inst.key, key.questions);
  return inst;
}

// A kind of the two: MethodKind with their branches, constraints, draw loop and layout. The kind
// adds, as static members: kShape, kWhat (what its constraints hold), figure_of(d) (the core's
// figure), clear(result, branch, limits) (the branch asked, clear of its boundaries), canonical
// (result) (the canonical frame's panel), and optionally easy(d, result, ctx) (what the easy
// level asks more).
template <class Kind>
class TransformedKind final : public MethodKind<Kind> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 2}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override { return common_constraints(); }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}, {"N", 0, "I", "\\vec{N}"}, {"Ac", 1, {}, "A_{c}"}, {"uc", 1, "Ac", "\\vec{u}_{c}"}}; }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const Limits lim = limits(ctx, *this);
    const Difficulty level = ctx.spec.difficulty;
    const std::optional<RayBranch> branch = ray_branch(ctx.branch);
    const bool inside = branch == RayBranch::inside;
    const Data d = draw_until(50000, fmt::format("{} ({})", Kind::kName, Kind::kWhat), [&]() -> std::optional<Data> {
      auto d = draw_data(rng, level, Kind::kShape, inside, lim);
      if (!d) return std::nullopt;
      const auto r = geo::intersect(world_ray(*d), Kind::figure_of(*d));
      if (!Kind::clear(r, branch, lim)) return std::nullopt;
      if constexpr (requires { Kind::easy(*d, r, ctx); })
        if (level == Difficulty::easy && !Kind::easy(*d, r, ctx)) return std::nullopt;
      if (!well_conditioned<Kind>(*d, ctx.decimals, lim)) return std::nullopt;
      return d;
    });
    if (auto taken = already_taken(ctx, this->write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto r = geo::intersect(world_ray(d), Kind::figure_of(d));
    return transformed::assemble<Kind>(d, ctx, Kind::kShape, solved_of(r), Kind::canonical(r));
  }
};

// ---- for the tests ------------------------------------------------------------------------------

// Each kind's key solution of given data, as make() builds it: the method's exact run (worked
// steps and exact forms), the core's answers and the questions with their tolerances.
KeySolution ellipse_key(const Data& d, const ExerciseContext& ctx);
KeySolution rectangle_key(const Data& d, const ExerciseContext& ctx);

}  // namespace epure::kinds::transformed
