// Exercise 4 of the course: the first point where a ray meets the canonical square [-1,1]². The
// sides whose outer half-plane holds A are the candidates (at most two); each is met where
// (A + t·û)·n = 1, t = (1 − A·n) / (û·n), if the ray heads into it (û·n < 0) and the point lies
// on the side. A ray that starts inside leaves through the side it reaches first.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/kind_method.h"
#include "geometry/ray_square.h"

namespace epure::kinds {

namespace {

using exact::Rational;
using exact::Surd;
using geo::Face;
using geo::Point2;
using geo::Vec2;

struct Data {
  Point2 A;
  Vec2 u;
};

// Axis directions and Pythagorean triples: û, t and I rational at the easy level.
constexpr Vec2 kEasyDirections[] = {{1, 0}, {0, 1}, {2, 0}, {0, 3},  {3, 4},
                                    {4, 3}, {6, 8}, {8, 6}, {5, 12}, {12, 5}};

using square::bit_of;
using square::index_of;
using square::kSides;
using square::kStepJ;
using square::kStepT;
using square::kStepUn;

double coord(Point2 p, int axis) { return axis == 0 ? p.x : p.y; }
Vec2 normal_of(Face f) { return f.axis == 0 ? Vec2{double(f.sign), 0} : Vec2{0, double(f.sign)}; }
const char* axis_name(int axis) { return axis == 0 ? "x" : "y"; }

geo::RaySquare solve_core(const Data& d) { return geo::intersect_canonical_square(geo::Ray2::unit(d.A, d.u)); }

std::string branch_of(const geo::RaySquare& rs) {
  if (rs.inside) return "inside";
  return rs.hit ? "hit" : "miss";
}

// A side the method looks at: a candidate from outside, a side the ray heads towards from inside.
struct Side {
  Face face;
  double u_n;                  // û·n
  std::optional<double> t;     // where the ray crosses the side's line, when it heads to it
  std::optional<Point2> J;     // that crossing
};

std::vector<Side> sides_in_play(const Data& d, const geo::RaySquare& rs) {
  const Vec2 uh = d.u / geo::norm(d.u);
  std::vector<Side> out;
  for (Face f : kSides) {
    const Vec2 n = normal_of(f);
    const double u_n = geo::dot(uh, n);
    Side s{f, u_n, std::nullopt, std::nullopt};
    if (rs.inside ? !(u_n > 0) : !rs.faces.contains(f)) continue;
    if (rs.inside || u_n < 0) {
      // (A + t·û)·n = 1
      s.t = (1 - geo::dot(geo::to_vec(d.A), n)) / u_n;
      s.J = d.A + *s.t * uh;
    }
    out.push_back(s);
  }
  return out;
}

using method::AnswerType;
constexpr std::string_view kFaceNames[] = {"+x", "+y", "-x", "-y"};


// The course's exercise 4, written once (method.h).
struct RaySquareMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "ray_square";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("u", d.u);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"faces", AnswerType::faces, 1, kFaceNames}, {"inside", AnswerType::boolean}, {"hit", AnswerType::boolean},
      {"t", AnswerType::number},                   {"I", AnswerType::point},        {"N", AnswerType::point}};

  // what the exercise is worth on every sheet, whatever the branch (the spec may say otherwise)
  static constexpr double kPoints = 6;

  static constexpr std::string_view kMistakes[] = {"faces_wrong_half_planes", "faces_inner_half_planes", "faces_from_direction",
                                                   "direction_not_unit", "normal_inward"};

  // The candidate sides are those whose closed outer half-plane holds A (A·n ≥ 1); on each the
  // ray heads into (û·n < 0), (A + t·û)·n = 1 gives t = (1 − A·n)/(û·n), and the crossing is
  // the hit when it lies on the side. From inside, the ray leaves through the side it reaches
  // first among those it heads to (û·n > 0). N is the side's normal: the side I lies on.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using N = typename M::Number;
    const auto A = m.in(d.A), u = m.in(d.u);
    const auto zero = m.in(0.0), one = m.in(1.0);
    auto coord = [](const auto& p, int axis) { return axis == 0 ? p.x : p.y; };
    auto along = [&](const auto& p, Face f) { return f.sign > 0 ? coord(p, f.axis) : -coord(p, f.axis); };

    method::FaceMask candidates = 0, opposite = 0, inner = 0, towards = 0;
    method::Cond inside{true};
    for (int i = 0; i < 4; ++i) {
      const Face f = kSides[i];
      const auto a_n = along(A, f);
      if (!less(a_n, one)) candidates |= bit_of(f), opposite |= bit_of({f.axis, -f.sign});
      if (!less(one, a_n)) inner |= bit_of(f);
      inside = inside && less(a_n, one);
      if (less(along(u, f), zero)) towards |= bit_of(f);
    }
    const method::Faces right{candidates};
    const auto faces = m.faces(
        "faces", m.mistake("faces_from_direction",
                           m.mistake("faces_inner_half_planes",
                                     m.mistake("faces_wrong_half_planes", right, method::Faces{opposite}),
                                     inside ? right : method::Faces{inner}),
                           method::Faces{towards}));
    const auto in = m.boolean("inside", inside);
    const auto length = m.note("norm_u", sqrt(dot(u, u)));
    const auto uh = m.round("u_hat", m.mistake("direction_not_unit", u / length, u));

    std::optional<N> best;
    method::Deps deps = faces.deps | in.deps;
    for (int i = 0; i < 4; ++i) {
      const Face f = kSides[i];
      const auto u_n = m.note(kStepUn[i], along(uh, f));
      const bool in_play = in ? !less_equal_zero(u_n) : (faces.bits & bit_of(f)) != 0;
      if (!in_play || (!in && !less(u_n, zero))) continue;
      const auto t = m.note(kStepT[i], (one - along(A, f)) / u_n);
      const auto J = m.note(kStepJ[i], A + t * uh);
      const auto other = coord(J, 1 - f.axis);
      const bool on_side = static_cast<bool>(!less(t, zero) && !less(one, method::magnitude(other)));
      if (on_side && (!best || less(t, *best))) best = t;
    }
    const auto hit = m.boolean("hit", method::Cond{best.has_value(), deps});
    if (!hit) return;
    const auto t = m.number("t", m.round("t", best ? *best : zero));
    const auto I = m.point("I", m.round("I", A + t * uh));
    // the side I lies on: its larger coordinate, in absolute value
    const bool on_x = static_cast<bool>(!less(method::magnitude(I.x), method::magnitude(I.y)));
    const auto sign = [&](const auto& c) { return less(c, zero) ? -one : one; };
    const auto no = I.x - I.x;  // carries I's dependencies into N, at no cost to its value
    const typename M::Vec n{m.either(no + (on_x ? sign(I.x) : zero), on_x ? sign(I.x) : zero),
                            m.either(no + (on_x ? zero : sign(I.y)), on_x ? zero : sign(I.y))};
    m.point("N", m.mistake("normal_inward", n, -n));
  }

  static CoreAnswers core(const Data& d) {
    const auto rs = solve_core(d);
    method::FaceMask bits = 0;
    rs.faces.for_each([&](Face f) { bits |= bit_of(f); });
    CoreAnswers a;
    a.faces("faces", bits).boolean("inside", rs.inside).boolean("hit", rs.hit.has_value());
    if (rs.hit) a.number("t", rs.hit->t).point("I", rs.hit->I).vec("N", rs.hit->N);
    return a;
  }

 private:
  template <class T>
  static bool less_equal_zero(const T& x) {
    return !(method::value(x) > 0);
  }
};

class RaySquareKind final : public MethodKind<RaySquareMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 3}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override {
    return {
        {"corner_margin", 0.15},  // a crossing at least this far from a side's ends (on or off it)
        {"side_margin", 0.5},     // each coordinate of A at least this far from ±1
        {"t_min", 0.5},           // the hit at least this far along the ray
        {"min_cos", 0.2},         // |û·n| of a side in play at least this, unless exactly 0
    };
  }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}, {"N", 0, "I"}}; }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    const bool inside = ctx.branch == "inside";
    const double cm = constraint(ctx, *this, "corner_margin");
    const double sm = constraint(ctx, *this, "side_margin");
    const double t_min = constraint(ctx, *this, "t_min") / (hard ? 2 : 1);
    const double min_cos = constraint(ctx, *this, "min_cos");
    // hard: near a corner or grazing a side's end, yet on the clear side of these margins
    const double cm_clear = hard ? cm / 3 : cm, sm_clear = hard ? sm / 5 : sm;
    const double graze = cm + 0.1;

    auto accept = [&](const Data& x) {
      const auto rs = solve_core(x);
      if (branch_of(rs) != ctx.branch) return false;
      for (int k = 0; k < 2; ++k)
        if (std::abs(std::abs(coord(x.A, k)) - 1) < sm_clear) return false;
      if (rs.hit && rs.hit->t < t_min) return false;
      double closest = 1e9;  // how near a decisive crossing comes to a side's end
      for (const Side& s : sides_in_play(x, rs)) {
        if (std::abs(s.u_n) < min_cos && s.u_n != 0) return false;  // nearly parallel to the side
        if (!s.J) continue;
        const double other = std::abs(coord(*s.J, 1 - s.face.axis));
        const bool decisive = rs.face && *rs.face == s.face;
        if (decisive) {
          if (other > 1 - cm_clear) return false;
          closest = std::min(closest, 1 - other);
        } else if (!rs.inside) {
          if (other < 1 + cm_clear) return false;
          closest = std::min(closest, other - 1);
        }
      }
      if (!hard) return true;
      const bool grazing = closest <= graze;
      if (rs.inside)
        return grazing || std::max(std::abs(x.A.x), std::abs(x.A.y)) >= 1 - sm;
      // A in a corner region close to the corner (two candidates), or close to its only
      // candidate side
      const double ax = std::abs(x.A.x), ay = std::abs(x.A.y);
      const bool near_corner = ax > 1 && ay > 1 && ax <= 1.8 && ay <= 1.8;
      const bool near_side = std::min(ax > 1 ? ax : 9.0, ay > 1 ? ay : 9.0) <= 1 + 3 * sm_clear;
      return grazing || near_corner || near_side;
    };

    const Data d = draw_until(200000, "ray_square (branch, corner and side margins, t range)",
                              [&]() -> std::optional<Data> {
      Data x;
      // Widened (a large set has used up the usual ranges): A further out, finer steps inside,
      // longer directions.
      const int w = ctx.widening;
      if (inside && !hard) {
        // A grid of 1/(2w + 2), strictly inside: unwidened, half a grid step (the only integer
        // point strictly inside is the centre)
        const std::int64_t k = 2 * w + 1;
        x.A = {double(rng.integer(-k, k)) / double(k + 1), double(rng.integer(-k, k)) / double(k + 1)};
      } else if (inside) {
        x.A = {grid_value(rng, -0.9, 0.9, level), grid_value(rng, -0.9, 0.9, level)};
      } else {
        const double reach = 4 + 2 * w;
        x.A = {grid_value(rng, -reach, reach, level), grid_value(rng, -reach, reach, level)};
      }
      if (level == Difficulty::easy) {
        x.u = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
        if (rng.chance(0.5)) x.u.x = -x.u.x;
        if (rng.chance(0.5)) x.u.y = -x.u.y;
      } else {
        const double m = (hard ? 3 : 4) + 2 * w;
        x.u = {grid_value(rng, -m, m, level), grid_value(rng, -m, m, level)};
        if (geo::norm(x.u) < 1) return std::nullopt;
      }
      if (!accept(x)) return std::nullopt;
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
    const auto sides = sides_in_play(d, rs);

    ExerciseInstance inst = begin_instance(d, ctx);
    KeySolution key = solve(d, ctx);
    const Questions& q = key.questions;
    inst.questions = key.questions.take_questions();
    std::vector<std::string> faces;
    rs.faces.for_each([&](Face f) { faces.emplace_back(face_label(geo::face_name(f))); });
    std::optional<Surd> t_exact, ix_exact, iy_exact;
    if (rs.hit) t_exact = key.exact("t"), ix_exact = key.exact_x("I"), iy_exact = key.exact_y("I");
    auto side_exact = [&](std::string_view id) -> std::optional<Surd> {
      const auto* r = key.run.step(id);
      return r ? r->x.e : std::nullopt;
    };

    const TextVars data_vars = {{"A", N.point(d.A.x, d.A.y)}, {"u", N.point(d.u.x, d.u.y)}};
    // ---- the sheet
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      inst.sheet = begin_sheet_section(ctx, "ray_square.title");
      inst.sheet.add(render::Paragraph{T.format("ray_square.statement", data_vars)});
      inst.sheet.add(render::Figure{question_scene(d, ctx), 0.5});
      add_fields(inst.sheet, q);
    }

    // ---- the key, as the course: candidate sides, then each one in turn
    inst.key = begin_key_section(ctx, "ray_square.title");
    inst.key.add(render::Paragraph{T.format("ray_square.data", data_vars)});
    auto step = [&](std::string_view key, const TextVars& vars = {}) {
      inst.key.add(render::Paragraph{T.format(fmt::format("ray_square.step.{}", key), vars)});
    };
    for (int k = 0; k < 2; ++k) {
      const double a = coord(d.A, k);
      const char* where = rs.faces.contains({k, +1}) ? "plus" : rs.faces.contains({k, -1}) ? "minus" : "none";
      step(fmt::format("axis.{}", where), {{"c", axis_name(k)},
                                           {"v", N.datum(a)},
                                           {"face", face_label(geo::face_name({k, a > 0 ? +1 : -1}))}});
    }
    if (rs.inside) {
      step("no_candidate");
    } else {
      std::string list;
      for (const auto& f : faces) list += fmt::format("{}{}", list.empty() ? "" : ", ", f);
      step("candidates", {{"faces", list}});
    }
    const Vec2 uh = d.u / geo::norm(d.u);
    step("unit", {{"norm_u", step_value(ctx, geo::norm(d.u), key.exact("norm_u"))},
                  {"u_hat", step_point(ctx, geo::to_point(uh), key.exact_x("u_hat"), key.exact_y("u_hat"))}});
    for (const Side& s : sides) {
      const int i = index_of(s.face);
      struct {
        std::optional<Surd> u_n, t, jx, jy;
      } ex{side_exact(kStepUn[i]), side_exact(kStepT[i]), std::nullopt, std::nullopt};
      if (const auto* J = key.run.step(kStepJ[i])) ex.jx = J->x.e, ex.jy = J->y.e;
      const bool hit_here = rs.face && *rs.face == s.face;
      const Vec2 n = normal_of(s.face);
      // the side hit shows the core's values; the others their exact values (or the formula's)
      const double t = hit_here ? rs.hit->t : s.t.value_or(0);
      const Point2 J = hit_here ? rs.hit->I : s.J.value_or(Point2{});
      const TextVars vars = {{"face", face_label(geo::face_name(s.face))},
                             {"n", N.point(n.x, n.y)},
                             {"un", step_value(ctx, s.u_n, ex.u_n)},
                             {"t", step_value(ctx, t, ex.t)},
                             {"I", step_point(ctx, J, ex.jx, ex.jy)}};
      if (rs.inside) {
        step("exit_side", vars);
        continue;
      }
      step("side", vars);
      if (!s.J) {
        step("side_away");
        continue;
      }
      step("side_cross", vars);
      const int other = 1 - s.face.axis;
      const std::optional<Surd>& other_exact = other == 0 ? ex.jx : ex.jy;
      const double v = coord(J, other);
      step(hit_here ? "side_on" : "side_off",
           {{"c", axis_name(other)},
            {"v", step_value(ctx, std::abs(v), other_exact ? std::optional<Surd>(v < 0 ? -*other_exact : *other_exact)
                                                      : std::nullopt)}});
    }
    if (rs.hit) {
      const TextVars vars = {{"face", face_label(geo::face_name(*rs.face))},
                             {"t", step_value(ctx, rs.hit->t, t_exact)},
                             {"I", step_point(ctx, rs.hit->I, ix_exact, iy_exact)},
                             {"N", N.point(rs.hit->N.x, rs.hit->N.y)}};
      step(rs.inside ? "exit" : "hit", vars);
    } else {
      step("miss");
    }
    inst.key.add(render::Figure{key_scene(d, rs, sides, ctx), 0.45});
    add_lines(inst.key, q);
    return inst;
  }

  static render::Panel data_panel(const Data& d) {
    render::Panel panel;
    const double m = std::ceil(std::max({2.0, std::abs(d.A.x), std::abs(d.A.y)}) + 1);
    panel.view = {-m, -m, m, m};
    panel.add(render::Grid{1, true});
    return panel;
  }

  static std::vector<render::P2> corners() { return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; }

  render::Scene question_scene(const Data& d, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("ray_square.title");
    s.description = ctx.texts.get("ray_square.figure.question");
    render::Panel panel = data_panel(d);
    panel.add(render::Polygon{corners(), true, render::Role::data, false});
    panel.add(render::Ray{p2(d.A), p2(d.u), render::Role::data});
    panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
    s.panels.push_back(std::move(panel));
    return s;
  }

  render::Scene key_scene(const Data& d, const geo::RaySquare& rs, const std::vector<Side>& sides,
                          const ExerciseContext& ctx) const {
    using render::Role;
    const auto& T = ctx.texts;
    render::Scene s;
    s.title = T.get("ray_square.title");
    s.description = T.get(fmt::format("ray_square.figure.key.{}", branch_of(rs)));
    render::Panel panel = data_panel(d);
    const Vec2 uh = d.u / geo::norm(d.u);
    auto in_view = [&](Point2 p) {
      return p.x > panel.view.x_min && p.x < panel.view.x_max && p.y > panel.view.y_min && p.y < panel.view.y_max;
    };
    // the sides' supporting lines where the method crosses them off the side
    for (const Side& side : sides)
      if (side.J && !(rs.face && *rs.face == side.face)) {
        const Vec2 n = normal_of(side.face);
        panel.add(render::Line{p2(geo::to_point(n)), p2(geo::to_point(n) + geo::perp(n)), Role::construction});
      }
    // the four sides: those in play highlighted, the others greyed
    for (Face f : kSides) {
      const bool in_play = std::any_of(sides.begin(), sides.end(), [&](const Side& x) { return x.face == f; });
      const Vec2 n = normal_of(f), along = geo::perp(n);
      const Point2 mid = geo::to_point(n);
      panel.add(render::Segment{p2(mid - along), p2(mid + along), in_play ? Role::highlight : Role::muted});
    }
    panel.add(render::Ray{p2(d.A), p2(d.u), Role::data});
    panel.add(render::Arrow{p2(d.A), p2(d.A + uh), Role::construction});
    panel.add(render::Label{T.get("ray_square.figure.u_hat"), p2(d.A + uh), render::Side::auto_, Role::construction});
    for (const Side& side : sides)
      if (side.J && !(rs.face && *rs.face == side.face) && in_view(*side.J))
        panel.add(render::PointMark{p2(*side.J), Role::construction,
                                    render::Label{T.get("ray_square.figure.off_side"), p2(*side.J),
                                                  render::Side::auto_, Role::construction}});
    panel.add(render::PointMark{p2(d.A), Role::data, render::Label{"A", p2(d.A)}});
    if (rs.hit) {
      const Point2 I = rs.hit->I;
      panel.add(render::PointMark{p2(I), Role::result, render::Label{"I", p2(I), render::Side::auto_, Role::result}});
      panel.add(render::Arrow{p2(I), p2(I + rs.hit->N), Role::normal});
      panel.add(render::Label{T.get("ray_square.figure.N"), p2(I + rs.hit->N), render::Side::auto_, Role::normal});
    }
    s.panels.push_back(std::move(panel));
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_square_kind() {
  static const RaySquareKind kind;
  return kind;
}

}  // namespace epure::kinds
