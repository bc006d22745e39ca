// The course's open question "does this work for any rectangle?": yes, through the canonical
// square [-1,1]². The ray is carried into the square's frame by T⁻¹, the course's method (the
// candidate sides, each met where (A_c + t·u_c)·n = 1) solves it there, and the hit comes back
// with the normal by the inverse transpose.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kinds/box_family.h"
#include "exercises/kinds/transformed_common.h"
#include "geometry/box_faces.h"

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
// the side the ray heads to (|u_c·n| past box::kAlongFace·‖u_c‖).

struct SideTest {
  geo::Face face;
  std::optional<double> t;  // where the ray crosses the side's line, when it heads to it
  Point2 at;                // the ray's point there
};

std::vector<SideTest> side_tests(const geo::RayRectangle& r) {
  const Point2 Ac = r.canonical_ray.origin;
  const Vec2 uc = r.canonical_ray.direction;
  std::vector<SideTest> tests;
  const double tiny = box::kAlongFace * geo::norm(uc);
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

// The canonical square's steps in the rectangle's words: no step before a side's crossing.
constexpr box::FaceTexts kTexts = {"side.exit", "", "side.away", "", "side.on", "side.off", method::Shown::equals,
                                   method::Shown::shown};

// The ray and the rectangle, written once (method.h): the frame change and the way back are
// transformed_common's, the canonical part is the course's exercise 4 on the square.
struct RayRectangle : Family<RayRectangle> {
  static constexpr std::string_view kName = "ray_rectangle";
  static constexpr std::string_view kSizes = "half";
  // No normal_wrong_transform: a side's canonical normal lies along an axis, which S and S⁻¹
  // only stretch, so the normal carried by T and normalised is the right one.
  static constexpr auto kMistakes = frame_mistakes_then();

  // In the canonical frame, as the course's exercise 4 (the square): the candidate sides are
  // those whose closed outer half-plane holds A_c (A_c·n ≥ 1), A_c is inside when there is none;
  // on each side the ray heads into (u_c·n < 0; from inside, u_c·n > 0), (A_c + t·u_c)·n = 1
  // gives t = (1 − A_c·n)/(u_c·n), and the crossing is the hit when it lies on the side (the
  // nearest, from inside). N_c is the normal of the side I_c = A_c + t·u_c lies on. They round t.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using method::Shown;
    const Frame<M> f = frame_change(m, d);
    const auto one = m.in(1.0), zero = m.in(0.0);
    method::FaceMask candidates = 0;
    method::Cond inside{true};
    for (Face s : box::Space<2>::kFaces) {
      // the closed outer half-plane A_c·n ≥ 1, exactly where A_c is exact (A on a side's line)
      const method::Cond within = method::exactly_less(box::along(f.Ac, s), one);
      if (!within) candidates |= box::bit_of(s);
      inside = inside && within;
    }
    const auto in = m.boolean("inside", inside);
    m.note("candidates", method::Faces{candidates});
    m.tell(inside ? "inside.yes" : "inside.no", {{"faces", "candidates", Shown::faces}});
    // from inside the key goes axis by axis (+x, −x, +y, −y); from outside, the contract's order
    static constexpr int kAxisByAxis[] = {0, 2, 1, 3};
    const auto best = box::search_faces<2>(m, f.Ac, f.uc, static_cast<bool>(in), candidates, kTexts,
                                           in ? std::span<const int>(kAxisByAxis) : std::span<const int>());
    // whether it hits is read from A_c and u_c
    const method::Deps deps = in.deps | method::deps_of(f.Ac.x) | method::deps_of(f.Ac.y) |
                              method::deps_of(f.uc.x) | method::deps_of(f.uc.y);
    const auto hit = m.boolean("hit", method::Cond{best.has_value(), deps});
    if (!hit) {
      m.tell("no_hit");
      return;
    }
    const auto t = m.number("t", m.round("t", best ? *best : zero));
    const auto Ic = m.note("Ic", f.Ac + t * f.uc);
    const auto Nc = box::face_normal<2>(m, Ic);
    m.tell(inside ? "leaves" : "enters", {{"face", box::face_of_normal<2>(Nc), Shown::face},
                                          {"t", "t", Shown::equals},
                                          {"Nc", "Nc", Shown::shown}});
    back_to_world(m, f, t, Ic, Nc);
  }

  // the solve contract (solve/solve.h)
  static void contract(const Data& d, const solve::Fields& f, solve::Result& r) {
    solve_contract(d, rectangle_of(d), kSizes, f, r);
  }

  static CoreAnswers core(const Data& d) { return core_answers(geo::intersect(world_ray(d), rectangle_of(d))); }
  static constexpr Shape kShape = Shape::rectangle;
  static constexpr std::string_view kWhat =
      "branch, clearance from the sides and corners, drawing area, aspect, conditioning";
  static geo::Rectangle figure_of(const Data& d) { return rectangle_of(d); }

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

  // The branch asked, and a figure well away from its boundaries: A_c clearly in or out of the
  // square, every side the method tests clearly met or clearly missed (no corner), the side hit
  // met steeply, a miss clear of the corners.
  static bool clear(const geo::RayRectangle& r, std::optional<RayBranch> branch, const Limits& lim) {
    const Point2 Ac = r.canonical_ray.origin;
    const Vec2 uc = r.canonical_ray.direction;
    const double reach = std::max(std::abs(Ac.x), std::abs(Ac.y));
    if (reach > lim.max_canonical) return false;
    if (branch == RayBranch::inside ? !r.inside || reach > 1 - lim.margin : reach < 1 + lim.margin) return false;
    for (const SideTest& s : side_tests(r))
      if (s.t && std::abs(std::abs(along(s.at, 1 - s.face.axis)) - 1) < lim.margin) return false;
    if (branch == RayBranch::miss) {
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
};

}  // namespace

KeySolution transformed::rectangle_key(const Data& d, const ExerciseContext& ctx) { return MethodKind<RayRectangle>::key_solution(d, ctx); }

const ExerciseKind& ray_rectangle_kind() { return the_kind<TransformedKind<RayRectangle>>(); }

}  // namespace epure::kinds
