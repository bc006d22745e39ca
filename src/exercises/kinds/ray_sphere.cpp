// The course's exercise 3 in space: the first point where a ray meets a sphere, by the ball
// family's method (ball_family.h), every coordinate in space. The plane through the ray and C
// holds the whole construction: the key draws it in true size beside the 3D view, where it is
// exactly the 2D ray/circle figure. This file is the sphere's draw and diagrams.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/kinds/ball_family.h"
#include "exercises/kinds/space_common.h"

namespace epure::kinds {

namespace {

using geo::Point3;
using geo::Vec3;
using Data = ball::Data<3>;

// Directions of integer length: û and t_proj rational at the easy level (signs and the order of
// the components drawn on top).
constexpr Vec3 kEasyDirections[] = {{1, 0, 0}, {2, 0, 0}, {3, 4, 0}, {1, 2, 2}, {2, 3, 6}, {2, 1, 2}, {4, 4, 2}};

// The direction (below the horizontal, in radians) of the radius drawn in the 3D view.
constexpr double kRadiusAngle = 0.6;

struct RaySphere : ball::Family<3> {
  static constexpr std::string_view kName = "ray_sphere";
  static constexpr double kPoints = 8;
  static constexpr double kMaxRadius = 3, kRadiusLimit = 4;
  // after the method's steps: the plane of the ray and C, drawn in true size
  static constexpr std::string_view kAfter[] = {"plane"};

  // Widened (a large set has used up the usual ranges): A and C further out.
  static std::optional<Data> draw(Rng& rng, const ExerciseContext& ctx, double r_lo, double r_hi) {
    const Difficulty level = ctx.spec.difficulty;
    const double w = 2 * ctx.widening;
    Data x;
    x.r = grid_value(rng, r_lo, r_hi, level);
    x.C = {grid_value(rng, -3 - w, 3 + w, level), grid_value(rng, -3 - w, 3 + w, level), grid_value(rng, 0, 3 + w, level)};
    x.A = {grid_value(rng, -6 - w, 6 + w, level), grid_value(rng, -6 - w, 6 + w, level), grid_value(rng, -1 - w, 6 + w, level)};
    if (level == Difficulty::easy) {
      x.u = space::easy_direction(rng, kEasyDirections);
    } else {
      const double m = level == Difficulty::hard ? 3 : 4;
      x.u = {grid_value(rng, -m, m, level), grid_value(rng, -m, m, level), grid_value(rng, -m, m, level)};
      if (geo::norm(x.u) < 1) return std::nullopt;
    }
    return x;
  }
  static bool in_area(const geo::RaySphere& rs, const ExerciseContext& ctx) {
    const double w = 2 * ctx.widening;
    return !(std::abs(rs.P.x) > 7 + w || std::abs(rs.P.y) > 7 + w || rs.P.z < -3 - w || rs.P.z > 8 + w);
  }
  static render::Figure sheet_figure(const Data& d, const geo::RaySphere& rs, const ExerciseContext& ctx) {
    return {question_scene(d, rs, ctx), 0.5};
  }
  static render::Figure key_figure(const Data& d, const geo::RaySphere& rs, const ExerciseContext& ctx) {
    return {key_scene(d, rs, ball::branch_of(rs), ctx), 0.95};
  }

  // The 3D view with the data: the sphere's outline, the ray (dashed where the sphere hides it),
  // A and C.
  static render::Panel view(const Data& d, const geo::RaySphere& rs, const render::Camera& cam, bool key) {
    using render::Role;
    using space::p3;
    const Vec3 uh = d.u / geo::norm(d.u);
    const double reach = std::max(rs.t_proj, 0.0) + d.r + 2;
    const Point3 end = d.A + reach * uh;
    std::vector<render::P3> pts = {p3(d.A), p3(end), p3(d.C + Vec3{d.r, d.r, d.r}), p3(d.C + Vec3{-d.r, -d.r, -d.r})};
    if (key) pts.push_back(p3(rs.P));
    const render::Ball ball{p3(d.C), d.r};
    render::Panel panel = space::view_panel(cam, pts, 4, 1.5, ball);
    // the sphere's outline: the circle of radius r around C's projection, inside the view
    const render::P2 c = cam.project(p3(d.C));
    panel.view.x_min = std::min(panel.view.x_min, std::floor(c.x - d.r - 0.5));
    panel.view.x_max = std::max(panel.view.x_max, std::ceil(c.x + d.r + 0.5));
    panel.view.y_min = std::min(panel.view.y_min, std::floor(c.y - d.r - 0.5));
    panel.view.y_max = std::max(panel.view.y_max, std::ceil(c.y + d.r + 0.5));
    space::add_drop(panel, cam, p3(d.A));
    space::add_drop(panel, cam, p3(d.C));
    panel.add(render::Circle{cam.project(p3(d.C)), d.r, Role::data});
    // a radius parallel to the picture, hence in true size: the figure's scale
    const render::P2 rim{c.x + d.r * std::cos(-kRadiusAngle), c.y + d.r * std::sin(-kRadiusAngle)};
    panel.add(render::Segment{c, rim, Role::construction, false});
    panel.add(render::Label{"r", {(c.x + rim.x) / 2, (c.y + rim.y) / 2}, render::Side::auto_, Role::construction});
    if (key) render::add_segment(panel, cam, p3(rs.P), p3(d.C), Role::construction, ball);
    // behind: the ray's line back to P, which lies before A
    if (key && rs.t_proj < 0) render::add_segment(panel, cam, p3(rs.P), p3(d.A), Role::construction, ball);
    render::add_segment(panel, cam, p3(d.A), p3(end), Role::data, ball);
    panel.add(render::Arrow{cam.project(p3(d.A)), cam.project(p3(d.A + uh)), Role::construction});
    panel.add(render::Label{"û", cam.project(p3(d.A + uh)), render::Side::auto_, Role::construction});
    panel.add(render::PointMark{cam.project(p3(d.C)), Role::data, render::Label{"C", cam.project(p3(d.C))}});
    panel.add(render::PointMark{cam.project(p3(d.A)), Role::data, render::Label{"A", cam.project(p3(d.A))}});
    return panel;
  }

  static render::Scene question_scene(const Data& d, const geo::RaySphere& rs, const ExerciseContext& ctx) {
    render::Scene s;
    s.title = ctx.texts.get("ray_sphere.title");
    s.description = ctx.texts.get("ray_sphere.figure.question");
    render::Panel panel = view(d, rs, space::camera(), false);
    panel.caption = ctx.texts.get("ray_sphere.figure.view");
    s.panels.push_back(std::move(panel));
    return s;
  }

  static render::Scene key_scene(const Data& d, const geo::RaySphere& rs, RayBranch branch,
                          const ExerciseContext& ctx) {
    using render::P2;
    using render::Role;
    using space::p3;
    const auto& T = ctx.texts;
    const render::Camera cam = space::camera();
    render::Scene s;
    s.title = T.get("ray_sphere.title");
    s.description = T.get(fmt::format("ray_sphere.figure.key.{}", name(branch)));
    render::Panel v3 = view(d, rs, cam, true);
    v3.add(render::PointMark{cam.project(p3(rs.P)), Role::construction,
                             render::Label{"P", cam.project(p3(rs.P)), render::Side::auto_, Role::construction}});
    if (rs.hit) {
      const P2 I = cam.project(p3(rs.hit->I));
      v3.add(render::PointMark{I, Role::result, render::Label{"I", I, render::Side::auto_, Role::result}});
      const P2 tip = cam.project(p3(rs.hit->I + rs.hit->N));
      v3.add(render::Arrow{I, tip, Role::normal});
      v3.add(render::Label{T.get("ray_sphere.figure.N"), tip, render::Side::auto_, Role::normal});
    }
    v3.caption = T.get("ray_sphere.figure.view");
    s.panels.push_back(std::move(v3));

    // The plane of the ray and C in true size: A at the origin, û along the first axis, C above
    // it at the height d (the core's t_proj and d²).
    const double dd = std::sqrt(rs.d2);
    const P2 A{0, 0}, C{rs.t_proj, dd}, P{rs.t_proj, 0};
    render::Panel plane;
    std::vector<P2> pts = {A, {1, 0}, {C.x - d.r, C.y - d.r}, {C.x + d.r, C.y + d.r}, P};
    // With an impact, the dimension of PI is set under the ray, where the circle's lower arc
    // leaves a narrow lens: a row under the circle is room for its label (0.6 of a unit left a
    // short PI's label against the frame: builtin:3d, seed 509, sheet 0).
    if (rs.hit) pts.push_back({P.x, C.y - d.r - 1.0});
    plane.view = view_around(pts, 1.0, 5.0);
    plane.add(render::Grid{1, false});
    auto outward = [](P2 a, P2 b, P2 c) {
      return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0 ? -0.35 : 0.35;
    };
    plane.add(render::Line{A, {1, 0}, Role::construction});
    std::optional<P2> I;
    if (rs.hit) {
      I = P2{rs.hit->t, 0};
      plane.add(render::Polygon{{C, P, *I}, true, Role::construction, true});
    }
    plane.add(render::Circle{C, d.r, Role::data});
    plane.add(render::Ray{A, {1, 0}, Role::data, I});
    plane.add(render::Segment{C, P, Role::construction, true});
    plane.add(render::RightAngle{P, {0, 1}, {1, 0}, Role::construction});
    if (I) {
      plane.add(render::Dimension{C, P, T.get("ray_sphere.figure.d"), outward(C, P, *I), Role::construction});
      plane.add(render::Dimension{P, *I, T.get("ray_sphere.figure.h"), outward(P, *I, C), Role::construction});
      plane.add(render::Dimension{*I, C, T.get("ray_sphere.figure.r"), outward(*I, C, P), Role::construction});
    } else if (branch == RayBranch::miss) {
      const P2 R{C.x, C.y - d.r};
      plane.add(render::Segment{C, R, Role::construction});
      plane.add(render::Dimension{C, P, T.get("ray_sphere.figure.d"), 0.35, Role::construction});
      plane.add(render::Dimension{C, R, T.get("ray_sphere.figure.r"), -0.35, Role::construction});
    } else {
      plane.add(render::Tick{A, {1, 0}, std::string("0"), Role::construction});
      plane.add(render::Tick{P, {1, 0}, T.get("ray_sphere.figure.t_proj_negative"), Role::construction});
    }
    plane.add(render::PointMark{C, Role::data, render::Label{"C", C}});
    plane.add(render::PointMark{A, Role::data, render::Label{"A", A}});
    plane.add(render::PointMark{P, Role::construction, render::Label{"P", P, render::Side::auto_, Role::construction}});
    if (I) {
      plane.add(render::PointMark{*I, Role::result, render::Label{"I", *I, render::Side::auto_, Role::result}});
      const P2 tip{I->x + (I->x - C.x) / d.r, I->y + (I->y - C.y) / d.r};
      plane.add(render::Arrow{*I, tip, Role::normal});
      plane.add(render::Label{T.get("ray_sphere.figure.N"), tip, render::Side::auto_, Role::normal});
    }
    plane.caption = T.get("ray_sphere.figure.plane");
    s.panels.push_back(std::move(plane));
    s.links = {T.get("ray_sphere.figure.link")};
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_sphere_kind() { return the_kind<ball::BallKind<RaySphere>>(); }

}  // namespace epure::kinds
