// The course's open question "does this work for any rectangle?": yes, through the canonical
// square [-1,1]². The ray is carried into the square's frame by T⁻¹, the course's method (the
// candidate sides, each met where (A_c + t·u_c)·n = 1) solves it there, and the hit comes back
// with the normal by the inverse transpose.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kinds/transformed_common.h"
#include "geometry/box_faces.h"
#include "support/portable.h"

namespace epure::kinds {

namespace {

using geo::Face;
using geo::Point2;
using geo::Vec2;
using namespace transformed;

geo::Rectangle rectangle_of(const Data& d) { return {d.C, d.sx, d.sy, d.angle_deg}; }

double along(Vec2 v, int axis) { return axis == 0 ? v.x : v.y; }
double along(Point2 p, int axis) { return axis == 0 ? p.x : p.y; }

// A side the method looks at, on the core's canonical ray, for the draw's clearances (the key
// shows the method's own steps). From outside: each candidate side, met where (A_c + t·u_c)·n = 1
// if the ray heads into it (u_c·n < 0), t = (1 − A_c·n)/(u_c·n). From inside: along each axis
// the side the ray heads to.
// |u_c·n| below this fraction of ‖u_c‖ is zero: what the binary rounding of cos 90° or sin 180°
// leaves (about 1e-17) where the ray runs along a side's direction, never a real crossing.
constexpr double kAlongSide = 1e-12;

struct SideTest {
  geo::Face face;
  std::optional<double> t;  // where the ray crosses the side's line, when it heads to it
  Point2 at;                // the ray's point there
};

std::vector<SideTest> side_tests(const geo::RayRectangle& r) {
  const Point2 Ac = r.canonical_ray.origin;
  const Vec2 uc = r.canonical_ray.direction;
  std::vector<SideTest> tests;
  const double tiny = kAlongSide * geo::norm(uc);
  auto look = [&](geo::Face face) {
    SideTest s{face, std::nullopt, {}};
    const double u_n = face.sign * along(uc, face.axis);
    if (r.inside ? u_n > tiny : u_n < -tiny) {
      s.t = (1 - face.sign * along(Ac, face.axis)) / u_n;
      s.at = Ac + *s.t * uc;
    }
    tests.push_back(s);
  };
  if (r.inside) {
    for (int axis : {0, 1})
      if (std::abs(along(uc, axis)) > tiny) look({axis, along(uc, axis) > 0 ? +1 : -1});
  } else {
    r.canonical.faces.for_each(look);
  }
  return tests;
}

using square::index_of;
using square::kSides;
using square::kStepJ;
using square::kStepT;
using square::kStepUn;

// The ray and the rectangle, written once (method.h): the frame change and the way back are
// transformed_common's, the canonical part is the course's exercise 4 on the square.
struct RayRectangle {
  using Data = transformed::Data;
  static constexpr std::string_view kName = "ray_rectangle";

  template <class V, class D>
  static void schema(V& v, D& d) {
    transformed::schema(v, d, "half");
  }

  static constexpr auto& kQuestions = transformed::kQuestions;
  // what the exercise is worth on every sheet, whatever the branch (the spec may say otherwise)
  static constexpr double kPoints = 7;

  // No normal_wrong_transform: a side's canonical normal lies along an axis, which S and S⁻¹
  // only stretch, so the normal carried by T and normalised is the right one.
  static constexpr std::string_view kMistakes[] = {
      "rotation_sign",        "translation_forgotten", "transform_order",   "uc_renormalised",
      "direction_not_unit",   "direction_translated",  "not_back_to_world", "normal_inward",
      "normal_not_unit"};

  // In the canonical frame, as the course's exercise 4 (the square): the candidate sides are
  // those whose closed outer half-plane holds A_c (A_c·n ≥ 1), A_c is inside when there is none;
  // on each side the ray heads into (u_c·n < 0; from inside, u_c·n > 0), (A_c + t·u_c)·n = 1
  // gives t = (1 − A_c·n)/(u_c·n), and the crossing is the hit when it lies on the side (the
  // nearest, from inside). N_c is the normal of the side I_c = A_c + t·u_c lies on. They round t.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using Num = typename M::Number;
    const Frame<M> f = frame_change(m, d);
    const auto one = m.in(1.0), zero = m.in(0.0);
    auto coord = [](const auto& p, int axis) { return axis == 0 ? p.x : p.y; };
    auto on = [&](const auto& p, Face s) { return s.sign > 0 ? coord(p, s.axis) : -coord(p, s.axis); };

    bool candidate[4] = {};
    method::Cond inside{true};
    for (int i = 0; i < 4; ++i) {
      const auto a_n = on(f.Ac, kSides[i]);
      candidate[i] = !less(a_n, one).v;
      inside = inside && less(a_n, one);
    }
    const auto in = m.boolean("inside", inside);
    std::optional<Num> best;
    const double tiny = kAlongSide * portable::hypot(method::value(f.uc.x), method::value(f.uc.y));
    for (int i = 0; i < 4; ++i) {
      const Face s = kSides[i];
      const auto u_n = m.note(kStepUn[i], on(f.uc, s));
      const bool in_play = in ? method::value(u_n) > tiny : candidate[i];
      if (!in_play || (!in && !(method::value(u_n) < -tiny))) continue;
      const auto t = m.note(kStepT[i], (one - on(f.Ac, s)) / u_n);
      const auto J = m.note(kStepJ[i], f.Ac + t * f.uc);
      const bool on_side = static_cast<bool>(!less(t, zero) && !less(one, method::magnitude(coord(J, 1 - s.axis))));
      if (on_side && (!best || less(t, *best))) best = t;
    }
    // whether it hits is read from A_c and u_c
    const method::Deps deps = in.deps | method::deps_of(f.Ac.x) | method::deps_of(f.Ac.y) |
                              method::deps_of(f.uc.x) | method::deps_of(f.uc.y);
    const auto hit = m.boolean("hit", method::Cond{best.has_value(), deps});
    if (!hit) return;
    const auto t = m.number("t", m.round("t", best ? *best : zero));
    const auto Ic = m.note("Ic", f.Ac + t * f.uc);
    // the side I_c lies on: its larger coordinate, in absolute value
    const bool on_x = static_cast<bool>(!less(method::magnitude(Ic.x), method::magnitude(Ic.y)));
    const auto sign = [&](const auto& c) { return less(c, zero) ? -one : one; };
    const auto no = Ic.x - Ic.x;  // carries I_c's dependencies into N_c, at no cost to its value
    const typename M::Vec Nc{m.either(no + (on_x ? sign(Ic.x) : zero), on_x ? sign(Ic.x) : zero),
                             m.either(no + (on_x ? zero : sign(Ic.y)), on_x ? zero : sign(Ic.y))};
    back_to_world(m, f, t, Ic, Nc);
  }

  static CoreAnswers core(const Data& d) { return core_answers(geo::intersect(world_ray(d), rectangle_of(d))); }
};

std::string side_name(geo::Face face) { return face_label(geo::face_name(face)); }

class RayRectangleKind final : public MethodKind<RayRectangle> {
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
    const Data d = draw_until(50000, "ray_rectangle (branch, clearance from the sides and corners, drawing area, aspect, conditioning)",
                              [&]() -> std::optional<Data> {
      auto d = draw_data(rng, level, Shape::rectangle, inside, lim);
      if (!d) return std::nullopt;
      const auto r = geo::intersect(world_ray(*d), rectangle_of(*d));
      if (!clear(r, ctx.branch, lim)) return std::nullopt;
      if (!well_conditioned<RayRectangle>(*d, ctx.decimals, lim)) return std::nullopt;
      return d;
    });
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
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
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto r = geo::intersect(world_ray(d), rectangle_of(d));
    const Solved s = solved_of(r);

    ExerciseInstance inst = begin_instance(d, ctx);
    KeySolution key = solve(d, ctx);
    const Questions& q = key.questions;
    inst.questions = key.questions.take_questions();

    const TextVars data = data_vars(ctx, d, Shape::rectangle);
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      inst.sheet = begin_sheet_section(ctx, "ray_rectangle.title");
      inst.sheet.add(render::Paragraph{ctx.texts.format("ray_rectangle.statement", data)});
      inst.sheet.add(render::Figure{question_scene(ctx, d, Shape::rectangle, s), 0.55});
      add_fields(inst.sheet, q);
    }

    inst.key = begin_key_section(ctx, "ray_rectangle.title");
    inst.key.add(render::Paragraph{ctx.texts.format("ray_rectangle.data", data)});
    frame_steps(inst.key, ctx, d, Shape::rectangle, key);
    square_steps(inst.key, ctx, r, key);
    if (s.hit) world_steps(inst.key, ctx, key);
    inst.key.add(render::Figure{key_scene(ctx, d, Shape::rectangle, s, canonical(r)), 0.95});
    add_lines(inst.key, q);
    return inst;
  }

  // The canonical square's steps, side by side as the core decides them, with the values of the
  // key's method.
  static void square_steps(render::Section& sec, const ExerciseContext& ctx, const geo::RayRectangle& r,
                           const KeySolution& key) {
    auto value = [&](std::string_view id) { return equals_value(ctx, key.value(id), key.exact(id)); };
    if (r.inside) {
      step(sec, ctx, "inside.yes");
    } else {
      std::string faces;
      r.canonical.faces.for_each([&](geo::Face face) {
        faces += fmt::format("{}{}", faces.empty() ? "" : ", ", side_name(face));
      });
      step(sec, ctx, "inside.no", {{"faces", faces}});
    }
    // the sides the method looked at, in the key's order (axis by axis): from outside the
    // candidates, from inside those the ray heads to; a side it heads into has its crossing
    auto show = [&](Face side) {
      const int i = index_of(side);
      const std::string face = side_name(side);
      if (!key.run.step(kStepT[i])) {
        if (!r.inside) step(sec, ctx, "side.away", {{"face", face}, {"u_n", value(kStepUn[i])}});
        return;
      }
      const Point2 J = key.point(kStepJ[i]);
      const TextVars vars{{"face", face},
                          {"u_n", value(kStepUn[i])},
                          {"t", value(kStepT[i])},
                          {"at", shown_point(ctx, J, key.exact_x(kStepJ[i]), key.exact_y(kStepJ[i]))}};
      if (r.inside)
        step(sec, ctx, "side.exit", vars);
      else
        step(sec, ctx, std::abs(along(J, 1 - side.axis)) <= 1 ? "side.on" : "side.off", vars);
    };
    if (r.inside) {
      for (int axis : {0, 1})
        for (int sign : {+1, -1}) show({axis, sign});
    } else {
      r.canonical.faces.for_each(show);
    }
    if (!r.hit) {
      step(sec, ctx, "no_hit");
      return;
    }
    const geo::Face face = *r.canonical.face;
    step(sec, ctx, r.inside ? "leaves" : "enters",
         {{"face", side_name(face)},
          {"t", value("t")},
          {"Nc", shown_point(ctx, key.point("Nc"), key.exact_x("Nc"), key.exact_y("Nc"))}});
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

KeySolution transformed::rectangle_key(const Data& d, const ExerciseContext& ctx) { return MethodKind<RayRectangle>::solve(d, ctx); }

const ExerciseKind& ray_rectangle_kind() {
  static const RayRectangleKind kind;
  return kind;
}

}  // namespace epure::kinds
