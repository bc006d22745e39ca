// Exercise 4 of the course: the first point where a ray meets the canonical square [-1,1]², by
// the box family's method (box_family.h: the candidate sides, each met where (A + t·û)·n = 1).
// This file is the square's draw and diagrams.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/kinds/box_family.h"

namespace epure::kinds {

namespace {

using geo::Face;
using geo::Point2;
using geo::Vec2;
using Data = box::Data<2>;
using Side = box::FaceInPlay<2>;

// Axis directions and Pythagorean triples: û, t and I rational at the easy level.
constexpr Vec2 kEasyDirections[] = {{1, 0}, {0, 1}, {2, 0}, {0, 3},  {3, 4},
                                    {4, 3}, {6, 8}, {8, 6}, {5, 12}, {12, 5}};

Vec2 normal_of(Face f) { return f.axis == 0 ? Vec2{double(f.sign), 0} : Vec2{0, double(f.sign)}; }

struct RaySquare : box::Family<2> {
  static constexpr std::string_view kName = "ray_square";
  // what the exercise adds to the sheet's total when the spec does not set its points (points.h:
  // the sheet's questions share that total by their work)
  static constexpr double kPoints = 6;
  static constexpr std::string_view kWhat = "branch, corner and side margins, t range";
  static std::vector<DrawnField> kDrawn() { return {{"I", 0, {}}, {"N", 0, "I", "\\vec{N}"}}; }

  static std::map<std::string, double> constraints() {
    return {
        {"corner_margin", 0.15},  // a crossing at least this far from a side's ends (on or off it)
        {"side_margin", 0.5},     // each coordinate of A at least this far from ±1
        {"t_min", 0.5},           // the hit at least this far along the ray
        {"min_cos", 0.2},         // |û·n| of a side in play at least this, unless exactly 0
    };
  }
  static box::Margins margins(const ExerciseContext& ctx, const ExerciseKind& kind) {
    const bool hard = ctx.spec.difficulty == Difficulty::hard;
    return {constraint(ctx, kind, "corner_margin"), constraint(ctx, kind, "side_margin"),
            constraint(ctx, kind, "t_min") / (hard ? 2 : 1), constraint(ctx, kind, "min_cos")};
  }
  static Vec2 easy_direction(Rng& rng) {
    Vec2 u = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
    if (rng.chance(0.5)) u.x = -u.x;
    if (rng.chance(0.5)) u.y = -u.y;
    return u;
  }
  // Hard: a crossing grazing a side's end, or A in a corner region close to the corner (two
  // candidates), or close to its only candidate side; from inside, grazing or close to a side.
  static bool hard_enough(const Data& x, const geo::RaySquare& rs, std::optional<double> closest,
                          const box::Margins& mg, double side_clear) {
    const bool grazing = closest && *closest <= mg.edge + 0.1;
    if (rs.inside) return grazing || std::max(std::abs(x.A.x), std::abs(x.A.y)) >= 1 - mg.face;
    const double ax = std::abs(x.A.x), ay = std::abs(x.A.y);
    const bool near_corner = ax > 1 && ay > 1 && ax <= 1.8 && ay <= 1.8;
    const bool near_side = std::min(ax > 1 ? ax : 9.0, ay > 1 ? ay : 9.0) <= 1 + 3 * side_clear;
    return grazing || near_corner || near_side;
  }
  static render::Figure sheet_figure(const Data& d, const geo::RaySquare&, const ExerciseContext& ctx) {
    return {question_scene(d, ctx), 0.5};
  }
  static render::Figure key_figure(const Data& d, const geo::RaySquare& rs, const KeySolution& key,
                                   const ExerciseContext& ctx) {
    return {key_scene(d, rs, box::faces_in_play<2>(key.run), ctx), 0.45};
  }

  static render::Panel data_panel(const Data& d) {
    render::Panel panel;
    const double m = std::ceil(std::max({2.0, std::abs(d.A.x), std::abs(d.A.y)}) + 1);
    panel.view = {-m, -m, m, m};
    panel.add(render::Grid{1, true});
    return panel;
  }

  static std::vector<render::P2> corners() { return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; }

  static render::Scene question_scene(const Data& d, const ExerciseContext& ctx) {
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

  static render::Scene key_scene(const Data& d, const geo::RaySquare& rs, const std::vector<Side>& sides,
                          const ExerciseContext& ctx) {
    using render::Role;
    const auto& T = ctx.texts;
    render::Scene s;
    s.title = T.get("ray_square.title");
    s.description = T.get(fmt::format("ray_square.figure.key.{}", name(box::branch_of(rs))));
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
    // the four sides: the candidate sides highlighted, the others greyed. Orange means "a
    // candidate side" in every square and rectangle key; from inside there is none (the key says
    // so), and the sides the exit is sought on are drawn as the square itself.
    for (Face f : box::Space<2>::kFaces) {
      const bool in_play = std::any_of(sides.begin(), sides.end(), [&](const Side& x) { return x.face == f; });
      const Vec2 n = normal_of(f), along = geo::perp(n);
      const Point2 mid = geo::to_point(n);
      const Role role = !in_play ? Role::muted : rs.inside ? Role::data : Role::highlight;
      panel.add(render::Segment{p2(mid - along), p2(mid + along), role});
    }
    std::optional<render::P2> followed_to;
    if (rs.hit) followed_to = p2(rs.hit->I);
    panel.add(render::Ray{p2(d.A), p2(d.u), Role::data, followed_to});
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
    legend_highlight(s, ctx, "ray_square.figure.legend.candidate", render::LegendEntry::Swatch::line);
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_square_kind() { return the_kind<box::BoxKind<RaySquare>>(); }

}  // namespace epure::kinds
