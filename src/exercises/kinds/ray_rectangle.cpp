// The course's open question "does this work for any rectangle?": yes, through the canonical
// square [-1,1]². The ray is carried into the square's frame by T⁻¹, the course's method (the
// candidate sides, each met where (A_c + t·u_c)·n = 1) solves it there, and the hit comes back
// with the normal by the inverse transpose.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kinds/registry.h"
#include "exercises/kinds/transformed_common.h"
#include "geometry/box_faces.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::Vec2;
using namespace transformed;

geo::Rectangle rectangle_of(const Data& d) { return {d.C, d.sx, d.sy, d.angle_deg}; }

double along(Vec2 v, int axis) { return axis == 0 ? v.x : v.y; }
double along(Point2 p, int axis) { return axis == 0 ? p.x : p.y; }
const Ex& along(const ExVec& v, int axis) { return axis == 0 ? v.x : v.y; }

// A side the method looks at, and what it finds there. From outside: each candidate side, met
// where (A_c + t·u_c)·n = 1 if the ray heads into it (u_c·n < 0), t = (1 − A_c·n)/(u_c·n); the
// point must then lie on the side. From inside: along each axis the side the ray heads to.
struct SideTest {
  geo::Face face;
  double u_n;               // u_c·n
  std::optional<double> t;  // where the ray crosses the side's line, when it heads to it
  Point2 at;                // the ray's point there
  bool on_side = false;
};

std::vector<SideTest> side_tests(const geo::RayRectangle& r) {
  const Point2 Ac = r.canonical_ray.origin;
  const Vec2 uc = r.canonical_ray.direction;
  std::vector<SideTest> tests;
  auto look = [&](geo::Face face) {
    SideTest s{face, face.sign * along(uc, face.axis), std::nullopt, {}, false};
    const bool heads_to = r.inside ? s.u_n > 0 : s.u_n < 0;
    if (heads_to) {
      s.t = (1 - face.sign * along(Ac, face.axis)) / s.u_n;
      s.at = Ac + *s.t * uc;
      s.on_side = std::abs(along(s.at, 1 - face.axis)) <= 1;
    }
    tests.push_back(s);
  };
  if (r.inside) {
    for (int axis : {0, 1})
      if (std::abs(along(uc, axis)) > 0) look({axis, along(uc, axis) > 0 ? +1 : -1});
  } else {
    r.canonical.faces.for_each(look);
  }
  return tests;
}

// The exact side test: u_c·n, t = (σ − A_c)/u_c along the side's axis, and the point there.
struct ExactSide {
  Ex u_n, t;
  ExVec at;
};
ExactSide exact_side(const ExactFrame& f, geo::Face face) {
  ExactSide e;
  const Ex sign = Ex::integer(face.sign);
  e.u_n = sign * along(f.uc, face.axis);
  e.t = (sign - along(f.Ac, face.axis)) / along(f.uc, face.axis);
  e.at = {f.Ac.x + e.t * f.uc.x, f.Ac.y + e.t * f.uc.y};
  return e;
}

Vec2 normal_of(geo::Face face) { return face.axis == 0 ? Vec2{double(face.sign), 0} : Vec2{0, double(face.sign)}; }
ExVec exact_normal_of(geo::Face face) {
  const Ex one = Ex::integer(face.sign), zero = Ex::integer(0);
  return face.axis == 0 ? ExVec{one, zero} : ExVec{zero, one};
}

// The intermediate the student rounds after the frame change: t.
constexpr int kStudentSteps = kFrameSteps + 1;

// The course's method in the canonical frame, by hand, through the side the core says is hit:
// {Ac.x, Ac.y, uc.x, uc.y} and, with a hit, {t, I.x, I.y, N.x, N.y}.
StudentMethod student_method(const Data& d, std::optional<geo::Face> face, int decimals) {
  return [d, face, decimals](const Nudge& nudge) {
    const Rounding r(nudge, decimals);
    const StudentFrame f = student_frame(d, r);
    std::vector<double> out{f.Ac.x, f.Ac.y, f.uc.x, f.uc.y};
    if (!face) return out;
    const double t = r(kFrameSteps, (face->sign - along(f.Ac, face->axis)) / along(f.uc, face->axis));
    out.push_back(t);
    for (double x : student_world(d, f, t, normal_of(*face))) out.push_back(x);
    return out;
  };
}

std::vector<double> tolerances(const Data& d, const geo::RayRectangle& r, int decimals) {
  return derive_abs_tolerances(student_method(d, r.canonical.face, decimals),
                               r.hit ? kStudentSteps : kFrameSteps, decimals);
}

std::string side_name(geo::Face face) { return std::string(geo::face_name(face)); }

class RayRectangleKind final : public ExerciseKind {
 public:
  std::string_view name() const override { return "ray_rectangle"; }
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
    const Data d = draw_until(50000, "ray_rectangle (branch, clearance from the sides and corners, drawing area, aspect, conditioning)",
                              [&]() -> std::optional<Data> {
      auto d = draw_data(rng, level, Shape::rectangle, inside, lim);
      if (!d) return std::nullopt;
      const auto r = geo::intersect(world_ray(*d), rectangle_of(*d));
      if (!clear(r, ctx.branch, lim)) return std::nullopt;
      if (!well_conditioned(tolerances(*d, r, ctx.decimals), lim)) return std::nullopt;
      return d;
    });
    if (auto taken = already_taken(ctx, instance_text(d, Shape::rectangle))) return *std::move(taken);
    return build(d, ctx);
  }

  // The branch asked, and a figure well away from its boundaries: A_c clearly in or out of the
  // square, every side the method tests clearly met or clearly missed (no corner), the side hit
  // met steeply, a miss clear of the corners.
  static bool clear(const geo::RayRectangle& r, const std::string& branch, const Limits& lim) {
    const Point2 Ac = r.canonical_ray.origin;
    const Vec2 uc = r.canonical_ray.direction;
    const double reach = std::max(std::abs(Ac.x), std::abs(Ac.y));
    if (reach > lim.max_canonical) return false;
    if (branch == "inside" ? !r.inside || reach > 1 - lim.margin : reach < 1 + lim.margin) return false;
    for (const SideTest& s : side_tests(r))
      if (s.t && std::abs(std::abs(along(s.at, 1 - s.face.axis)) - 1) < lim.margin) return false;
    if (branch == "miss") {
      if (r.hit) return false;
      // every corner at least `margin` from the half-line (A_c already is from the square)
      for (Point2 corner : {Point2{1, 1}, Point2{-1, 1}, Point2{-1, -1}, Point2{1, -1}}) {
        const double t = std::max(0.0, geo::dot(corner - Ac, uc) / geo::norm2(uc));
        if (geo::norm(corner - (Ac + t * uc)) < lim.margin) return false;
      }
      return true;
    }
    if (!r.hit) return false;
    const double incidence = std::abs(geo::dot(uc, r.canonical.hit->N)) / geo::norm(uc);
    return incidence >= lim.min_incidence && r.hit->t >= lim.min_gap;
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const {
    const auto r = geo::intersect(world_ray(d), rectangle_of(d));
    const Solved s = solved_of(r);

    // exact forms, each checked against the core's double
    const ExactFrame f = exact_frame(d);
    cross_check(f.Ac, geo::to_vec(s.canonical_ray.origin), "A_c");
    cross_check(f.uc, s.canonical_ray.direction, "u_c");
    ExactWorld w;
    if (s.hit) {
      const geo::Face face = *r.canonical.face;
      const ExactSide e = exact_side(f, face);
      w = exact_world(d, f, e.t, exact_normal_of(face));
      cross_check(w.t, s.hit->t, "t");
      cross_check(e.at, geo::to_vec(s.canonical_hit->I), "I_c");
      cross_check(w.I, geo::to_vec(s.hit->I), "I");
      cross_check(w.N, s.hit->N, "N");
    }

    ExerciseInstance inst;
    inst.n = ctx.n;
    inst.kind = std::string(name());
    inst.branch = ctx.branch;
    inst.instance = instance_text(d, Shape::rectangle);
    inst.solution = solve_instance(inst.instance);
    inst.fingerprint = fingerprint(inst.instance);

    const auto tol = tolerances(d, r, ctx.decimals);
    Questions q(ctx);
    ask(q, s, tol, f, w);
    inst.questions = q.take_questions();

    const TextVars data = data_vars(ctx, d, Shape::rectangle);
    inst.sheet = begin_sheet_section(ctx, "ray_rectangle.title");
    inst.sheet.add(render::Paragraph{ctx.texts.format("ray_rectangle.statement", data)});
    inst.sheet.add(render::Figure{question_scene(ctx, d, Shape::rectangle, s), 0.55});
    add_fields(inst.sheet, q);

    inst.key = begin_key_section(ctx, "ray_rectangle.title");
    inst.key.add(render::Paragraph{ctx.texts.format("ray_rectangle.statement", data)});
    frame_steps(inst.key, ctx, d, Shape::rectangle, s, f);
    square_steps(inst.key, ctx, r, f, w);
    if (s.hit) world_steps(inst.key, ctx, d, Shape::rectangle, s, w);
    inst.key.add(render::Figure{key_scene(ctx, d, Shape::rectangle, s, canonical(r)), 0.95});
    add_lines(inst.key, q);
    return inst;
  }

  static void square_steps(render::Section& key, const ExerciseContext& ctx, const geo::RayRectangle& r,
                           const ExactFrame& f, const ExactWorld& w) {
    if (r.inside) {
      step(key, ctx, "inside.yes");
    } else {
      std::string faces;
      r.canonical.faces.for_each([&](geo::Face face) {
        faces += fmt::format("{}{}", faces.empty() ? "" : ", ", side_name(face));
      });
      step(key, ctx, "inside.no", {{"faces", faces}});
    }
    for (const SideTest& side : side_tests(r)) {
      const bool is_hit = r.canonical.face && *r.canonical.face == side.face;
      const ExactSide e = exact_side(f, side.face);
      const std::string face = side_name(side.face);
      if (!side.t) {
        step(key, ctx, "side.away", {{"face", face}, {"u_n", equals_value(ctx, side.u_n, e.u_n.get())}});
        continue;
      }
      // the side hit shows the core's t and point; the others the method's own
      const double t = is_hit ? r.hit->t : *side.t;
      const Point2 at = is_hit ? r.canonical.hit->I : side.at;
      const TextVars vars{{"face", face},
                          {"u_n", equals_value(ctx, side.u_n, e.u_n.get())},
                          {"t", equals_value(ctx, t, e.t.get())},
                          {"at", shown_point(ctx, at, e.at.x.get(), e.at.y.get())}};
      if (r.inside)
        step(key, ctx, "side.exit", vars);
      else
        step(key, ctx, side.on_side ? "side.on" : "side.off", vars);
    }
    if (!r.hit) {
      step(key, ctx, "no_hit");
      return;
    }
    const geo::Face face = *r.canonical.face;
    step(key, ctx, r.inside ? "leaves" : "enters",
         {{"face", side_name(face)},
          {"t", equals_value(ctx, r.hit->t, w.t.get())},
          {"Nc", shown_point(ctx, geo::to_point(r.canonical.hit->N), w.Nc.x.get(), w.Nc.y.get())}});
  }

  // The canonical frame: the square with its candidate sides highlighted (and their supporting
  // lines) and the others muted, A_c and the ray, I_c and N_c.
  static render::Panel canonical(const geo::RayRectangle& r) {
    const Solved s = solved_of(r);
    render::Panel panel = canonical_panel(s);
    for (int axis : {0, 1})
      for (int sign : {+1, -1}) {
        const geo::Face face{axis, sign};
        const Point2 a = axis == 0 ? Point2{double(sign), -1} : Point2{-1, double(sign)};
        const Point2 b = axis == 0 ? Point2{double(sign), 1} : Point2{1, double(sign)};
        const bool candidate = r.canonical.faces.contains(face);
        if (candidate) panel.add(render::Line{p2(a), p2(b), render::Role::construction});
        const render::Role role = r.inside ? render::Role::data
                                  : candidate ? render::Role::highlight
                                              : render::Role::muted;
        panel.add(render::Segment{p2(a), p2(b), role});
      }
    panel.add(render::PointMark{{0, 0}, render::Role::muted, render::Label{"O", {0, 0}, render::Side::auto_, render::Role::muted}});
    add_canonical_ray(panel, s);
    if (s.canonical_hit) add_canonical_hit(panel, *s.canonical_hit);
    return panel;
  }
};

}  // namespace

std::vector<double> transformed::rectangle_student_answers(const Data& d) {
  const auto r = geo::intersect(world_ray(d), rectangle_of(d));
  return student_method(d, r.canonical.face, 2)(Nudge{});
}

const ExerciseKind& ray_rectangle_kind() {
  static const RayRectangleKind kind;
  return kind;
}

}  // namespace epure::kinds
