// The course's open question "does this work for any ellipse?": yes, through the canonical
// circle. The ray is carried into the circle's frame by T⁻¹, the course's method (projection,
// then Pythagoras) solves it there, and the hit comes back with the normal by the inverse
// transpose.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kinds/registry.h"
#include "exercises/kinds/transformed_common.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::Vec2;
using namespace transformed;

geo::Ellipse ellipse_of(const Data& d) { return {d.C, d.sx, d.sy, d.angle_deg}; }

// The canonical circle's construction, exactly: ‖A_c‖², t_proj, P_c, d², √(1 − d²), ‖u_c‖, t,
// and I_c (which is also N_c on the unit circle).
struct ExactCircle {
  Ex ac2, t_proj, d2, half_chord, norm_uc, t;
  ExVec Pc, Ic;
};

// t alone, for the easy level's draw: t = t_proj ∓ √((1 − d²)/(u_c·u_c)) with
// d² = A_c·A_c − (A_c·u_c)²/(u_c·u_c).
Ex exact_t(const ExactFrame& f, bool inside) {
  const Ex uu = dot(f.uc, f.uc), au = dot(f.Ac, f.uc);
  const Ex t_proj = -au / uu;
  const Ex d2 = dot(f.Ac, f.Ac) - au * au / uu;
  const Ex along = sqrt((Ex::integer(1) - d2) / uu);
  return inside ? t_proj + along : t_proj - along;
}

ExactCircle exact_circle(const ExactFrame& f, bool inside) {
  ExactCircle e;
  const ExVec& Ac = f.Ac;
  const ExVec& uc = f.uc;
  const Ex uu = dot(uc, uc);
  e.ac2 = dot(Ac, Ac);
  e.t_proj = -dot(Ac, uc) / uu;
  e.Pc = {Ac.x + e.t_proj * uc.x, Ac.y + e.t_proj * uc.y};
  e.d2 = dot(e.Pc, e.Pc);
  const Ex one = Ex::integer(1);
  e.half_chord = sqrt(one - e.d2);
  e.norm_uc = sqrt(uu);
  // √(1 − d²)/‖u_c‖ as one root: rational more often than each part
  const Ex along = sqrt((one - e.d2) / uu);
  e.t = inside ? e.t_proj + along : e.t_proj - along;
  e.Ic = {Ac.x + e.t * uc.x, Ac.y + e.t * uc.y};
  return e;
}

// The intermediates the student rounds after the frame change: t_proj, d², √(1 − d²), ‖u_c‖,
// t, I_c.x, I_c.y.
constexpr int kStudentSteps = kFrameSteps + 7;

// The course's method in the canonical frame, by hand: {Ac.x, Ac.y, uc.x, uc.y} and, with a
// hit, {t, I.x, I.y, N.x, N.y}.
StudentMethod student_method(const Data& d, bool hit, bool inside, int decimals) {
  return [d, hit, inside, decimals](const Nudge& nudge) {
    const Rounding r(nudge, decimals);
    const StudentFrame f = student_frame(d, r);
    std::vector<double> out{f.Ac.x, f.Ac.y, f.uc.x, f.uc.y};
    if (!hit) return out;
    const Vec2 Ac = geo::to_vec(f.Ac);
    const double t_proj = r(kFrameSteps, -(Ac.x * f.uc.x + Ac.y * f.uc.y) / (f.uc.x * f.uc.x + f.uc.y * f.uc.y));
    const Vec2 Pc = Ac + t_proj * f.uc;
    const double d2 = r(kFrameSteps + 1, Pc.x * Pc.x + Pc.y * Pc.y);
    const double half_chord = r(kFrameSteps + 2, std::sqrt(std::max(0.0, 1 - d2)));
    const double norm_uc = r(kFrameSteps + 3, std::hypot(f.uc.x, f.uc.y));
    const double t = r(kFrameSteps + 4, inside ? t_proj + half_chord / norm_uc : t_proj - half_chord / norm_uc);
    const Vec2 Ic{r(kFrameSteps + 5, Ac.x + t * f.uc.x), r(kFrameSteps + 6, Ac.y + t * f.uc.y)};
    out.push_back(t);
    for (double x : student_world(d, f, t, Ic)) out.push_back(x);
    return out;
  };
}

std::vector<double> tolerances(const Data& d, const geo::RayEllipse& r, int decimals) {
  return derive_abs_tolerances(student_method(d, r.hit.has_value(), r.inside, decimals),
                               r.hit ? kStudentSteps : kFrameSteps, decimals);
}

class RayEllipseKind final : public ExerciseKind {
 public:
  std::string_view name() const override { return "ray_ellipse"; }
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 2}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override { return common_constraints(); }
  std::vector<std::string> fields() const override { return transformed::fields(); }
  std::vector<SheetField> sheet_fields() const override {
    return {{"Ac", render::AnswerField::Kind::point, {}},       {"uc", render::AnswerField::Kind::point, {}},
            {"inside", render::AnswerField::Kind::boolean, {}}, {"hit", render::AnswerField::Kind::boolean, {}},
            {"t", render::AnswerField::Kind::number, {}},       {"I", render::AnswerField::Kind::point, {}},
            {"N", render::AnswerField::Kind::point, {}}};
  }

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
      if (level == Difficulty::easy && r.hit && !exact_t(exact_frame(*d), r.inside).is_rational())
        return std::nullopt;
      if (!well_conditioned(tolerances(*d, r, ctx.decimals), lim)) return std::nullopt;
      return d;
    });
    if (auto taken = already_taken(ctx, instance_text(d, Shape::ellipse))) return *std::move(taken);
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
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const {
    const auto r = geo::intersect(world_ray(d), ellipse_of(d));
    const Solved s = solved_of(r);
    const geo::RayCircle& c = r.canonical;

    // exact forms, each checked against the core's double
    const ExactFrame f = exact_frame(d);
    const ExactCircle e = exact_circle(f, r.inside);
    ExactWorld w;
    cross_check(f.Ac, geo::to_vec(s.canonical_ray.origin), "A_c");
    cross_check(f.uc, s.canonical_ray.direction, "u_c");
    cross_check(e.t_proj, c.t_proj, "t_proj");
    cross_check(e.d2, c.d2, "d2");
    if (s.hit) {
      w = exact_world(d, f, e.t, e.Ic);
      cross_check(e.half_chord, *c.half_chord, "half chord");
      cross_check(w.t, s.hit->t, "t");
      cross_check(e.Ic, geo::to_vec(s.canonical_hit->I), "I_c");
      cross_check(w.I, geo::to_vec(s.hit->I), "I");
      cross_check(w.N, s.hit->N, "N");
    }

    ExerciseInstance inst;
    inst.n = ctx.n;
    inst.kind = std::string(name());
    inst.branch = ctx.branch;
    inst.instance = instance_text(d, Shape::ellipse);
    inst.solution = solve_instance(inst.instance);
    inst.fingerprint = fingerprint(inst.instance);

    const auto tol = tolerances(d, r, ctx.decimals);
    Questions q(ctx);
    ask(q, s, tol, f, w);
    inst.questions = q.take_questions();

    const TextVars data = data_vars(ctx, d, Shape::ellipse);
    inst.sheet = begin_sheet_section(ctx, "ray_ellipse.title");
    inst.sheet.add(render::Paragraph{ctx.texts.format("ray_ellipse.statement", data)});
    inst.sheet.add(render::Figure{question_scene(ctx, d, Shape::ellipse, s), 0.55});
    add_fields(inst.sheet, q);

    inst.key = begin_key_section(ctx, "ray_ellipse.title");
    inst.key.add(render::Paragraph{ctx.texts.format("ray_ellipse.statement", data)});
    frame_steps(inst.key, ctx, d, Shape::ellipse, s, f);
    circle_steps(inst.key, ctx, s, c, e);
    if (s.hit) world_steps(inst.key, ctx, d, Shape::ellipse, s, w);
    inst.key.add(render::Figure{key_scene(ctx, d, Shape::ellipse, s, canonical(s, c)), 0.95});
    add_lines(inst.key, q);
    return inst;
  }

  static void circle_steps(render::Section& key, const ExerciseContext& ctx, const Solved& s,
                           const geo::RayCircle& c, const ExactCircle& e) {
    const Vec2 Ac = geo::to_vec(s.canonical_ray.origin);
    step(key, ctx, s.inside ? "inside.yes" : "inside.no", {{"ac2", equals_value(ctx, geo::norm2(Ac), e.ac2.get())}});
    step(key, ctx, "t_proj", {{"t_proj", equals_value(ctx, c.t_proj, e.t_proj.get())}});
    if (c.reason == geo::NoHit::behind) {
      step(key, ctx, "behind");
      return;
    }
    step(key, ctx, "d2",
         {{"Pc", shown_point(ctx, c.P, e.Pc.x.get(), e.Pc.y.get())}, {"d2", equals_value(ctx, c.d2, e.d2.get())}});
    if (c.reason == geo::NoHit::miss) {
      step(key, ctx, "miss");
      return;
    }
    const double norm_uc = geo::norm(s.canonical_ray.direction);
    step(key, ctx, "pythagoras",
         {{"half_chord", equals_value(ctx, *c.half_chord, e.half_chord.get())},
          {"norm_uc", equals_value(ctx, norm_uc, e.norm_uc.get())}});
    step(key, ctx, s.inside ? "t.inside" : "t.outside", {{"t", equals_value(ctx, s.hit->t, e.t.get())}});
    step(key, ctx, "Ic", {{"Ic", shown_point(ctx, s.canonical_hit->I, e.Ic.x.get(), e.Ic.y.get())}});
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

std::vector<double> transformed::ellipse_student_answers(const Data& d) {
  const auto r = geo::intersect(world_ray(d), ellipse_of(d));
  return student_method(d, r.hit.has_value(), r.inside, 2)(Nudge{});
}

const ExerciseKind& ray_ellipse_kind() {
  static const RayEllipseKind kind;
  return kind;
}

}  // namespace epure::kinds
