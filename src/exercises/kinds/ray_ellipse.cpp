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
struct RayEllipse : Family<RayEllipse> {
  static constexpr std::string_view kName = "ray_ellipse";
  static constexpr std::string_view kSizes = "radii";
  // After the frame change's: the far root last, since it moves N too (at the flat ellipse's far
  // vertex N is −N, the normal inward, which names the answer better).
  static constexpr auto kMistakes = frame_mistakes_then<3>({"normal_wrong_transform", "far_intersection",
                                                         "near_root_inside"});

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
    using method::Shown;
    const Frame<M> f = frame_change(m, d);
    const auto one = m.in(1.0), zero = m.in(0.0);
    const auto ac2 = m.note("ac2", dot(f.Ac, f.Ac));
    const auto inside = m.boolean("inside", less(ac2, one));
    m.tell(inside ? "inside.yes" : "inside.no", {{"ac2", "ac2", Shown::equals}});
    const auto uu = dot(f.uc, f.uc);
    const auto t_proj = m.round("t_proj", -dot(f.Ac, f.uc) / uu);
    m.tell("t_proj", {{"t_proj", "t_proj", Shown::equals}});
    const auto Pc = m.note("Pc", f.Ac + t_proj * f.uc);
    const auto d2 = m.round("d2", dot(Pc, Pc));
    const auto ahead = !less(t_proj, zero);
    const auto hit = m.boolean("hit", inside || (ahead && less_equal(d2, one)));
    if (!hit && !ahead) {
      m.tell("behind");  // the course stops at once
      return;
    }
    m.tell("d2", {{"Pc", "Pc", Shown::shown}, {"d2", "d2", Shown::equals}});
    if (!hit) {
      m.tell("miss");
      return;
    }
    const auto half_chord = m.round("half_chord", sqrt(one - d2));
    const auto norm_uc = m.round("norm_uc", sqrt(uu));
    m.tell("pythagoras", {{"half_chord", "half_chord", Shown::equals}, {"norm_uc", "norm_uc", Shown::equals}});
    const auto near = t_proj - half_chord / norm_uc, far = t_proj + half_chord / norm_uc;
    // √((1 − d²)/(u_c·u_c)) as one root: an exact form more often than each root apart
    const auto along = sqrt((one - d2) / uu);
    const auto t = m.number(
        "t", m.round("t", inside ? m.either(m.mistake("near_root_inside", far, near), t_proj + along)
                                 : m.either(m.mistake("far_intersection", near, far), t_proj - along)));
    m.tell(inside ? "t.inside" : "t.outside", {{"t", "t", Shown::equals}});
    const auto Ic = m.round("Ic", f.Ac + t * f.uc);
    m.tell("Ic", {{"Ic", "Ic", Shown::shown}});
    back_to_world(m, f, t, Ic, Ic);
  }

  // the solve contract (solve/solve.h)
  static void contract(const Data& d, const solve::Fields& f, solve::Result& r) {
    solve_contract(d, ellipse_of(d), kSizes, f, r);
  }

  static CoreAnswers core(const Data& d) { return core_answers(geo::intersect(world_ray(d), ellipse_of(d))); }
  static constexpr Shape kShape = Shape::ellipse;
  static constexpr std::string_view kWhat = "branch, clearance from the ellipse, drawing area, aspect, conditioning";
  static geo::Ellipse figure_of(const Data& d) { return ellipse_of(d); }

  // Easy: t rational, so that I is too.
  static bool easy(const Data& d, const geo::RayEllipse& r, const ExerciseContext& ctx) {
    if (!r.hit) return true;
    const auto run = MethodKind<RayEllipse>::exact_run(d, ctx.decimals);
    const auto* t = run.answer("t");
    return t && t->x.e && t->x.e->is_rational();
  }

  // The branch asked, and a figure well away from its boundaries: A clearly in or out, the
  // canonical line clearly through or clearly beside the circle (or clearly pointing away).
  static bool clear(const geo::RayEllipse& r, std::optional<RayBranch> branch, const Limits& lim) {
    const Vec2 Ac = geo::to_vec(r.canonical_ray.origin);
    const double from_centre = geo::norm(Ac);
    if (std::max(std::abs(Ac.x), std::abs(Ac.y)) > lim.max_canonical) return false;
    if (branch == RayBranch::inside ? !r.inside || from_centre > 1 - lim.margin : from_centre < 1 + lim.margin)
      return false;
    const double d = std::sqrt(r.canonical.d2);
    if (branch == RayBranch::miss) {
      if (r.hit) return false;
      // behind or beside, told apart clearly; the half-line's nearest point to O is A_c or P_c
      const double t_proj_length = r.canonical.t_proj * geo::norm(r.canonical_ray.direction);
      if (std::abs(t_proj_length) < lim.margin) return false;
      return (t_proj_length > 0 ? d : from_centre) >= 1 + lim.margin;
    }
    if (!r.hit) return false;
    if (branch == RayBranch::hit && d > 1 - lim.margin) return false;  // steeper than min_incidence too
    return r.hit->t >= lim.min_gap;
  }

  // The canonical frame: the unit circle, A_c and the ray, the projection P_c of O with its right
  // angle, and with a hit the Pythagoras triangle O–P_c–I_c, I_c and N_c.
  static render::Panel canonical(const geo::RayEllipse& r) {
    const Solved s = solved_of(r);
    const geo::RayCircle& c = r.canonical;
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

KeySolution transformed::ellipse_key(const Data& d, const ExerciseContext& ctx) { return MethodKind<RayEllipse>::key_solution(d, ctx); }

const ExerciseKind& ray_ellipse_kind() { return the_kind<TransformedKind<RayEllipse>>(); }

}  // namespace epure::kinds
