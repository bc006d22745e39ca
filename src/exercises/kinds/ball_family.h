#pragma once
// The course's exercise 3 as one figure family, written once over the number type and the
// dimension: a ray and a ball (the circle; in space, the sphere). Project C on the ray (t_proj,
// P), the early rejections in the course's order (behind: A outside and t_proj < 0; miss:
// d² > r²), then Pythagoras in the triangle C–P–I (PI = √(r² − d²)), I, and the normal
// N = (I − C)/r. Unlike the course's code, a ray that starts inside the ball hits it, on its way
// out. A kind of this family (the circle's file, the sphere's) is its name, its draw and its
// scenes; the schema, the questions, the method with its mistakes and roads, the key's
// worked steps, the solve contract and the draw's clearances are the family's.
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "exercises/kind_method.h"
#include "exercises/kinds/dimension.h"
#include "exercises/kinds/ray_branch.h"
#include "geometry/ray_3d.h"
#include "geometry/ray_circle.h"
#include "solve/result.h"

namespace epure::kinds::ball {

// What differs between the plane and space: the core's types (dimension.h: its point, vector,
// ray and step names; here its ball and result), and how a point is asked and recorded (in the
// plane one point answer "I" with I.x and I.y; in space three numbers).
template <int Dim>
struct Space;

template <>
struct Space<2> : Dimension<2> {
  using Ball = geo::Circle;
  using Result = geo::RayCircle;
  static constexpr Name AC = "AC", u_hat = "u_hat", P = "P", I = "I", N = "N";
  static constexpr std::string_view kReasons[] = {"behind", "miss"};
  static constexpr method::QuestionDecl kQuestions[] = {
      {"t_proj", method::AnswerType::number}, {"d2", method::AnswerType::number},
      {"inside", method::AnswerType::boolean}, {"hit", method::AnswerType::boolean},
      {"t", method::AnswerType::number},      {"I", method::AnswerType::point},
      {"N", method::AnswerType::point},
      {"reason", method::AnswerType::choice, method::kTickWork, kReasons}};
};

template <>
struct Space<3> : Dimension<3> {
  using Ball = geo::Sphere;
  using Result = geo::RaySphere;
  static constexpr Name AC = {"AC.x", "AC.y", "AC.z"}, u_hat = {"u_hat.x", "u_hat.y", "u_hat.z"},
                        P = {"P.x", "P.y", "P.z"}, I = {"I.x", "I.y", "I.z"}, N = {"N.x", "N.y", "N.z"};
  static constexpr std::string_view kReasons[] = {"behind", "miss"};
  static constexpr method::QuestionDecl kQuestions[] = {
      {"t_proj", method::AnswerType::number},  {"d2", method::AnswerType::number},
      {"inside", method::AnswerType::boolean}, {"hit", method::AnswerType::boolean},
      {"t", method::AnswerType::number},
      {"I.x", method::AnswerType::number, method::kCoordinateWork},
      {"I.y", method::AnswerType::number, method::kCoordinateWork},
      {"I.z", method::AnswerType::number, method::kCoordinateWork},
      {"N.x", method::AnswerType::number, method::kCoordinateWork},
      {"N.y", method::AnswerType::number, method::kCoordinateWork},
      {"N.z", method::AnswerType::number, method::kCoordinateWork},
      {"reason", method::AnswerType::choice, method::kTickWork, kReasons}};
};

template <int Dim>
struct Data {
  typename Space<Dim>::Point A;
  typename Space<Dim>::Vec u;
  typename Space<Dim>::Point C;
  double r = 0;
};

// The core's solution of the figure, on the unit ray (t a length).
template <int Dim>
typename Space<Dim>::Result solve_core(const Data<Dim>& d) {
  using S = Space<Dim>;
  return geo::intersect(S::Ray::unit(d.A, d.u), typename S::Ball{d.C, d.r});
}

// The branch the core's solution shows: inside, hit, behind or miss.
template <class Result>
RayBranch branch_of(const Result& r) {
  if (r.inside) return RayBranch::inside;
  if (r.hit) return RayBranch::hit;
  return *r.reason == geo::NoHit::behind ? RayBranch::behind : RayBranch::miss;
}

// (a∧b)²: the square of the plane's cross product, the squared norm of space's.
template <class T>
T squared_norm_of_cross(const method::V2<T>& a, const method::V2<T>& b) {
  const T c = cross(a, b);
  return c * c;
}
template <class T>
T squared_norm_of_cross(const method::V3<T>& a, const method::V3<T>& b) {
  return norm2(cross(a, b));
}

// The family, for MethodKind (kind_method.h): a kind adds its kName and kPoints.
template <int Dim>
struct Family {
  using Data = ball::Data<Dim>;
  using S = Space<Dim>;

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("u", d.u, role::from("A"));
    v("C", d.C);
    v("r", d.r, role::radius_about("C"));
  }

  static constexpr auto& kQuestions = S::kQuestions;
  static constexpr std::string_view kRoads[] = {"pythagoras_apc", "cross_product"};
  static constexpr std::string_view kMistakes[] = {"direction_not_unit", "far_intersection", "near_root_inside",
                                                   "normal_not_unit", "normal_inward"};

  // The student's road, in the course's order: û, t_proj = û·AC, P = A + t_proj·û, d² = CP²,
  // then Pythagoras in C–P–I, t = t_proj ∓ √(r² − d²), I = A + t·û, N = (I − C)/r. They round
  // û, t_proj, P, d², PI, t and I on the way. The key's worked steps are told as the method
  // reaches them.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using method::less_equal;
    using method::Shown;
    const auto A = m.in(d.A), C = m.in(d.C), u = m.in(d.u);
    const auto r = m.in(d.r), zero = m.in(0.0), one = m.in(1.0);
    const auto AC = m.note(S::AC, C - A);
    const auto ac2 = m.note("ac2", norm2(AC));
    const auto r2 = m.note("r2", r * r);
    m.tell("AC", {{"AC", "AC", Shown::data}, {"ac2", "ac2"}, {"r2", "r2"}});
    const auto inside = m.boolean("inside", less(ac2, r2));
    m.tell(inside ? "inside.yes" : "inside.no");
    const auto n = dot(u, u);
    const auto length = m.note("norm_u", sqrt(n));
    const auto uh = m.round(S::u_hat, m.mistake("direction_not_unit", u / length, u));
    m.tell("unit", {{"norm_u", "norm_u"}, {"u_hat", "u_hat", Shown::point}});
    const auto t_proj = m.number("t_proj", m.round("t_proj", dot(uh, AC)));
    m.tell("t_proj", {{"t_proj", "t_proj"}});
    const auto ahead = !less(t_proj, zero);
    m.tell(inside ? "ahead.inside" : ahead ? "ahead.outside" : "behind");
    if (!(inside || ahead)) {
      // "si t ≤ 0, on arrête": the course eliminates the useless case at once, and so does the
      // sheet: nothing past t_proj is asked
      m.boolean("hit", inside || ahead);
      m.choice("reason", method::pick(ahead, "miss", "behind"));
      return;
    }
    const auto P = m.round(S::P, A + t_proj * uh);
    m.tell("P", {{"P", "P", Shown::point}});
    // d² = CP², or by Pythagoras in the triangle A–P–C: AC² − t_proj², or as the course
    // computes it, the squared cross product (û∧AC)² (the area of the parallelogram on û and AC
    // over a base of length 1), which does not go through t_proj
    const auto d2 = m.number(
        "d2", m.round("d2", m.road("cross_product",
                                   m.road("pythagoras_apc", norm2(P - C), ac2 - t_proj * t_proj),
                                   squared_norm_of_cross(uh, AC))));
    m.tell("d2", {{"d2", "d2"}});
    const auto hit = m.boolean("hit", inside || (ahead && less_equal(d2, r2)));
    if (!hit) {
      m.choice("reason", method::pick(ahead, "miss", "behind"));
      m.tell("miss", {{"d2", "d2"}, {"r2", "r2"}});
      return;
    }
    const auto h2 = r2 - d2;
    const auto h = m.round("h", sqrt(h2));
    m.tell("pythagoras", {{"d2", "d2"}, {"r2", "r2"}, {"h", "h"}});
    // from outside the ray meets the near point first; from inside it leaves at the far one
    const auto t = m.number("t", m.round("t", inside ? m.mistake("near_root_inside", t_proj + h, t_proj - h)
                                                     : m.mistake("far_intersection", t_proj - h, t_proj + h)));
    m.tell(inside ? "t.inside" : "t.outside", {{"t", "t"}});
    // √(h²/u·u)·u: the same point as t·û, with an exact form more often
    const auto along = (inside ? one : -one) * sqrt(h2 / n);
    const auto I = m.point(S::I, m.round(S::I, m.either(A + t * uh, P + along * u)));
    m.tell("I", {{"I", "I", Shown::point}});
    const auto IC = I - C;
    m.point(S::N, m.mistake("normal_inward", m.mistake("normal_not_unit", IC / r, IC), -(IC / r)));
    m.tell("N", {{"N", "N", Shown::point}});
  }

  static CoreAnswers core(const Data& d) {
    const auto rc = solve_core(d);
    CoreAnswers a;
    a.number("t_proj", rc.t_proj);
    if (branch_of(rc) != RayBranch::behind) a.number("d2", rc.d2);  // the course stops behind at once
    a.boolean("inside", rc.inside).boolean("hit", rc.hit.has_value());
    if (rc.hit) a.number("t", rc.hit->t).point(S::I, rc.hit->I).vec(S::N, rc.hit->N);
    else a.choice("reason", geo::to_string(*rc.reason));
    return a;
  }

  // The solve contract: t_proj, d2, inside, hit; then t, I, N; else the reason.
  static void contract(const Data&, const solve::Fields& f, solve::Result& r) {
    const auto A = f.decimals<Dim>("A");
    const auto u = f.decimals<Dim>("u");
    const auto C = f.decimals<Dim>("C");
    const geo::Decimal& radius = f.decimal("r");
    const auto [direction, length] = solve::raw_direction(u);
    const auto c = geo::intersect_exact(A, direction, C, radius);
    solve::write_round(c, geo::printed_values(A, direction, C, radius, c, length), r);
  }
};

// ---- the draw ---------------------------------------------------------------------------------

// The draw's margins (the kind's constraints, as the spec sets them).
struct Margins {
  double tangent;   // |d/r − 1| at least this: a clear hit or a clear miss
  double boundary;  // |AC/r − 1| at least this: A clearly inside or outside
  double t_proj;    // |t_proj| at least this from outside: clearly ahead or behind
  double t_min;     // the hit at least this far along the ray
  double min_offset;  // d/r at least this: C off the ray's line, a real triangle C–P–I
};

// The constraints both kinds have, with their defaults (a kind adds its radii).
inline std::map<std::string, double> common_constraints(double max_radius) {
  return {{"tangent_margin", 0.15}, {"boundary_margin", 0.15}, {"t_proj_margin", 0.5}, {"t_min", 1.0},
          {"min_offset", 0.25},     {"min_radius", 2.0},       {"max_radius", max_radius}};
}

// The margins of a context; hard instances closer to the boundaries (t_proj and t_min a third).
inline Margins margins(const ExerciseContext& ctx, const ExerciseKind& kind) {
  const bool hard = ctx.spec.difficulty == Difficulty::hard;
  return {constraint(ctx, kind, "tangent_margin"), constraint(ctx, kind, "boundary_margin"),
          constraint(ctx, kind, "t_proj_margin") / (hard ? 3 : 1), constraint(ctx, kind, "t_min") / (hard ? 3 : 1),
          constraint(ctx, kind, "min_offset")};
}

// Whether the core's solution is the branch asked, clear of its boundaries: A clearly in or out,
// the line clearly through or beside the ball, t_proj clearly signed, the hit far enough along.
// Hard: close to tangency or to the ball, yet on the clear side of the margins (a quarter of the
// tangent margin, a third of the boundary's).
template <class Result>
bool clear(const Result& rc, double r, std::optional<RayBranch> branch, const Margins& mg, bool hard) {
  if (!branch || branch_of(rc) != *branch) return false;
  const double tm_clear = hard ? mg.tangent / 4 : mg.tangent, bm_clear = hard ? mg.boundary / 3 : mg.boundary;
  const double ac = geo::norm(rc.AC) / r;  // A's distance to C, in radii
  const double dr = std::sqrt(rc.d2) / r;   // the line's distance to C, in radii
  if (dr < mg.min_offset) return false;
  if (rc.inside) {
    if (ac > 1 - bm_clear || rc.hit->t < mg.t_min) return false;
    return !hard || ac >= 1 - mg.boundary;
  }
  if (ac < 1 + bm_clear || std::abs(dr - 1) < tm_clear) return false;
  const bool near_tangent = std::abs(dr - 1) <= mg.tangent, near_ball = ac <= 1 + mg.boundary;
  if (branch == RayBranch::behind) return rc.t_proj <= -mg.t_proj && (!hard || near_tangent || near_ball);
  if (rc.t_proj < mg.t_proj) return false;
  if (branch == RayBranch::miss) return !hard || near_tangent;
  return rc.hit->t >= mg.t_min && (!hard || near_tangent || near_ball);
}

// Easy: Pythagoras gives a rational PI (r² − d² the square of a rational), on the branches that
// reach it.
template <class Kind>
bool pythagorean(const typename Kind::Data& d, const ExerciseContext& ctx) {
  const auto branch = ray_branch(ctx.branch);
  if (ctx.spec.difficulty != Difficulty::easy || branch == RayBranch::behind || branch == RayBranch::miss) return true;
  const auto run = MethodKind<Kind>::exact_run(d);
  const auto* h = run.step("h");
  return h && h->x.e && h->x.e->is_rational();
}

// A kind of the family: MethodKind with the family's branches, constraints and draw loop. The
// kind (a Family<Dim> with kName, kPoints) adds, as static members:
//   kMaxRadius, kRadiusLimit                  the default largest radius, the largest allowed
//   std::optional<Data> draw(Rng&, ctx, r_lo, r_hi)   one attempt at the data
//   bool in_area(const Result&, ctx)          the construction inside the drawing area
//   render::Figure sheet_figure(d, result, ctx), key_figure(d, result, ctx)
//   kAfter                                    the key's steps after the method's (optional)
//   std::vector<DrawnField> kDrawn()          what a feedback sheet draws (optional)
template <class Kind>
class BallKind final : public MethodKind<Kind> {
 public:
  using Data = typename Kind::Data;

  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 3}, {"behind", 1}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override { return common_constraints(Kind::kMaxRadius); }
  std::vector<DrawnField> drawn() const override {
    if constexpr (requires { Kind::kDrawn(); }) return Kind::kDrawn();
    else return {};
  }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const bool hard = ctx.spec.difficulty == Difficulty::hard;
    const std::optional<RayBranch> branch = ray_branch(ctx.branch);
    const Margins mg = margins(ctx, *this);
    const double r_lo = constraint(ctx, *this, "min_radius");
    const double r_hi = constraint(ctx, *this, "max_radius");
    // the ball must fit in the drawing area
    if (!(r_lo > 0 && r_lo <= r_hi && r_hi <= Kind::kRadiusLimit))
      throw std::runtime_error(
          fmt::format("{}: need 0 < min_radius ≤ max_radius ≤ {}", Kind::kName, Kind::kRadiusLimit));
    const Data d = draw_until(200000, fmt::format("{} (branch, tangency and boundary margins, t range)", Kind::kName),
                              [&]() -> std::optional<Data> {
      const std::optional<Data> x = Kind::draw(rng, ctx, r_lo, r_hi);
      if (!x) return std::nullopt;
      const auto rc = solve_core(*x);
      if (!Kind::in_area(rc, ctx) || !clear(rc, x->r, branch, mg, hard) || !pythagorean<Kind>(*x, ctx) ||
          !this->answers_well_conditioned(*x, ctx.decimals))
        return std::nullopt;
      return x;
    });
    if (auto taken = already_taken(ctx, this->write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto rc = solve_core(d);
    std::span<const std::string_view> after;
    if constexpr (requires { Kind::kAfter; }) after = Kind::kAfter;
    return this->assemble(
        d, ctx, [&](const KeySolution&) { return Kind::sheet_figure(d, rc, ctx); },
        [&](const KeySolution&) { return Kind::key_figure(d, rc, ctx); }, after);
  }
};

}  // namespace epure::kinds::ball
