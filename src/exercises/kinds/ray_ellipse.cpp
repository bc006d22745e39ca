// The course's open question "does this work for any ellipse?": yes, through the canonical
// circle. The ray is carried into the circle's frame by T⁻¹, the course's method (projection,
// then Pythagoras) solves it there, and the hit comes back with the normal by the inverse
// transpose.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kinds/transformed_common.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::Vec2;
using namespace transformed;

geo::Ellipse ellipse_of(const Data& d) { return {d.C, d.sx, d.sy, d.angle_deg}; }

// The ray and the ellipse, written once (method.h): the frame change and the way back are
// transformed_common's, the canonical part is the course's exercise 3 on the unit circle.
struct RayEllipse {
  using Data = transformed::Data;
  static constexpr std::string_view kName = "ray_ellipse";

  template <class V, class D>
  static void schema(V& v, D& d) {
    transformed::schema(v, d, "radii");
  }

  static constexpr auto& kQuestions = transformed::kQuestions;
  // what the exercise is worth on every sheet, whatever the branch (the spec may say otherwise)
  static constexpr double kPoints = 7;

  // In the order grading tries them: the far root last, since it moves N too (at the flat
  // ellipse's far vertex N is −N, the normal inward, which names the answer better).
  static constexpr std::string_view kMistakes[] = {
      "rotation_sign",     "translation_forgotten", "transform_order",        "uc_renormalised",
      "direction_not_unit", "direction_translated",  "not_back_to_world",      "normal_inward",
      "normal_not_unit",   "normal_wrong_transform", "far_intersection",       "near_root_inside"};

  // In the canonical frame, by hand: A_c inside when ‖A_c‖² < 1; the projection of O on the
  // ray, t_proj = −(A_c·u_c)/(u_c·u_c), P_c = A_c + t_proj·u_c, d² = ‖P_c‖²; behind (outside,
  // t_proj < 0) or beside (d² > 1) it misses; else Pythagoras, half chord √(1 − d²), and t =
  // t_proj ∓ √(1 − d²)/‖u_c‖ (the near root from outside, the far one from inside), I_c = A_c +
  // t·u_c, which is also N_c on the unit circle. They round t_proj, d², √(1 − d²), ‖u_c‖, t and
  // I_c on the way.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using method::less_equal;
    const Frame<M> f = frame_change(m, d);
    const auto one = m.in(1.0), zero = m.in(0.0);
    const auto ac2 = m.note("ac2", dot(f.Ac, f.Ac));
    const auto inside = m.boolean("inside", less(ac2, one));
    const auto uu = dot(f.uc, f.uc);
    const auto t_proj = m.round("t_proj", -dot(f.Ac, f.uc) / uu);
    const auto Pc = m.note("Pc", f.Ac + t_proj * f.uc);
    const auto d2 = m.round("d2", dot(Pc, Pc));
    const auto ahead = !less(t_proj, zero);
    const auto hit = m.boolean("hit", inside || (ahead && less_equal(d2, one)));
    if (!hit) return;
    const auto half_chord = m.round("half_chord", sqrt(one - d2));
    const auto norm_uc = m.round("norm_uc", sqrt(uu));
    const auto near = t_proj - half_chord / norm_uc, far = t_proj + half_chord / norm_uc;
    // √((1 − d²)/(u_c·u_c)) as one root: an exact form more often than each root apart
    const auto along = sqrt((one - d2) / uu);
    const auto t = m.number(
        "t", m.round("t", inside ? m.either(m.mistake("near_root_inside", far, near), t_proj + along)
                                 : m.either(m.mistake("far_intersection", near, far), t_proj - along)));
    const auto Ic = m.round("Ic", f.Ac + t * f.uc);
    back_to_world(m, f, t, Ic, Ic);
  }

  static CoreAnswers core(const Data& d) { return core_answers(geo::intersect(world_ray(d), ellipse_of(d))); }
};

class RayEllipseKind final : public MethodKind<RayEllipse> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 2}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override { return common_constraints(); }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}, {"N", 0, "I"}, {"Ac", 1, {}}, {"uc", 1, "Ac"}}; }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const Limits lim = limits(ctx, *this);
    const Difficulty level = ctx.spec.difficulty;
    const bool inside = ctx.branch == "inside";
    const Data d = draw_until(50000, "ray_ellipse (branch, clearance from the ellipse, drawing area, aspect, conditioning)",
                              [&]() -> std::optional<Data> {
      auto d = draw_data(rng, level, Shape::ellipse, inside, lim);
      if (!d) return std::nullopt;
      const auto r = geo::intersect(world_ray(*d), ellipse_of(*d));
      if (!clear(r, ctx.branch, lim)) return std::nullopt;
      // easy: t rational, so that I is too
      if (level == Difficulty::easy && r.hit) {
        const auto run = exact_run(*d, ctx.decimals);
        const auto* t = run.answer("t");
        if (!t || !t->x.e || !t->x.e->is_rational()) return std::nullopt;
      }
      if (!well_conditioned<RayEllipse>(*d, ctx.decimals, lim)) return std::nullopt;
      return d;
    });
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return build(d, ctx);
  }

  // The branch asked, and a figure well away from its boundaries: A clearly in or out, the
  // canonical line clearly through or clearly beside the circle (or clearly pointing away).
  static bool clear(const geo::RayEllipse& r, const std::string& branch, const Limits& lim) {
    const Vec2 Ac = geo::to_vec(r.canonical_ray.origin);
    const double from_centre = geo::norm(Ac);
    if (std::max(std::abs(Ac.x), std::abs(Ac.y)) > lim.max_canonical) return false;
    if (branch == "inside" ? !r.inside || from_centre > 1 - lim.margin : from_centre < 1 + lim.margin)
      return false;
    const double d = std::sqrt(r.canonical.d2);
    if (branch == "miss") {
      if (r.hit) return false;
      // behind or beside, told apart clearly; the half-line's nearest point to O is A_c or P_c
      const double t_proj_length = r.canonical.t_proj * geo::norm(r.canonical_ray.direction);
      if (std::abs(t_proj_length) < lim.margin) return false;
      return (t_proj_length > 0 ? d : from_centre) >= 1 + lim.margin;
    }
    if (!r.hit) return false;
    if (branch == "hit" && d > 1 - lim.margin) return false;  // steeper than min_incidence too
    return r.hit->t >= lim.min_gap;
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto r = geo::intersect(world_ray(d), ellipse_of(d));
    const Solved s = solved_of(r);

    ExerciseInstance inst = begin_instance(d, ctx);
    KeySolution key = solve(d, ctx);
    const Questions& q = key.questions;
    inst.questions = key.questions.take_questions();

    const TextVars data = data_vars(ctx, d, Shape::ellipse);
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      inst.sheet = begin_sheet_section(ctx, "ray_ellipse.title");
      inst.sheet.add(render::Paragraph{ctx.texts.format("ray_ellipse.statement", data)});
      inst.sheet.add(render::Figure{question_scene(ctx, d, Shape::ellipse, s), 0.55});
      add_fields(inst.sheet, q);
    }

    inst.key = begin_key_section(ctx, "ray_ellipse.title");
    inst.key.add(render::Paragraph{ctx.texts.format("ray_ellipse.data", data)});
    frame_steps(inst.key, ctx, d, Shape::ellipse, key);
    circle_steps(inst.key, ctx, r, key);
    if (s.hit) world_steps(inst.key, ctx, key);
    inst.key.add(render::Figure{key_scene(ctx, d, Shape::ellipse, s, canonical(s, r.canonical)), 0.95});
    add_lines(inst.key, q);
    return inst;
  }

  // The canonical circle's steps, as the core decides them (inside, behind, miss), with the
  // values of the key's method.
  static void circle_steps(render::Section& sec, const ExerciseContext& ctx, const geo::RayEllipse& r,
                           const KeySolution& key) {
    auto value = [&](std::string_view id) { return equals_value(ctx, key.value(id), key.exact(id)); };
    const geo::RayCircle& c = r.canonical;
    step(sec, ctx, r.inside ? "inside.yes" : "inside.no", {{"ac2", value("ac2")}});
    step(sec, ctx, "t_proj", {{"t_proj", value("t_proj")}});
    if (c.reason == geo::NoHit::behind) {
      step(sec, ctx, "behind");
      return;
    }
    step(sec, ctx, "d2",
         {{"Pc", shown_point(ctx, key.point("Pc"), key.exact_x("Pc"), key.exact_y("Pc"))}, {"d2", value("d2")}});
    if (c.reason == geo::NoHit::miss) {
      step(sec, ctx, "miss");
      return;
    }
    step(sec, ctx, "pythagoras", {{"half_chord", value("half_chord")}, {"norm_uc", value("norm_uc")}});
    step(sec, ctx, r.inside ? "t.inside" : "t.outside", {{"t", value("t")}});
    step(sec, ctx, "Ic", {{"Ic", shown_point(ctx, key.point("Ic"), key.exact_x("Ic"), key.exact_y("Ic"))}});
  }

  // The canonical frame: the unit circle, A_c and the ray, the projection P_c of O with its right
  // angle, and with a hit the Pythagoras triangle O–P_c–I_c, I_c and N_c.
  static render::Panel canonical(const Solved& s, const geo::RayCircle& c) {
    render::Panel panel = canonical_panel(s);
    panel.add(render::Circle{{0, 0}, 1, render::Role::data});
    panel.add(render::PointMark{{0, 0}, render::Role::data, render::Label{"O", {0, 0}}});
    const bool projected = c.reason != geo::NoHit::behind;  // P_c is ahead of A_c
    // below this the right angle and the triangle are too small to draw
    constexpr double kVisible = 0.1;
    const bool apart = c.d2 > kVisible * kVisible;
    if (projected && s.canonical_hit && apart)
      panel.add(render::Polygon{{{0, 0}, p2(c.P), p2(s.canonical_hit->I)}, true, render::Role::construction, true});
    if (projected) {
      panel.add(render::Segment{{0, 0}, p2(c.P), render::Role::construction, true});
      if (apart)
        panel.add(render::RightAngle{p2(c.P), p2(Point2{0, 0} - c.P), p2(s.canonical_ray.direction),
                                     render::Role::construction});
    }
    add_canonical_ray(panel, s);
    if (projected)
      panel.add(render::PointMark{p2(c.P), render::Role::construction,
                                  render::Label{"P_{c}", p2(c.P), render::Side::auto_, render::Role::construction}});
    if (s.canonical_hit) add_canonical_hit(panel, *s.canonical_hit);
    return panel;
  }
};

}  // namespace

KeySolution transformed::ellipse_key(const Data& d, const ExerciseContext& ctx) { return MethodKind<RayEllipse>::solve(d, ctx); }

const ExerciseKind& ray_ellipse_kind() {
  static const RayEllipseKind kind;
  return kind;
}

}  // namespace epure::kinds
