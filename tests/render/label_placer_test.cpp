#include "render/label_placer.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "exercises/rng.h"
#include "render/recording_canvas.h"
#include "render/scene_painter.h"
#include "render/svg_scene.h"

using namespace epure::render;
using epure::Rng;
using epure::test::RecordingCanvas;

namespace {

constexpr double kEps = 1e-9;

const Box kArea{0, 0, 200, 100};

P2 centre(const Box& b) { return {(b.x_min + b.x_max) / 2, (b.y_min + b.y_max) / 2}; }

}  // namespace

TEST_CASE("place_labels: the preferred side first, others when it is taken") {
  SUBCASE("1. no preference: above right of the anchor, at the gap") {
    const auto p = place_labels({{{100, 50}, 10, 8, {0, 0}, 3}}, {}, kArea);
    REQUIRE(p.size() == 1);
    CHECK(p[0].clean);
    CHECK(p[0].box.x_min > 100);
    CHECK(p[0].box.y_max < 50);
    CHECK(p[0].box.width() == doctest::Approx(10).epsilon(kEps));
    CHECK(p[0].box.height() == doctest::Approx(8).epsilon(kEps));
    // The corner facing the anchor is `gap` away from it.
    CHECK(std::hypot(p[0].box.x_min - 100, p[0].box.y_max - 50) ==
          doctest::Approx(3).epsilon(1e-6));
  }
  SUBCASE("2. a preferred side is honoured") {
    const auto p = place_labels({{{100, 50}, 10, 8, {-1, 0}, 3}}, {}, kArea);
    CHECK(p[0].box.x_max == doctest::Approx(97).epsilon(kEps));
    CHECK(centre(p[0].box).y == doctest::Approx(50).epsilon(kEps));
  }
  SUBCASE("3. a line through the preferred spot pushes the label elsewhere") {
    Obstacles o;
    o.segments.push_back({{100, 50}, {200, 0}});  // up and to the right of the anchor
    const auto p = place_labels({{{100, 50}, 10, 8, {1, -1}, 3}}, o, kArea);
    CHECK(p[0].clean);
    CHECK_FALSE(segment_hits_box({100, 50}, {200, 0}, p[0].box));
  }
  SUBCASE("4. two labels on one anchor do not overlap") {
    const auto p = place_labels({{{100, 50}, 20, 8, {}, 3}, {{100, 50}, 20, 8, {}, 3}}, {}, kArea);
    CHECK(p[0].clean);
    CHECK(p[1].clean);
    CHECK_FALSE(boxes_overlap(p[0].box, p[1].box));
  }
  SUBCASE("5. near the panel's edge the label turns inwards") {
    const auto p = place_labels({{{198, 2}, 10, 8, {1, -1}, 3}}, {}, kArea);
    CHECK(p[0].clean);
    CHECK(p[0].box.x_max <= kArea.x_max);
    CHECK(p[0].box.y_min >= kArea.y_min);
  }
  SUBCASE("6. no room at all: the least bad box, reported") {
    const auto p = place_labels({{{5, 5}, 50, 30, {}, 3}}, {}, Box{0, 0, 20, 20});
    CHECK_FALSE(p[0].clean);
  }
  SUBCASE("7. a label on a stroke goes beside it, not across") {
    Obstacles o;
    o.segments.push_back({{0, 80}, {200, 20}});  // a sloped line through the anchor
    const P2 anchor{100, 50};
    const auto p = place_labels({{anchor, 40, 8, {0, 1}, 3, {200, -60}}}, o, kArea);
    CHECK(p[0].clean);
    CHECK(centre(p[0].box).y > anchor.y);  // on the preferred (lower) side
  }
  SUBCASE("8. deterministic") {
    Obstacles o;
    o.discs.push_back({{103, 47}, 3});
    const std::vector<LabelRequest> r = {{{100, 50}, 12, 8, {}, 3}, {{104, 52}, 12, 8, {}, 3}};
    const auto a = place_labels(r, o, kArea);
    const auto b = place_labels(r, o, kArea);
    for (std::size_t i = 0; i < a.size(); ++i) {
      CHECK(a[i].box.x_min == b[i].box.x_min);  // the same computation: bit-identical
      CHECK(a[i].box.y_min == b[i].box.y_min);
    }
  }
}

TEST_CASE("geometry of the placer") {
  const Box b{0, 0, 10, 10};
  CHECK(segment_hits_box({-5, 5}, {15, 5}, b));
  CHECK(segment_hits_box({5, 5}, {6, 6}, b));  // inside entirely
  CHECK_FALSE(segment_hits_box({-5, -1}, {15, -1}, b));
  CHECK_FALSE(segment_hits_box({-5, 4}, {4, 16}, Box{5, 0, 10, 10}));  // passes the corner
  CHECK(disc_hits_box({12, 5}, 2.5, b));
  CHECK_FALSE(disc_hits_box({12, 12}, 2.5, b));  // the corner is √8 ≈ 2.83 away
  CHECK(boxes_overlap(b, {9, 9, 20, 20}));
  CHECK_FALSE(boxes_overlap(b, {10.5, 0, 20, 10}));
}

namespace {

// A random figure like the course's: a few points (some on segments), segments, a line, a ray,
// maybe a circle, ticks along a segment, a dimension, arrows.
Scene random_scene(std::uint64_t seed) {
  Rng rng(seed, 7);
  Scene s;
  Panel p;
  p.view = {-1, -1, 11, 8};
  p.add(Grid{1, rng.chance(0.8)});
  const auto pt = [&] { return P2{double(rng.integer(0, 10)), double(rng.integer(0, 7))}; };
  const int n_points = static_cast<int>(rng.integer(3, 6));
  std::vector<P2> pts;
  for (int i = 0; i < n_points; ++i) pts.push_back(pt());
  const char* names[] = {"A", "B", "C", "D", "E", "F"};
  const char* fancy[] = {"P_{1}", "I", "\\vec{u}", "M_{ab}", "Ω", "t^{2}"};
  if (rng.chance(0.5)) p.add(Circle{pts[2], double(rng.integer(1, 3)), Role::data});
  p.add(Segment{pts[0], pts[1], Role::data});
  if (rng.chance(0.6)) p.add(Line{pts[0], pts[1], Role::construction});
  if (rng.chance(0.5)) p.add(Segment{pts[2], pts[0], Role::construction, true});
  if (rng.chance(0.5)) p.add(Ray{pts[1], {rng.uniform(-1, 1), rng.uniform(-1, 1)}, Role::data});
  if (rng.chance(0.4))
    p.add(Arrow{
        pts[2], {pts[2].x + rng.uniform(-2, 2), pts[2].y + rng.uniform(-2, 2)}, Role::normal});
  const P2 ab{pts[1].x - pts[0].x, pts[1].y - pts[0].y};
  if (rng.chance(0.6)) {
    p.add(Tick{pts[0], ab, "0"});
    p.add(Tick{{pts[0].x + 0.5 * ab.x, pts[0].y + 0.5 * ab.y}, ab, "t"});
    p.add(Tick{pts[1], ab, "1"});
  }
  if (rng.chance(0.4)) p.add(Dimension{pts[0], pts[2], "√(d^{2})", rng.uniform(-0.6, 0.6)});
  if (rng.chance(0.4)) p.add(RightAngle{pts[1], ab, {-ab.y, ab.x}});
  for (int i = 0; i < n_points; ++i) {
    const char* name = rng.chance(0.3) ? fancy[i] : names[i];
    p.add(PointMark{pts[i], i == 3 ? Role::result : Role::data,
                    Label{name, pts[i], Side::auto_, Role::data}});
  }
  s.panels.push_back(std::move(p));
  return s;
}

}  // namespace

TEST_CASE("labels never overlap each other nor what is drawn (random figures)") {
  constexpr int kScenes = 400;
  int labels = 0, unclean = 0;
  for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
    CAPTURE(seed);
    const Scene scene = random_scene(seed);
    RecordingCanvas canvas;
    const SceneReport report = paint_scene(canvas, scene, 0, 0, 360);
    REQUIRE(report.panels.size() == 1);
    const PanelReport& panel = report.panels[0];
    REQUIRE(panel.labels.size() == panel.texts.size());
    for (std::size_t i = 0; i < panel.labels.size(); ++i) {
      ++labels;
      const Placement& l = panel.labels[i];
      if (!l.clean) {
        ++unclean;
        continue;
      }
      CAPTURE(panel.texts[i]);
      const Box& b = l.box;
      // Inside its panel.
      CHECK(b.x_min >= panel.area.x_min);
      CHECK(b.x_max <= panel.area.x_max);
      CHECK(b.y_min >= panel.area.y_min);
      CHECK(b.y_max <= panel.area.y_max);
      // Off every other label.
      for (std::size_t j = 0; j < panel.labels.size(); ++j) {
        if (j != i) CHECK_FALSE(boxes_overlap(b, panel.labels[j].box));
      }
      // Off every stroke and point actually drawn (cubics sampled by the recorder, so a hair of
      // slack under the clearance the placer keeps).
      const Box shrunk = inflate(b, -0.3);
      for (const auto& s : canvas.strokes) {
        if (segment_hits_box(s.a, s.b, shrunk)) {
          FAIL_CHECK("label crosses a stroke of group " << s.group);
          break;
        }
      }
      for (const auto& d : canvas.discs) CHECK_FALSE(disc_hits_box(d.c, d.r, shrunk));
      // And no axis number under it.
      for (const auto& t : canvas.texts) {
        if (t.group == "grid") CHECK_FALSE(boxes_overlap(t.box, shrunk));
      }
    }
  }
  MESSAGE(labels << " labels in " << kScenes << " figures, " << unclean << " not clean");
  // Figures as dense as these leave a label no clean spot very rarely.
  CHECK(unclean * 100 <= labels);
}

TEST_CASE("a label box holds its text: the drawn text lies inside the placed box") {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    CAPTURE(seed);
    RecordingCanvas canvas;
    const SceneReport report = paint_scene(canvas, random_scene(seed), 0, 0, 360);
    std::vector<Box> drawn;
    for (const auto& t : canvas.texts) {
      if (t.group == "labels") drawn.push_back(t.box);
    }
    const auto& placed = report.panels[0].labels;
    REQUIRE(drawn.size() == placed.size());
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      CHECK(drawn[i].x_min == doctest::Approx(placed[i].box.x_min).epsilon(1e-9));
      CHECK(drawn[i].y_min == doctest::Approx(placed[i].box.y_min).epsilon(1e-9));
      CHECK(drawn[i].x_max == doctest::Approx(placed[i].box.x_max).epsilon(1e-9));
      CHECK(drawn[i].y_max == doctest::Approx(placed[i].box.y_max).epsilon(1e-9));
    }
  }
}

TEST_CASE("painting is deterministic: the same scene gives the same SVG bytes") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    CAPTURE(seed);
    const Scene scene = random_scene(seed);
    CHECK(scene_to_svg(scene, 300) == scene_to_svg(scene, 300));
  }
}
