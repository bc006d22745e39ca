// Exercise 3 of the course: the first point where a ray meets a circle, by the ball family's
// method (ball_family.h: the projection P of C on the ray, the early rejections behind then
// miss, Pythagoras in C–P–I). This file is the circle's draw and diagrams.
#include <fmt/format.h>

#include <cmath>

#include "exercises/kinds/ball_family.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::Vec2;
using Data = ball::Data<2>;

// Directions of rational length (Pythagorean triples and axes), so that û and t_proj are
// rational at the easy level. Signs are drawn on top.
constexpr Vec2 kEasyDirections[] = {{1, 0}, {0, 1}, {2, 0}, {0, 2},  {3, 4},
                                    {4, 3}, {6, 8}, {8, 6}, {5, 12}, {12, 5}};

struct RayCircle : ball::Family<2> {
  static constexpr std::string_view kName = "ray_circle";
  // what the exercise adds to the sheet's total when the spec does not set its points (points.h:
  // the sheet's questions share that total by their work)
  static constexpr double kPoints = 7;
  // radii: the default largest, and the largest that fits the drawing area [-1, 11] × [-1, 9]
  static constexpr double kMaxRadius = 4, kRadiusLimit = 5;
  static std::vector<DrawnField> kDrawn() { return {{"I", 0, {}}, {"N", 0, "I", "\\vec{N}"}}; }

  static std::optional<Data> draw(Rng& rng, const ExerciseContext& ctx, double r_lo, double r_hi) {
    const Difficulty level = ctx.spec.difficulty;
    Data x;
    x.r = grid_value(rng, r_lo, r_hi, level);
    x.C = {grid_value(rng, x.r - 1, 11 - x.r, level), grid_value(rng, x.r - 1, 9 - x.r, level)};
    x.A = {grid_value(rng, 0, 10, level), grid_value(rng, 0, 8, level)};
    if (level == Difficulty::easy) {
      x.u = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
      if (rng.chance(0.5)) x.u.x = -x.u.x;
      if (rng.chance(0.5)) x.u.y = -x.u.y;
    } else {
      const double m = level == Difficulty::hard ? 3 : 4;
      x.u = {grid_value(rng, -m, m, level), grid_value(rng, -m, m, level)};
      if (geo::norm(x.u) < 1) return std::nullopt;
    }
    return x;
  }
  static bool in_area(const geo::RayCircle& rc, const ExerciseContext&) {
    return !(rc.P.x < -1 || rc.P.x > 11 || rc.P.y < -1 || rc.P.y > 9);
  }
  static render::Figure sheet_figure(const Data& d, const geo::RayCircle& rc, const ExerciseContext& ctx) {
    return {question_scene(d, rc, ctx), 0.55};
  }
  static render::Figure key_figure(const Data& d, const geo::RayCircle& rc, const ExerciseContext& ctx) {
    return {key_scene(d, rc, ball::branch_of(rc), ctx), 0.45};
  }

  static render::Panel data_panel(const Data& d, const geo::RayCircle& rc) {
    render::Panel panel;
    const Vec2 uh = d.u / geo::norm(d.u);
    panel.view = view_around({p2(d.A), p2(d.A + uh), {d.C.x - d.r, d.C.y - d.r},
                              {d.C.x + d.r, d.C.y + d.r}, p2(rc.P)},
                             1.0, 5.0);
    panel.add(render::Grid{1, true});
    return panel;
  }

  static render::Scene question_scene(const Data& d, const geo::RayCircle& rc, const ExerciseContext& ctx) {
    render::Scene s;
    s.title = ctx.texts.get("ray_circle.title");
    s.description = ctx.texts.get("ray_circle.figure.question");
    render::Panel panel = data_panel(d, rc);
    panel.add(render::Circle{p2(d.C), d.r, render::Role::data});
    panel.add(render::Ray{p2(d.A), p2(d.u), render::Role::data});
    panel.add(render::PointMark{p2(d.C), render::Role::data, render::Label{"C", p2(d.C)}});
    panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
    s.panels.push_back(std::move(panel));
    return s;
  }

  static render::Scene key_scene(const Data& d, const geo::RayCircle& rc, RayBranch branch,
                          const ExerciseContext& ctx) {
    using render::Role;
    const auto& T = ctx.texts;
    render::Scene s;
    s.title = T.get("ray_circle.title");
    s.description = T.get(fmt::format("ray_circle.figure.key.{}", name(branch)));
    render::Panel panel = data_panel(d, rc);
    const Vec2 uh = d.u / geo::norm(d.u);
    // a side a→b of the triangle gets its dimension on the side away from the third vertex c
    auto outward = [](Point2 a, Point2 b, Point2 c) { return geo::cross(b - a, c - a) > 0 ? -0.35 : 0.35; };

    // the ray's whole line: P may lie behind A
    panel.add(render::Line{p2(d.A), p2(d.A + d.u), Role::construction});
    if (rc.hit) {
      const Point2 I = rc.hit->I;
      panel.add(render::Polygon{{p2(d.C), p2(rc.P), p2(I)}, true, Role::construction, true});
    }
    panel.add(render::Circle{p2(d.C), d.r, Role::data});
    std::optional<render::P2> followed_to;
    if (rc.hit) followed_to = p2(rc.hit->I);
    panel.add(render::Ray{p2(d.A), p2(d.u), Role::data, followed_to});
    panel.add(render::Segment{p2(d.C), p2(rc.P), Role::construction, true});
    panel.add(render::RightAngle{p2(rc.P), p2(d.C - rc.P), p2(d.u), Role::construction});
    panel.add(render::Arrow{p2(d.A), p2(d.A + uh), Role::construction});
    panel.add(render::Label{T.get("ray_circle.figure.u_hat"), p2(d.A + uh), render::Side::auto_,
                            Role::construction});
    if (rc.hit) {
      const Point2 I = rc.hit->I;
      panel.add(render::Dimension{p2(d.C), p2(rc.P), T.get("ray_circle.figure.d"),
                                  outward(d.C, rc.P, I), Role::construction});
      panel.add(render::Dimension{p2(rc.P), p2(I), T.get("ray_circle.figure.h"),
                                  outward(rc.P, I, d.C), Role::construction});
      panel.add(render::Dimension{p2(I), p2(d.C), T.get("ray_circle.figure.r"),
                                  outward(I, d.C, rc.P), Role::construction});
    } else if (branch == RayBranch::miss) {
      // d > r: the radius towards P stops short of P
      const Vec2 to_P = rc.P - d.C;
      const Point2 R = d.C + (d.r / geo::norm(to_P)) * to_P;
      panel.add(render::Segment{p2(d.C), p2(R), Role::construction});
      panel.add(render::Dimension{p2(d.C), p2(rc.P), T.get("ray_circle.figure.d"), 0.35, Role::construction});
      panel.add(render::Dimension{p2(d.C), p2(R), T.get("ray_circle.figure.r"), -0.35, Role::construction});
    } else {
      // behind: P lies before A on the line, at a negative parameter
      panel.add(render::Tick{p2(d.A), p2(d.u), std::string("0"), Role::construction});
      panel.add(render::Tick{p2(rc.P), p2(d.u), T.get("ray_circle.figure.t_proj_negative"), Role::construction});
    }
    panel.add(render::PointMark{p2(d.C), Role::data, render::Label{"C", p2(d.C)}});
    panel.add(render::PointMark{p2(d.A), Role::data, render::Label{"A", p2(d.A)}});
    panel.add(render::PointMark{p2(rc.P), Role::construction,
                                render::Label{"P", p2(rc.P), render::Side::auto_, Role::construction}});
    if (rc.hit) {
      const Point2 I = rc.hit->I;
      panel.add(render::PointMark{p2(I), Role::result, render::Label{"I", p2(I), render::Side::auto_, Role::result}});
      panel.add(render::Arrow{p2(I), p2(I + rc.hit->N), Role::normal});
      panel.add(render::Label{T.get("ray_circle.figure.N"), p2(I + rc.hit->N), render::Side::auto_, Role::normal});
    }
    s.panels.push_back(std::move(panel));
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_circle_kind() { return the_kind<ball::BallKind<RayCircle>>(); }

}  // namespace epure::kinds
