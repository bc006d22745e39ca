// The course's remark on the square, "cet algo se généralise très simplement en 3D avec le cube
// canonique (6 faces)": the first point where a ray meets [-1,1]³, by the box family's method
// (box_family.h), every coordinate in space. This file is the cube's draw and diagrams.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/kinds/box_family.h"
#include "exercises/kinds/space_common.h"

namespace epure::kinds {

namespace {

using Data = box::Data<3>;
using FaceInPlay = box::FaceInPlay<3>;
using geo::Point3;
using geo::Vec3;

constexpr Vec3 kEasyDirections[] = {{1, 0, 0}, {2, 0, 0}, {3, 4, 0}, {1, 2, 2}, {2, 3, 6}, {2, 1, 2}, {4, 4, 2}};
constexpr auto& kAxis = box::Space<3>::kAxes;

double coord(Point3 p, int axis) { return box::coord(p, axis); }

struct RayCube : box::Family<3> {
  static constexpr std::string_view kName = "ray_cube";
  static constexpr double kPoints = 7;
  static constexpr std::string_view kWhat = "branch, edge and face margins, t range";

  static std::map<std::string, double> constraints() {
    return {{"edge_margin", 0.15}, {"face_margin", 0.5}, {"t_min", 0.5}, {"min_cos", 0.2}};
  }
  static box::Margins margins(const ExerciseContext& ctx, const ExerciseKind& kind) {
    const bool hard = ctx.spec.difficulty == Difficulty::hard;
    return {constraint(ctx, kind, "edge_margin"), constraint(ctx, kind, "face_margin"),
            constraint(ctx, kind, "t_min") / (hard ? 2 : 1), constraint(ctx, kind, "min_cos")};
  }
  static Vec3 easy_direction(Rng& rng) { return space::easy_direction(rng, kEasyDirections); }
  // Hard: a crossing grazing a face's edge (from inside, any).
  static bool hard_enough(const Data&, const geo::RayCube& rc, std::optional<double> closest, const box::Margins& mg,
                          double) {
    return (closest && *closest <= mg.edge + 0.1) || rc.inside;
  }
  static render::Figure sheet_figure(const Data& d, const geo::RayCube&, const ExerciseContext& ctx) {
    return {question_scene(d, ctx), 0.5};
  }
  static render::Figure key_figure(const Data& d, const geo::RayCube& rc, const KeySolution& key,
                                   const ExerciseContext& ctx) {
    return {key_scene(d, rc, box::faces_in_play<3>(key.run), ctx), 0.95};
  }

  // The cube's 12 edges, the back ones dashed.
  static void add_cube(render::Panel& panel, const render::Camera& cam, const render::AlignedBox& box) {
    for (int axis = 0; axis < 3; ++axis)
      for (int s1 : {-1, 1})
        for (int s2 : {-1, 1}) {
          double a[3], b[3];
          a[axis] = -1, b[axis] = 1;
          a[(axis + 1) % 3] = b[(axis + 1) % 3] = s1;
          a[(axis + 2) % 3] = b[(axis + 2) % 3] = s2;
          render::add_segment(panel, cam, {a[0], a[1], a[2]}, {b[0], b[1], b[2]}, render::Role::data, box);
        }
  }

  static std::vector<render::P3> face_corners(geo::Face f) {
    std::vector<render::P3> out;
    const int a = (f.axis + 1) % 3, b = (f.axis + 2) % 3;
    const double sa[] = {-1, 1, 1, -1}, sb[] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
      double c[3];
      c[f.axis] = f.sign, c[a] = sa[k], c[b] = sb[k];
      out.push_back({c[0], c[1], c[2]});
    }
    return out;
  }

  static render::Panel view(const Data& d, const render::Camera& cam, double reach,
                            const std::vector<FaceInPlay>* shaded) {
    using render::Role;
    using space::p3;
    const Vec3 uh = d.u / geo::norm(d.u);
    const Point3 end = d.A + reach * uh;
    const render::AlignedBox box{{-1, -1, -1}, {1, 1, 1}};
    render::Panel panel = space::view_panel(cam, {p3(d.A), p3(end), {1, 1, 1}, {-1, -1, -1}}, 3, 2, box);
    space::add_drop(panel, cam, p3(d.A));
    if (shaded)
      for (const FaceInPlay& s : *shaded) {
        std::vector<render::P2> pts;
        for (const auto& c : face_corners(s.face)) pts.push_back(cam.project(c));
        panel.add(render::Polygon{pts, true, Role::highlight, true});
      }
    add_cube(panel, cam, box);
    render::add_segment(panel, cam, p3(d.A), p3(end), Role::data, box);
    panel.add(render::Arrow{cam.project(p3(d.A)), cam.project(p3(d.A + uh)), Role::construction});
    panel.add(render::Label{"û", cam.project(p3(d.A + uh)), render::Side::auto_, Role::construction});
    panel.add(render::PointMark{cam.project(p3(d.A)), Role::data, render::Label{"A", cam.project(p3(d.A))}});
    return panel;
  }

  static double reach_of(const Data& d) { return geo::norm(geo::to_vec(d.A)) + 2.5; }

  static render::Scene question_scene(const Data& d, const ExerciseContext& ctx) {
    render::Scene s;
    s.title = ctx.texts.get("ray_cube.title");
    s.description = ctx.texts.get("ray_cube.figure.question");
    render::Panel panel = view(d, space::camera(), reach_of(d), nullptr);
    panel.caption = ctx.texts.get("ray_cube.figure.view");
    s.panels.push_back(std::move(panel));
    return s;
  }

  // A face drawn flat in its own plane, axes (a, b) the two other coordinates in order: with I
  // and N (perpendicular to the plane, towards the reader) when it is the face hit, else where
  // the ray meets the plane off the face.
  static render::Panel flat_face(geo::Face f, std::optional<Point3> point, bool hit, const ExerciseContext& ctx) {
    using render::P2;
    using render::Role;
    const auto& T = ctx.texts;
    const int a = std::min((f.axis + 1) % 3, (f.axis + 2) % 3), b = std::max((f.axis + 1) % 3, (f.axis + 2) % 3);
    render::Panel panel;
    std::vector<P2> pts = {{-1, -1}, {1, 1}};
    std::optional<P2> J;
    if (point) J = P2{coord(*point, a), coord(*point, b)};
    if (J) pts.push_back(*J);
    panel.view = view_around(pts, 0.8, 3.0);
    panel.add(render::Grid{1, false});
    panel.add(render::Polygon{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, true, Role::highlight, true});
    panel.add(render::Label{std::string(kAxis[a]), {panel.view.x_max - 0.2, 0}, render::Side::above, Role::construction});
    panel.add(render::Label{std::string(kAxis[b]), {0, panel.view.y_max - 0.2}, render::Side::right, Role::construction});
    if (J) {
      if (hit) {
        panel.add(render::PointMark{*J, Role::result, render::Label{"I", *J, render::Side::auto_, Role::result}});
        panel.add(render::Circle{*J, 0.18, Role::normal});
        panel.add(render::Label{T.get("ray_cube.figure.N_out"), {J->x + 0.18, J->y - 0.18}, render::Side::below_right,
                                Role::normal});
      } else {
        panel.add(render::PointMark{*J, Role::construction,
                                    render::Label{"J", *J, render::Side::auto_, Role::construction}});
      }
    }
    panel.caption = T.format("ray_cube.figure.face", {{"face", face_label(geo::face_name(f))},
                                                      {"c", std::string(kAxis[f.axis])},
                                                      {"v", f.sign > 0 ? "1" : "−1"}});
    return panel;
  }

  static render::Scene key_scene(const Data& d, const geo::RayCube& rc, const std::vector<FaceInPlay>& faces,
                          const ExerciseContext& ctx) {
    using render::P2;
    using render::Role;
    using space::p3;
    const auto& T = ctx.texts;
    const render::Camera cam = space::camera();
    render::Scene s;
    s.title = T.get("ray_cube.title");
    s.description = T.get(fmt::format("ray_cube.figure.key.{}", name(box::branch_of(rc))));
    render::Panel v3 = view(d, cam, reach_of(d), &faces);
    for (const FaceInPlay& f : faces)
      if (f.J && !(rc.face && *rc.face == f.face))
        v3.add(render::PointMark{cam.project(p3(*f.J)), Role::construction,
                                 render::Label{"J", cam.project(p3(*f.J)), render::Side::auto_, Role::construction}});
    if (rc.hit) {
      const P2 I = cam.project(p3(rc.hit->I)), tip = cam.project(p3(rc.hit->I + rc.hit->N));
      v3.add(render::PointMark{I, Role::result, render::Label{"I", I, render::Side::auto_, Role::result}});
      v3.add(render::Arrow{I, tip, Role::normal});
      v3.add(render::Label{T.get("ray_cube.figure.N"), tip, render::Side::auto_, Role::normal});
    }
    v3.caption = T.get("ray_cube.figure.view");
    s.panels.push_back(std::move(v3));
    if (rc.hit) {
      s.panels.push_back(flat_face(*rc.face, rc.hit->I, true, ctx));
      s.links = {T.get("ray_cube.figure.link")};
    } else {
      // a miss: the first face tried that the ray's line crosses, off the face
      for (const FaceInPlay& f : faces)
        if (f.J) {
          s.panels.push_back(flat_face(f.face, f.J, false, ctx));
          s.links = {T.get("ray_cube.figure.link")};
          break;
        }
    }
    // Orange means a candidate face in every cube key: from inside there is none (the key says
    // so), and the faces the exit is sought on are shaded in the construction's colour.
    if (rc.inside)
      for (render::Panel& panel : s.panels)
        for (render::Item& item : panel.items)
          if (auto* p = std::get_if<render::Polygon>(&item); p && p->role == Role::highlight) p->role = Role::construction;
    legend_highlight(s, ctx, "ray_cube.figure.legend.candidate", render::LegendEntry::Swatch::area);
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_cube_kind() { return the_kind<box::BoxKind<RayCube>>(); }

}  // namespace epure::kinds
