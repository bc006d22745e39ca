// A turned ellipse or rectangle decided on the decimals written (geometry/turned_written.h),
// against figures worked by hand that are on a boundary as decimals and not as their doubles.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "geometry/quadratic.h"
#include "geometry/turned_written.h"

using namespace epure::geo;

namespace {

// The decimal a JSON text writes (its double correctly rounded by strtod). The texts are
// literals: they outlive the numbers.
Decimal d(const char* text) { return read_decimal(text, std::strtod(text, nullptr)); }
DPoint2 p(const char* x, const char* y) { return {d(x), d(y)}; }

struct Line {
  WrittenTurned w;
  Ray2 ray;
};
Line line(DPoint2 A, DPoint2 u, DPoint2 C, const char* sx, const char* sy, const char* angle) {
  return {{A, u, C, d(sx), d(sy), d(angle)}, {hi_point(A), hi_vec(u)}};
}
RayEllipse ellipse(const Line& l) {
  return intersect_written(l.w, l.w.u, l.ray, Ellipse{hi_point(l.w.C), l.w.sx.hi, l.w.sy.hi, l.w.angle_deg.hi});
}
RayRectangle rectangle(const Line& l) {
  return intersect_written(l.w, l.w.u, l.ray, Rectangle{hi_point(l.w.C), l.w.sx.hi, l.w.sy.hi, l.w.angle_deg.hi});
}

}  // namespace

TEST_CASE("turned figures: a quarter turn is read on the decimal written") {
  CHECK(quarter_turns(d("0")) == 0);
  CHECK(quarter_turns(d("90")) == 1);
  CHECK(quarter_turns(d("450.0")) == 1);
  CHECK(quarter_turns(d("-90")) == 3);
  CHECK(quarter_turns(d("-180")) == 2);
  CHECK(quarter_turns(d("7.2e2")) == 0);
  CHECK_FALSE(quarter_turns(d("90.00000000000000000001")));  // its double is 90, the decimal is not
  CHECK_FALSE(quarter_turns(d("45")));
  CHECK_FALSE(quarter_turns(d("1e300")));
}

TEST_CASE("turned ellipse at a quarter turn: tangent and on it as written") {
  // radii (0.3, 0.7) turned by 90°: its top in the world is C + (−0.7, 0)... its own x-axis is the
  // world's y: the vertex (0.3, 0) of its frame is C + (0, 0.3). The line y = C_y + 0.3 is tangent
  // there; 0.1 + 0.3 = 0.4 as decimals, not as doubles.
  const auto tangent = ellipse(line(p("-5", "0.4"), p("1", "0"), p("0.2", "0.1"), "0.3", "0.7", "90"));
  REQUIRE(tangent.hit);
  CHECK_FALSE(tangent.inside);
  CHECK(tangent.hit->t == doctest::Approx(5.2).epsilon(1e-15));
  CHECK(tangent.hit->N.y == doctest::Approx(1).epsilon(1e-15));
  // a hair above: a miss; a hair below: a chord
  CHECK_FALSE(ellipse(line(p("-5", "0.40000000000000000001"), p("1", "0"), p("0.2", "0.1"), "0.3", "0.7", "90")).hit);
  CHECK(ellipse(line(p("-5", "0.39999999999999999999"), p("1", "0"), p("0.2", "0.1"), "0.3", "0.7", "450")).hit);
  // A on the ellipse at that vertex: outside; heading in it hits at t = 0, heading out it is behind
  const auto in = ellipse(line(p("0.2", "0.4"), p("0.1", "-1"), p("0.2", "0.1"), "0.3", "0.7", "-270"));
  CHECK_FALSE(in.inside);
  REQUIRE(in.hit);
  CHECK(in.hit->t == 0);
  CHECK_FALSE(ellipse(line(p("0.2", "0.4"), p("0.1", "1"), p("0.2", "0.1"), "0.3", "0.7", "90")).hit);
  // a hair inside: inside, and it leaves at t > 0
  const auto hair = ellipse(line(p("0.2", "0.39999999999999999999"), p("0.1", "1"), p("0.2", "0.1"), "0.3", "0.7", "90"));
  CHECK(hair.inside);
  REQUIRE(hair.hit);
  CHECK(hair.hit->t >= 0);
}

TEST_CASE("turned ellipse with equal radii: a circle at any angle") {
  // radius 0.5 about (0.1, 0.2): the line y = 0.7 is tangent at (0.1, 0.7), whatever the angle
  const auto tangent = ellipse(line(p("-3", "0.7"), p("2", "0"), p("0.1", "0.2"), "0.5", "0.5", "37.3"));
  REQUIRE(tangent.hit);
  CHECK(tangent.hit->t == doctest::Approx(1.55).epsilon(1e-15));
  CHECK_FALSE(ellipse(line(p("-3", "0.70000000000000000001"), p("2", "0"), p("0.1", "0.2"), "0.5", "0.5", "37.3")).hit);
  // A on the circle (0.4, 0.6): 0.3² + 0.4² = 0.5²
  const auto on = ellipse(line(p("0.4", "0.6"), p("-1", "0"), p("0.1", "0.2"), "0.5", "0.5", "123"));
  CHECK_FALSE(on.inside);
  REQUIRE(on.hit);
  CHECK(on.hit->t == 0);
}

TEST_CASE("turned rectangle at a quarter turn: corners and sides as written") {
  // half-sizes (0.3, 0.1) turned by 90° about (0.7, 0.2): in the world it spans x in [0.6, 0.8],
  // y in [−0.1, 0.5]. The ray from (0.5, 0.4) along (1, 1) grazes its corner (0.6, 0.5) at
  // t = 0.1, through the figure's +y side (its own frame: X = (0.2, 0.2), U = (1, −1)), whose
  // normal is the world's −x.
  const auto corner = rectangle(line(p("0.5", "0.4"), p("1", "1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  REQUIRE(corner.hit);
  CHECK(corner.hit->t == doctest::Approx(0.1).epsilon(1e-14));
  REQUIRE(corner.canonical.face);
  CHECK(corner.canonical.face->axis == 1);
  CHECK(corner.hit->N.x == doctest::Approx(-1));
  // a hair above the corner (its double is on it): no hit
  CHECK_FALSE(rectangle(line(p("0.5", "0.40000000000000000001"), p("1", "1"), p("0.7", "0.2"), "0.3", "0.1", "90")).hit);
  // A on the side y = 0.5 (0.2 + 0.3), heading in: t = 0; a hair above: outside, t > 0
  const auto on = rectangle(line(p("0.7", "0.5"), p("0", "-1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  CHECK_FALSE(on.inside);
  REQUIRE(on.hit);
  CHECK(on.hit->t == 0);
  const auto above = rectangle(line(p("0.7", "0.50000000000000000001"), p("0", "-1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  REQUIRE(above.hit);
  CHECK(above.hit->t > 0);
  const auto below = rectangle(line(p("0.7", "0.49999999999999999999"), p("0", "-1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  CHECK(below.inside);
}

TEST_CASE("turned ellipse at multiples of 30° and 45°: exact in Q(√3) and Q(√2)") {
  // radii (7, 28) turned by 30°: x'²(3b² + a²)/4 = a²b² at x' = 8 along the world's x-axis, so
  // A = C + (8, 0) is on it (1 + 3·16 = 49 = 7²)
  const auto in = ellipse(line(p("8", "0"), p("-1", "0.3"), p("0", "0"), "7", "28", "30"));
  CHECK_FALSE(in.inside);
  REQUIRE(in.hit);
  CHECK(in.hit->t == 0);
  CHECK_FALSE(ellipse(line(p("8", "0"), p("1", "0.3"), p("0", "0"), "7", "28", "390")).hit);  // heading out
  CHECK(ellipse(line(p("7.99999999999999999999", "0"), p("1", "0.3"), p("0", "0"), "7", "28", "-330")).inside);
  CHECK_FALSE(ellipse(line(p("8.00000000000000000001", "0"), p("1", "0.3"), p("0", "0"), "7", "28", "30")).hit);
  // 60°: the same with the radii swapped
  CHECK_FALSE(ellipse(line(p("8", "0"), p("-1", "0.3"), p("0", "0"), "28", "7", "60")).inside);
  // 45°: b²(x + y)²/2 + a²(y − x)²/2 = a²b², which (x, y) = (1, 6), a = 5, b = 25 satisfy
  // (625·49/2 + 25·25/2 = 15,625); heading in along −(1, 1), it hits at t = 0
  const auto diagonal = ellipse(line(p("1", "6"), p("-0.1", "-0.1"), p("0", "0"), "5", "25", "45"));
  CHECK_FALSE(diagonal.inside);
  REQUIRE(diagonal.hit);
  CHECK(diagonal.hit->t == 0);
}

TEST_CASE("quadratic numbers: exact signs of p + q√K") {
  using exact::Quadratic;
  const auto q2 = [](double p, double q) { return Quadratic<2>{exact::exact_value(p), exact::exact_value(q)}; };
  CHECK(q2(1.4142135623730951, -1).sign() == 1);  // the double above √2
  CHECK(q2(-1.4142135623730951, 1).sign() == -1);
  CHECK(q2(1.4142135623730950, -1).sign() == -1);  // the one below
  CHECK(q2(0, 0).sign() == 0);
  const auto half = q2(0, 0.5);
  CHECK((half * half - q2(0.5, 0)).sign() == 0);  // (½√2)² = ½ exactly
  CHECK((half * half).value() == 0.5);
}
