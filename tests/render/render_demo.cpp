// epure_render_demo DIR: writes sample scenes as standalone SVG files into DIR, one per kind of
// figure the worksheets draw, for tests/cli/render_svg.sh (xmllint, rsvg-convert) and for a look
// by eye. Prints one line per scene with its labels' placement; exits 1 when a label could not
// be placed cleanly.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "render/scene.h"
#include "render/svg_scene.h"

using namespace epure::render;

namespace {

PointMark point(P2 at, const char* name, Role role = Role::data, Side side = Side::auto_) {
  return PointMark{at, role, Label{name, at, side, role}};
}

P2 lerp(P2 a, P2 b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

// The projection of C on (AB), question and key.
Scene projection(bool key) {
  const P2 a{1, 1}, b{8, 4}, c{3, 6};
  const P2 ab{b.x - a.x, b.y - a.y};
  const double t = ((c.x - a.x) * ab.x + (c.y - a.y) * ab.y) / (ab.x * ab.x + ab.y * ab.y);
  const P2 p = lerp(a, b, t);
  Scene s;
  s.title = key ? "Projection of C on (AB): construction" : "Projection of C on (AB)";
  s.description =
      key ? "Points A, B and C on a grid; P is the foot of the perpendicular from C to line AB, "
            "with a right angle at P and the parameters 0, t and 1 marked along AB."
          : "Points A(1, 1), B(8, 4) and C(3, 6) on a grid.";
  Panel panel;
  panel.view = {-1, -1, 10, 8};
  panel.add(Grid{1, true});
  if (key) {
    panel.add(Line{a, b, Role::construction});
    panel.add(Segment{c, p, Role::construction, true});
    panel.add(RightAngle{p, {c.x - p.x, c.y - p.y}, ab, Role::construction});
  }
  panel.add(Segment{a, b, Role::data});
  if (key) {
    panel.add(Tick{a, ab, "0"});
    panel.add(Tick{p, ab, "t"});
    panel.add(Tick{b, ab, "1"});
  }
  panel.add(point(a, "A"));
  panel.add(point(b, "B"));
  panel.add(point(c, "C"));
  if (key) panel.add(point(p, "P", Role::result));
  s.panels.push_back(std::move(panel));
  return s;
}

// A ray hitting a circle: the projection P of the centre on the ray, the triangle C–P–I and its
// three lengths, the normal at I.
Scene ray_circle() {
  const P2 a{-4, -1}, u{0.8, 0.6}, c{3, 3};
  const double r = 3;
  const double tp = (c.x - a.x) * u.x + (c.y - a.y) * u.y;
  const P2 p{a.x + tp * u.x, a.y + tp * u.y};
  const double d2 = (c.x - p.x) * (c.x - p.x) + (c.y - p.y) * (c.y - p.y);
  const double h = std::sqrt(r * r - d2);
  const P2 i{p.x - h * u.x, p.y - h * u.y};
  const P2 n{(i.x - c.x) / r, (i.y - c.y) / r};
  Scene s;
  s.title = "Ray and circle: construction";
  s.description = "A ray from A with direction u meets the circle of centre C and radius r at I.";
  Panel panel;
  panel.view = {-5, -2, 8, 7};
  panel.add(Grid{1, true});
  panel.add(Polygon{{c, p, i}, true, Role::construction, true});
  panel.add(Circle{c, r, Role::data});
  panel.add(Ray{a, u, Role::data});
  panel.add(Arrow{a, {a.x + 1.6 * u.x, a.y + 1.6 * u.y}, Role::data});
  panel.add(Label{"\\vec{u}", {a.x + 0.8 * u.x, a.y + 0.8 * u.y}, Side::above_left, Role::data});
  panel.add(RightAngle{p, {c.x - p.x, c.y - p.y}, {-u.x, -u.y}, Role::construction});
  panel.add(Dimension{c, p, "√(d^{2})", -0.4, Role::construction});
  panel.add(Dimension{p, i, "√(r^{2} − d^{2})", -0.4, Role::construction});
  panel.add(Dimension{i, c, "r", 0, Role::construction});
  panel.add(Arrow{i, {i.x + 1.5 * n.x, i.y + 1.5 * n.y}, Role::normal});
  panel.add(Label{"\\vec{N}", {i.x + 1.5 * n.x, i.y + 1.5 * n.y}, Side::auto_, Role::normal});
  panel.add(point(a, "A"));
  panel.add(point(c, "C"));
  panel.add(point(p, "P", Role::construction));
  panel.add(point(i, "I", Role::result));
  s.panels.push_back(std::move(panel));
  return s;
}

// A ray and a square: the candidate sides highlighted, the others muted.
Scene ray_square() {
  Scene s;
  s.title = "Ray and square: candidate sides";
  s.description = "The ray from A meets the square; the two sides it can enter by are highlighted.";
  Panel panel;
  panel.view = {-4, -3, 6, 5};
  panel.add(Grid{1, true});
  const P2 q[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  panel.add(Segment{q[1], q[2], Role::muted});
  panel.add(Segment{q[2], q[3], Role::muted});
  panel.add(Segment{q[0], q[1], Role::highlight});
  panel.add(Segment{q[3], q[0], Role::highlight});
  panel.add(Ray{{-3, -2}, {2, 1}, Role::data});
  panel.add(point({-3, -2}, "A"));
  panel.add(point({0, -0.5}, "I", Role::result, Side::left));
  panel.add(Arrow{{0, -0.5}, {-1.2, -0.5}, Role::normal});
  panel.add(Label{"\\vec{N}", {-1.2, -0.5}, Side::above, Role::normal});
  panel.add(Label{"x = 0", {0, 1.5}, Side::left, Role::highlight});
  panel.add(Label{"y = 0", {1.5, 0}, Side::below, Role::highlight});
  s.panels.push_back(std::move(panel));
  return s;
}

// An ellipse in the world frame and the unit circle in its canonical frame.
Scene ellipse() {
  Scene s;
  s.title = "Ray and ellipse: world and canonical frames";
  s.description =
      "Left, the ellipse and the ray in the world frame; right, the unit circle and the "
      "ray carried into the canonical frame.";
  Panel world;
  world.view = {-1, -1, 9, 6};
  world.caption = "world frame";
  world.add(Grid{1, true});
  world.add(Ellipse{{4, 2.5}, 3, 1.5, 20, Role::data});
  world.add(Ray{{0, 5}, {1, -0.6}, Role::data});
  world.add(point({4, 2.5}, "Ω"));
  world.add(point({0, 5}, "A"));
  Panel canon;
  canon.view = {-2, -2, 2, 2};
  canon.caption = "canonical frame";
  canon.add(Grid{0.5, true});
  canon.add(Circle{{0, 0}, 1, Role::data});
  canon.add(Ray{{-1.6, 1.2}, {1, -0.4}, Role::data});
  canon.add(point({-1.6, 1.2}, "A_{c}"));
  canon.add(Arrow{{-1.6, 1.2}, {-0.8, 0.88}, Role::data});
  canon.add(Label{"\\vec{u}_{c}", {-1.2, 1.04}, Side::below, Role::data});
  s.panels.push_back(std::move(world));
  s.panels.push_back(std::move(canon));
  s.links.push_back("M^{−1}: x' = R^{T}(x\u00A0−\u00A0Ω)");
  return s;
}

// Crowded points with long names, escapes and accents: the placer at work.
Scene crowded() {
  Scene s;
  s.title = "Label stress <&> \"test\"";
  s.description = "Eight points close together with long names: é, œ, Δ, ‖u‖ & <tags>.";
  Panel panel;
  panel.view = {0, 0, 6, 4};
  panel.add(Grid{1, true});
  panel.add(Segment{{0.5, 0.5}, {5.5, 3.5}});
  panel.add(Segment{{0.5, 3.5}, {5.5, 0.5}, Role::construction, true});
  const P2 pts[] = {{2.8, 2},   {3.2, 2.1}, {3, 1.7}, {2.6, 2.3},
                    {3.4, 1.8}, {1, 1},     {5, 3},   {3, 2.5}};
  const char* names[] = {"I", "P_{1}", "P_{2}", "Q", "M_{ab}", "é", "œ", "Δ"};
  for (int k = 0; k < 8; ++k)
    panel.add(point(pts[k], names[k], k == 0 ? Role::result : Role::data));
  panel.add(Label{"‖\\vec{u}‖ = 1 & t < 2", {1, 3.5}, Side::right, Role::construction});
  s.panels.push_back(std::move(panel));
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const std::vector<std::pair<std::string, Scene>> scenes = {
      {"projection_question", projection(false)},
      {"projection_key", projection(true)},
      {"ray_circle", ray_circle()},
      {"ray_square", ray_square()},
      {"ellipse", ellipse()},
      {"crowded", crowded()},
  };
  int unclean = 0;
  for (const auto& [name, scene] : scenes) {
    SceneReport report;
    const std::string svg = scene_to_svg(scene, name == "ellipse" ? 480 : 320, report);
    std::ofstream(dir / (name + ".svg"), std::ios::binary) << svg;
    int labels = 0;
    for (const auto& p : report.panels) labels += static_cast<int>(p.labels.size());
    std::printf("%s: %d labels, %d not clean\n", name.c_str(), labels, report.unclean());
    unclean += report.unclean();
  }
  return unclean == 0 ? 0 : 1;
}
