// The 3D view's camera (render/camera.h): orthographic (lengths in the picture plane kept, the
// view direction collapsed), what a ball and a box hide, and a segment split into visible (solid)
// and hidden (dashed) stretches at the right places.
#include <doctest/doctest.h>

#include <cmath>
#include <variant>

#include "render/camera.h"

using namespace epure::render;

namespace {
double length(P2 a, P2 b) { return std::hypot(b.x - a.x, b.y - a.y); }
}  // namespace

TEST_CASE("camera: orthographic, z up, right-handed") {
  for (const Camera& cam : {Camera::isometric(), Camera::axonometric(30, 25)}) {
    const P3 t = cam.toward();
    CHECK(dot3(t, t) == doctest::Approx(1));
    // a step towards the viewer does not move the picture; it raises the depth
    const P2 a = cam.project({0.3, -0.2, 0.5}), b = cam.project(P3{0.3, -0.2, 0.5} + 2.0 * t);
    CHECK(length(a, b) == doctest::Approx(0).epsilon(1e-12));
    CHECK(cam.depth(P3{0, 0, 0} + 1.0 * t) == doctest::Approx(1));
    // z goes straight up the picture
    const P2 z = cam.project({0, 0, 1});
    CHECK(std::abs(z.x) < 1e-12);
    CHECK(z.y > 0);
    // a unit vector orthogonal to the view direction keeps its length
    const P3 w{t.y, -t.x, 0};
    const double n = std::sqrt(dot3(w, w));
    CHECK(length(cam.project({0, 0, 0}), cam.project((1 / n) * w)) == doctest::Approx(1));
  }
  // from azimuth 30°, elevation 25°: x comes down to the left, y goes right
  const Camera cam = Camera::axonometric(30, 25);
  CHECK(cam.project({1, 0, 0}).x < 0);
  CHECK(cam.project({1, 0, 0}).y < 0);
  CHECK(cam.project({0, 1, 0}).x > 0);
}

TEST_CASE("camera: what a ball and a box hide") {
  const Camera cam = Camera::axonometric(30, 25);
  const P3 t = cam.toward();
  const Ball ball{{0, 0, 0}, 1};
  CHECK(hides(ball, cam, {0, 0, 0}));             // inside
  CHECK(hides(ball, cam, -3.0 * t));              // behind the ball
  CHECK_FALSE(hides(ball, cam, 3.0 * t));         // in front of it
  CHECK_FALSE(hides(ball, cam, 1.0 * t));         // on its front surface
  CHECK_FALSE(hides(ball, cam, {0, 0, 5}));       // beside it
  const AlignedBox box{{-1, -1, -1}, {1, 1, 1}};
  CHECK(hides(box, cam, {-1, -1, -1}));           // the back corner
  CHECK_FALSE(hides(box, cam, {1, 1, 1}));        // the front corner
  CHECK(hides(box, cam, P3{0, 0, 0} - 4.0 * t));  // behind the box
  CHECK_FALSE(hides(box, cam, P3{0, 0, 0} + 4.0 * t));
  CHECK_FALSE(hides(NoSolid{}, cam, {0, 0, 0}));
}

TEST_CASE("camera: a segment through a ball is solid, dashed inside and behind, then solid") {
  const Camera cam = Camera::axonometric(30, 25);
  const P3 t = cam.toward();
  // a segment along the view direction's perpendicular, through the centre: hidden where the
  // ball hides it, i.e. inside (|s| < 1): three pieces
  const P3 w{t.y, -t.x, 0};
  const P3 side = (1 / std::sqrt(dot3(w, w))) * w;
  Panel panel;
  add_segment(panel, cam, -3.0 * side, 3.0 * side, Role::data, Ball{{0, 0, 0}, 1});
  REQUIRE(panel.items.size() == 3);
  const auto& a = std::get<Segment>(panel.items[0]);
  const auto& b = std::get<Segment>(panel.items[1]);
  const auto& c = std::get<Segment>(panel.items[2]);
  CHECK_FALSE(a.dashed);
  CHECK(b.dashed);
  CHECK_FALSE(c.dashed);
  CHECK(length(a.a, a.b) == doctest::Approx(2).epsilon(1e-6));
  CHECK(length(b.a, b.b) == doctest::Approx(2).epsilon(1e-6));
  CHECK(length(c.a, c.b) == doctest::Approx(2).epsilon(1e-6));
  // a segment in front of the ball: one solid piece
  Panel front;
  add_segment(front, cam, P3{0, 0, 0} + 2.0 * t - 3.0 * side, P3{0, 0, 0} + 2.0 * t + 3.0 * side, Role::data,
              Ball{{0, 0, 0}, 1});
  REQUIRE(front.items.size() == 1);
  CHECK_FALSE(std::get<Segment>(front.items[0]).dashed);
  // the cube's 3 back edges dashed, the 9 others solid (from this camera)
  int dashed = 0, solid = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 : {-1, 1})
      for (int s2 : {-1, 1}) {
        double p[3], q[3];
        p[axis] = -1, q[axis] = 1;
        p[(axis + 1) % 3] = q[(axis + 1) % 3] = s1;
        p[(axis + 2) % 3] = q[(axis + 2) % 3] = s2;
        Panel edge;
        add_segment(edge, cam, {p[0], p[1], p[2]}, {q[0], q[1], q[2]}, Role::data, AlignedBox{{-1, -1, -1}, {1, 1, 1}});
        REQUIRE(edge.items.size() == 1);
        (std::get<Segment>(edge.items[0]).dashed ? dashed : solid)++;
      }
  CHECK(dashed == 3);
  CHECK(solid == 9);
}
