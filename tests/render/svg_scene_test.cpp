#include "render/svg_scene.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "render/recording_canvas.h"
#include "render/scene_painter.h"

using namespace epure::render;
using epure::test::RecordingCanvas;

namespace {

constexpr double kEps = 1e-12;

Scene projection_key() {
  Scene s;
  s.title = "Projection <key> & \"more\"";
  s.description = "A, B, C and the foot P";
  Panel p;
  p.view = {-1, -1, 10, 8};
  p.add(Grid{1, true});
  p.add(Line{{1, 1}, {8, 4}, Role::construction});
  p.add(Segment{{3, 6}, {4.5, 2.5}, Role::construction, true});
  p.add(RightAngle{{4.5, 2.5}, {-1.5, 3.5}, {7, 3}});
  p.add(Segment{{1, 1}, {8, 4}});
  p.add(Tick{{1, 1}, {7, 3}, "0"});
  p.add(Tick{{4.5, 2.5}, {7, 3}, "t"});
  p.add(Tick{{8, 4}, {7, 3}, "1"});
  p.add(PointMark{{1, 1}, Role::data, Label{"A", {1, 1}}});
  p.add(PointMark{{8, 4}, Role::data, Label{"B", {8, 4}}});
  p.add(PointMark{{3, 6}, Role::data, Label{"C", {3, 6}}});
  p.add(PointMark{{4.5, 2.5}, Role::result, Label{"P", {4.5, 2.5}, Side::auto_, Role::result}});
  s.panels.push_back(std::move(p));
  return s;
}

bool contains(const std::string& s, std::string_view what) {
  return s.find(what) != std::string::npos;
}

}  // namespace

TEST_CASE("Frame: math to page, y flipped once, one scale") {
  const Frame f({-1, -1, 9, 4}, {10, 20, 110, 70});  // 10 × 5 units into 100 × 50 points
  CHECK(f.scale() == doctest::Approx(10).epsilon(kEps));
  const P2 top_left = f.to_page({-1, 4});
  CHECK(top_left.x == doctest::Approx(10).epsilon(kEps));
  CHECK(top_left.y == doctest::Approx(20).epsilon(kEps));
  const P2 bottom_right = f.to_page({9, -1});
  CHECK(bottom_right.x == doctest::Approx(110).epsilon(kEps));
  CHECK(bottom_right.y == doctest::Approx(70).epsilon(kEps));
  const P2 up = f.dir_to_page({0, 1});
  CHECK(up.x == doctest::Approx(0).epsilon(kEps));
  CHECK(up.y == doctest::Approx(-10).epsilon(kEps));
  SUBCASE("a view of another aspect is centred at one scale") {
    const Frame g({0, 0, 1, 1}, {0, 0, 200, 100});
    CHECK(g.scale() == doctest::Approx(100).epsilon(kEps));
    CHECK(g.to_page({0, 0}).x == doctest::Approx(50).epsilon(kEps));
  }
}

TEST_CASE("layout_scene: panels side by side at one height, links between, captions under") {
  Scene s;
  Panel a, b;
  a.view = {0, 0, 10, 5};
  a.caption = "world frame";
  b.view = {-2, -2, 2, 2};
  b.caption = "canonical frame";
  s.panels = {a, b};
  s.links = {"M^{−1}"};
  const SceneLayout l = layout_scene(s, 10, 20, 400);
  REQUIRE(l.panels.size() == 2);
  REQUIRE(l.links.size() == 1);
  CHECK(l.panels[0].x_min == doctest::Approx(10).epsilon(kEps));
  CHECK(l.panels[1].x_max == doctest::Approx(410).epsilon(kEps));
  CHECK(l.panels[0].height() == doctest::Approx(l.panels[1].height()).epsilon(kEps));
  CHECK(l.panels[0].width() == doctest::Approx(2 * l.panels[0].height()).epsilon(kEps));
  CHECK(l.links[0].x_min == doctest::Approx(l.panels[0].x_max).epsilon(kEps));
  CHECK(l.links[0].x_max == doctest::Approx(l.panels[1].x_min).epsilon(kEps));
  CHECK(l.height > l.panels[0].height());  // the captions
  CHECK(scene_height(s, 400) == doctest::Approx(l.height).epsilon(kEps));
  CHECK(scene_height(Scene{}, 400) == doctest::Approx(0).epsilon(kEps));
}

TEST_CASE("layout_scene: a link too long for its gap on one line goes under the captions") {
  Scene s;
  Panel a, b;
  a.view = {0, 0, 10, 10};
  a.caption = "world frame";
  b.view = {-2, -2, 2, 2};
  b.caption = "canonical frame";
  s.panels = {a, b};
  s.links = {"T^{−1} = scale(1/4, 1/2) ∘ rotate(−135°) ∘ translate(−5, −6)"};
  const double width = 400;
  const SceneLayout l = layout_scene(s, 10, 20, width);
  REQUIRE(l.link_on_arrow.size() == 1);
  CHECK_FALSE(l.link_on_arrow[0]);
  // The gap keeps only its arrow; the text's line spans the scene under both captions.
  CHECK(l.links[0].width() < 0.15 * width);
  CHECK(l.notes.x_min == doctest::Approx(10).epsilon(kEps));
  CHECK(l.notes.x_max == doctest::Approx(10 + width).epsilon(kEps));
  for (const Box& c : l.captions) CHECK(l.notes.y_min >= c.y_max);
  CHECK(l.height == doctest::Approx(l.notes.y_max - 20).epsilon(kEps));
  // Drawn: every text inside the scene's height, the link's on one line, clear of the captions.
  RecordingCanvas canvas;
  paint_scene(canvas, s, 10, 20, width);
  int link_lines = 0;
  for (const auto& t : canvas.texts) {
    CAPTURE(t.text);
    CHECK(t.box.y_max <= 20 + l.height + 1e-9);
    if (t.text.find("scale") != std::string::npos) {
      ++link_lines;
      CHECK(t.box.y_min >= l.notes.y_min - 1e-9);
    }
  }
  CHECK(link_lines == 1);
  // A short link still stands on its arrow.
  s.links = {"M^{−1}"};
  CHECK(layout_scene(s, 10, 20, width).link_on_arrow[0]);
}

TEST_CASE("lines and rays are clipped to the view; zero directions draw nothing") {
  Scene s;
  Panel p;
  p.view = {0, 0, 10, 10};
  p.add(Line{{-100, -50}, {100, 50}});
  p.add(Ray{{5, 5}, {1, 3}});
  p.add(Ray{{-5, -5}, {-1, 0}});  // points away from the view: nothing
  p.add(Line{{1, 1}, {1, 1}});    // no direction: nothing
  p.add(Ray{{1, 1}, {0, 0}});     // no direction: nothing
  p.add(Arrow{{2, 2}, {2, 2}});   // no length: nothing
  s.panels.push_back(p);
  RecordingCanvas canvas;
  const SceneReport r = paint_scene(canvas, s, 0, 0, 100);
  const Box& area = r.panels[0].area;
  int strokes = 0;
  for (const auto& st : canvas.strokes) {
    if (st.group == "panel") continue;  // the frame
    ++strokes;
    for (P2 q : {st.a, st.b}) {
      CHECK(q.x >= area.x_min - 1e-9);
      CHECK(q.x <= area.x_max + 1e-9);
      CHECK(q.y >= area.y_min - 1e-9);
      CHECK(q.y <= area.y_max + 1e-9);
    }
  }
  // The line (1 stroke) and the first ray (shaft + a 3-sided head).
  CHECK(strokes == 1 + 1 + 3);
  CHECK(canvas.clips == 0);  // balanced
  CHECK(canvas.groups.empty());
}

TEST_CASE("a ray followed to its hit: solid up to it, muted past it, a normal there stands alone") {
  // A key's ray from A(1, 5) along (2, 0), followed to its hit I(6, 5); the normal at I points
  // along the ray (an exit square to a side). The direction is not unit: the hit's parameter
  // is in steps of dir.
  Scene s;
  Panel p;
  p.view = {0, 0, 10, 10};
  p.add(Ray{{1, 5}, {2, 0}, Role::data, P2{6, 5}});
  p.add(Arrow{{6, 5}, {7, 5}, Role::normal});
  s.panels.push_back(p);
  RecordingCanvas canvas;
  const SceneReport r = paint_scene(canvas, s, 0, 0, 100);
  const Box& area = r.panels[0].area;
  const Frame frame(p.view, area);
  const P2 A = frame.to_page({1, 5}), I = frame.to_page({6, 5});
  std::vector<RecordingCanvas::Stroke> data, muted, normal;
  for (const auto& st : canvas.strokes) {
    if (st.group == "data") data.push_back(st);
    if (st.group == "muted") muted.push_back(st);
    if (st.group == "normal") normal.push_back(st);
  }
  // the followed part: one stroke from A to I, no head
  REQUIRE(data.size() == 1);
  CHECK(data[0].a.x == doctest::Approx(A.x));
  CHECK(data[0].b.x == doctest::Approx(I.x));
  CHECK(data[0].a.y == doctest::Approx(A.y));
  CHECK(data[0].b.y == doctest::Approx(I.y));
  // past I: a muted shaft from I and its head, all on the ray's line, towards the view's edge
  REQUIRE(muted.size() == 1 + 3);
  CHECK(muted[0].a.x == doctest::Approx(I.x));
  CHECK(muted[0].b.x > frame.to_page({9, 5}).x);
  for (const auto& st : muted) CHECK(std::min(st.a.x, st.b.x) >= I.x - 1e-9);
  CHECK(normal.size() == 1 + 3);  // the normal drawn as before, over the muted part only

  SUBCASE("a hit beyond the view: the ray as far as it is seen, with its head") {
    Scene far;
    Panel q = p;
    q.items.clear();
    q.add(Ray{{1, 5}, {2, 0}, Role::data, P2{40, 5}});
    far.panels.push_back(q);
    RecordingCanvas c2;
    paint_scene(c2, far, 0, 0, 100);
    int data_strokes = 0;
    for (const auto& st : c2.strokes) {
      CHECK((st.group == "data" || st.group == "panel"));
      data_strokes += st.group == "data";
    }
    CHECK(data_strokes == 1 + 3);
  }
}

TEST_CASE("scene_to_svg: a standalone SVG 1.1 document, grouped by role, escaped") {
  const std::string svg = scene_to_svg(projection_key(), 320);
  CHECK(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg "
                  "xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"",
                  0) == 0);
  CHECK(contains(svg, "viewBox=\"0 0 320 "));
  CHECK(contains(svg, "<title>Projection &lt;key&gt; &amp; \"more\"</title>"));
  CHECK(contains(svg, "<desc>A, B, C and the foot P</desc>"));
  CHECK(contains(svg, "id=\"panel1\" class=\"panel\""));
  for (const char* cls : {"class=\"grid\"", "class=\"construction\"", "class=\"data\"",
                          "class=\"labels\"", "class=\"points result\""}) {
    CAPTURE(cls);
    CHECK(contains(svg, cls));
  }
  CHECK(contains(svg, "stroke-dasharray=\"5 3\""));  // CP, dashed regardless of role
  CHECK(contains(svg, ">P</text>"));
  CHECK_FALSE(contains(svg, "nan"));
  CHECK_FALSE(contains(svg, "marker"));  // arrowheads are paths
  CHECK(svg.back() == '\n');
}

// One panel with one label at its centre.
Scene one_label(std::string text) {
  Scene s;
  Panel p;
  p.view = {0, 0, 4, 4};
  p.add(Label{std::move(text), {2, 2}, Side::right});
  s.panels.push_back(p);
  return s;
}

TEST_CASE("text: scripts as tspans that return to the baseline, \\vec as a drawn arrow") {
  const std::string svg = scene_to_svg(one_label("t_{ab}·\\vec{AB}"), 200);
  CHECK(contains(svg,
                 "\">t<tspan dy=\"2.5\" font-size=\"7\">ab</tspan><tspan "
                 "dy=\"-2.5\">·</tspan>AB</text>"));
  // In the labels group: the label's background, then the arrow's shaft and head.
  const std::size_t at = svg.find("<g class=\"labels\">");
  REQUIRE(at != std::string::npos);
  const std::string labels = svg.substr(at, svg.find("</g>", at) - at);
  std::size_t paths = 0;
  for (std::size_t k = labels.find("<path"); k != std::string::npos;
       k = labels.find("<path", k + 1))
    ++paths;
  CHECK(paths == 3);
}

TEST_CASE("text: SVG's initial values are not written; the root preserves spaces for all") {
  SvgWriter w;
  w.start("svg", {{"xml:space", "preserve"}});
  SvgCanvas canvas(w);
  const std::vector<TextRun> runs{TextRun{"a  b"}};
  TextLine plain;
  plain.at = {1, 2};
  plain.runs = runs;
  canvas.text(plain);
  TextLine grey = plain;
  grey.colour = {0x70, 0x70, 0x70};
  grey.anchor = Anchor::middle;
  canvas.text(grey);
  TextLine end = plain;
  end.anchor = Anchor::end;
  canvas.text(end);
  w.end("svg");
  const std::string svg = w.finish();
  CHECK(contains(svg, "<text x=\"1\" y=\"2\" font-size=\"10\">a  b</text>"));
  CHECK(contains(svg, "<text x=\"1\" y=\"2\" font-size=\"10\" fill=\"#707070\" text-anchor=\"middle\">a  b</text>"));
  CHECK(contains(svg, "<text x=\"1\" y=\"2\" font-size=\"10\" text-anchor=\"end\">a  b</text>"));

  // Whole documents carry xml:space on their root, so the double space above is kept.
  const std::string doc = scene_to_svg(one_label("A"), 200);
  const std::size_t root = doc.find("<svg"), root_end = doc.find('>', root);
  CHECK(contains(doc.substr(root, root_end - root), "xml:space=\"preserve\""));
  CHECK_FALSE(contains(doc.substr(root_end), "xml:space"));
}
