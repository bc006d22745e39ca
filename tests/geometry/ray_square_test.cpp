// Pins geometry/ray_square.h, exercise 4 of the course: ray/canonical square [-1,1]² by its
// sides. The contract's worked examples; in numbered cases: zero direction ("u"), the candidate
// sides (closed outer half-planes that contain A, at most two, in the contract's order), start
// inside (faces empty, the exit side), start on a side heading in (t = 0, I = A) or out (no
// hit), corners (a tie goes to the x side), grazing along a side, parallel misses, a ray from
// 1e8, directions of any length. Property tests against an independent slab method in
// quadruple precision (support/box_reference.h): faces, inside, hit, side, t, I; I on the
// side hit with N its axis normal, t = |AI|; the square's eight symmetries (quarter turns,
// mirrors) permute the answer exactly.
#include "geometry/ray_square.h"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "geometry/degenerate.h"
#include "support/approx.h"
#include "support/box_reference.h"
#include "support/draw.h"
#include "support/exactly.h"
#include "support/real.h"

using namespace epure::geo;
using epure::Rng;
using epure::test::d;
using epure::test::exactly;
using epure::test::Real;
namespace T = epure::test;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<std::string> names(const FaceSet<2>& faces) {
  std::vector<std::string> out;
  faces.for_each([&](Face f) { out.emplace_back(face_name(f)); });
  return out;
}
using Names = std::vector<std::string>;

void check_hit(const RaySquare& s, double t, double x, double y, Face face) {
  REQUIRE(s.hit.has_value());
  CHECK(s.hit->t == T::within(t, 4 * kEps, 0));
  CHECK(s.hit->I.x == T::within(x, 4 * kEps, 0));
  CHECK(s.hit->I.y == T::within(y, 4 * kEps, 0));
  REQUIRE(s.face.has_value());
  CHECK(face_name(*s.face) == face_name(face));
  CHECK(exactly(s.hit->N.x, face.axis == 0 ? face.sign : 0.0));
  CHECK(exactly(s.hit->N.y, face.axis == 1 ? face.sign : 0.0));
}

// A's side of each of the four lines, and the ray: random, or aimed at the square from far.
struct Figure {
  Point2 A;
  Vec2 u;
};
Figure draw_figure(Rng& rng, int kind) {
  switch (kind) {
    case 0:  // around the square
      return {T::point2(rng, 4), T::direction2(rng)};
    case 1:  // inside
      return {T::point2(rng, 0.999), T::direction2(rng)};
    default: {  // far away (up to 1e8), aimed at a point of the square or near it
      const double distance = T::decades(rng, 0.5, 8);
      const Point2 target = T::point2(rng, 1.2);
      const Vec2 from = *normalized(T::direction2(rng));
      const Point2 A = target + distance * from;
      return {A, T::decades(rng, -3, 3) * (target - A)};
    }
  }
}

// The whole answer against the slab reference; `unit_ray` as `epure solve` calls it.
void check_against_reference(const Figure& f, bool unit_ray) {
  const Ray2 ray = unit_ray ? Ray2::unit(f.A, f.u) : Ray2{f.A, f.u};
  const double length_u = unit_ray ? 1.0 : norm(f.u);
  const RaySquare s = intersect_canonical_square(ray);
  const auto e = T::box_reference<2>({f.A.x, f.A.y}, {f.u.x, f.u.y});
  CAPTURE(unit_ray);
  CHECK(s.inside == e.inside);
  CHECK(s.faces.contains({0, +1}) == e.faces[0]);
  CHECK(s.faces.contains({1, +1}) == e.faces[1]);
  CHECK(s.faces.contains({0, -1}) == e.faces[2]);
  CHECK(s.faces.contains({1, -1}) == e.faces[3]);
  CHECK(s.faces.size() <= 2);
  REQUIRE(s.hit.has_value() == e.t.has_value());
  if (!s.hit) return;
  const double a = std::max(std::abs(f.A.x), std::abs(f.A.y)), t = d(*e.t);
  CAPTURE(t);
  CHECK(s.face->axis == e.axis);
  CHECK(s.face->sign == e.sign);
  // t carries the rounding of A (ε·|A|), and the unit direction's (ε·t)
  CHECK(s.hit->t * length_u == T::within(t, 8 * kEps, 8 * kEps * a));
  // the landing point: to the last digits with the direction as given; rounding the direction
  // to unit length turns the line by ε about A, which moves I by ε·t
  const double wobble = unit_ray ? 4 * kEps * t : 0;
  CHECK(s.hit->I.x == T::within(d(e.I[0]), 4 * kEps, 4 * kEps + wobble));
  CHECK(s.hit->I.y == T::within(d(e.I[1]), 4 * kEps, 4 * kEps + wobble));
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/ray_square: the contract's worked examples") {
  SUBCASE("1. straight at the −x side") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({-3, 0.5}, {1, 0}));
    CHECK(names(s.faces) == Names{"-x"});
    CHECK_FALSE(s.inside);
    check_hit(s, 2, -1, 0.5, {0, -1});
  }
  SUBCASE("2. from below left: two candidate sides, the −x one is hit") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({-3, -2.5}, {1, 1}));
    CHECK(names(s.faces) == Names{"-x", "-y"});
    check_hit(s, 2.8284271247461903, -1, -0.5, {0, -1});
  }
  SUBCASE("3. from the centre, down: the exit, faces empty") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({0, 0}, {0, -2}));
    CHECK(names(s.faces).empty());
    CHECK(s.inside);
    check_hit(s, 1, 0, -1, {1, -1});
  }
  SUBCASE("4. passing by, parallel to the −x side") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({-3, 0}, {0, 1}));
    CHECK(names(s.faces) == Names{"-x"});
    CHECK_FALSE(s.inside);
    CHECK_FALSE(s.hit.has_value());
    CHECK_FALSE(s.face.has_value());
  }
}

TEST_CASE("geometry/ray_square: every branch") {
  SUBCASE("1. zero direction: field u") {
    try {
      intersect_canonical_square(Ray2{{0, 0}, {0, 0}});
      FAIL("no exception");
    } catch (const DegenerateFigure& e) {
      CHECK(e.field() == "u");
    }
  }
  SUBCASE("2. the candidate sides, region by region, in the contract's order") {
    CHECK(names(intersect_canonical_square(Ray2::unit({3, 0}, {1, 0})).faces) == Names{"+x"});
    CHECK(names(intersect_canonical_square(Ray2::unit({3, 3}, {1, 0})).faces) == Names{"+x", "+y"});
    CHECK(names(intersect_canonical_square(Ray2::unit({0, 3}, {1, 0})).faces) == Names{"+y"});
    CHECK(names(intersect_canonical_square(Ray2::unit({-3, 3}, {1, 0})).faces) ==
          Names{"+y", "-x"});
    CHECK(names(intersect_canonical_square(Ray2::unit({-3, -3}, {1, 0})).faces) ==
          Names{"-x", "-y"});
    CHECK(names(intersect_canonical_square(Ray2::unit({3, -3}, {1, 0})).faces) ==
          Names{"+x", "-y"});
    // on a side or a corner: the closed half-plane contains A
    CHECK(names(intersect_canonical_square(Ray2::unit({1, 0.2}, {1, 0})).faces) == Names{"+x"});
    CHECK(names(intersect_canonical_square(Ray2::unit({-1, -1}, {1, 0})).faces) ==
          Names{"-x", "-y"});
  }
  SUBCASE("3. from inside, every way: the side met first") {
    check_hit(intersect_canonical_square(Ray2::unit({0.5, 0.5}, {1, 0})), 0.5, 1, 0.5, {0, 1});
    check_hit(intersect_canonical_square(Ray2::unit({0.5, 0.5}, {0, -1})), 1.5, 0.5, -1, {1, -1});
    check_hit(intersect_canonical_square(Ray2::unit({-0.5, 0}, {-2, 1})), std::sqrt(0.3125), -1,
              0.25, {0, -1});
    check_hit(intersect_canonical_square(Ray2::unit({0, 0.9}, {1, 1})), 0.1 * std::sqrt(2.0), 0.1,
              1, {1, 1});
  }
  SUBCASE("4. leaving through a corner from inside: the x side (first axis)") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({0, 0}, {1, 1}));
    check_hit(s, std::sqrt(2.0), 1, 1, {0, 1});
  }
  SUBCASE("5. entering at a corner from outside: both sides candidates, the x side reported") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({-3, -3}, {1, 1}));
    CHECK(names(s.faces) == Names{"-x", "-y"});
    check_hit(s, 2 * std::sqrt(2.0), -1, -1, {0, -1});
    const RaySquare t = intersect_canonical_square(Ray2::unit({3, -2}, {-2, 1}));
    check_hit(t, std::sqrt(5.0), 1, -1, {0, 1});
  }
  SUBCASE("6. just past a corner by 1e-9: a miss; just inside: a hit") {
    CHECK_FALSE(intersect_canonical_square(Ray2::unit({-3, -1 - 1e-9}, {1, 0})).hit.has_value());
    check_hit(intersect_canonical_square(Ray2::unit({-3, -1 + 1e-9}, {1, 0})), 2, -1, -1 + 1e-9,
              {0, -1});
  }
  SUBCASE("7. grazing along a side from outside: touches the near corner") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({-3, 1}, {1, 0}));
    CHECK(names(s.faces) == Names{"+y", "-x"});
    check_hit(s, 2, -1, 1, {0, -1});
  }
  SUBCASE("8. starting on a side, running along it: no hit (it does not enter through it)") {
    const RaySquare s = intersect_canonical_square(Ray2::unit({1, 0}, {0, 1}));
    CHECK(names(s.faces) == Names{"+x"});
    CHECK_FALSE(s.inside);
    CHECK_FALSE(s.hit.has_value());
  }
  SUBCASE("9. starting on a side: heading in, a hit at t = 0 with I = A; heading out, none") {
    const RaySquare in = intersect_canonical_square(Ray2::unit({1, 0.5}, {-1, 0.3}));
    CHECK_FALSE(in.inside);
    check_hit(in, 0, 1, 0.5, {0, 1});
    CHECK(exactly(in.hit->t, 0));
    const RaySquare out = intersect_canonical_square(Ray2::unit({1, 0.5}, {1, 0.3}));
    CHECK_FALSE(out.inside);
    CHECK_FALSE(out.hit.has_value());
    // a start one ulp inside the side is on it (the data's rounding): the same answers
    const RaySquare ulp =
        intersect_canonical_square(Ray2::unit({std::nextafter(1.0, 0.0), 0.5}, {-1, 0.3}));
    CHECK_FALSE(ulp.inside);
    CHECK(exactly(ulp.hit->t, 0));
    CHECK(exactly(ulp.hit->I.x, 1));
  }
  SUBCASE("10. starting at a corner: in along the diagonal at t = 0, out: none") {
    const RaySquare in = intersect_canonical_square(Ray2::unit({1, 1}, {-1, -1}));
    check_hit(in, 0, 1, 1, {0, 1});
    CHECK_FALSE(intersect_canonical_square(Ray2::unit({1, 1}, {1, 0.5})).hit.has_value());
    // along the top side from its corner: in through the +x side's end
    check_hit(intersect_canonical_square(Ray2::unit({1, 1}, {-1, 0})), 0, 1, 1, {0, 1});
  }
  SUBCASE("11. pointing away, and parallel outside: no hit") {
    CHECK_FALSE(intersect_canonical_square(Ray2::unit({-3, 0}, {-1, 0})).hit.has_value());
    CHECK_FALSE(intersect_canonical_square(Ray2::unit({-3, 2}, {1, 0})).hit.has_value());
    CHECK_FALSE(intersect_canonical_square(Ray2::unit({2, 2}, {1, -3})).hit.has_value());
  }
  SUBCASE("12. from 1e8: the landing point to the last digits") {
    check_hit(intersect_canonical_square(Ray2::unit({1e8, 0.3}, {-1, 0})), 1e8 - 1, 1, 0.3, {0, 1});
    // a slanted ray with the direction as given: the line is exact data, so is I
    const Point2 A{1e8, 3e7};
    const Vec2 u = Point2{0.5, 0.2} - A;
    const RaySquare s = intersect_canonical_square(Ray2{A, u});
    const auto e = T::box_reference<2>({A.x, A.y}, {u.x, u.y});
    REQUIRE(s.hit.has_value());
    CHECK(s.hit->I.y == T::within(d(e.I[1]), 2 * kEps, 0));
    CHECK(exactly(s.hit->I.x, 1));
  }
  SUBCASE("13. directions of any length: t in units of the direction") {
    for (double k : {1e-300, 1e-8, 1e8, 1e300}) {
      CAPTURE(k);
      const RaySquare s = intersect_canonical_square(Ray2{{-3, 0.5}, {k, 0}});
      REQUIRE(s.hit.has_value());
      CHECK(s.hit->t * k == T::within(2, 2 * kEps, 0));
      CHECK(exactly(s.hit->I.y, 0.5));
      check_hit(intersect_canonical_square(Ray2::unit({-3, 0.5}, {k, 0})), 2, -1, 0.5, {0, -1});
    }
    check_hit(intersect_canonical_square(Ray2::unit({-3, 0.5}, {5e-324, 0})), 2, -1, 0.5, {0, -1});
  }
}

TEST_CASE("geometry/ray_square: random rays against the slab method in quadruple precision") {
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 6000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const Figure f = draw_figure(rng, static_cast<int>(seed % 3));
    CAPTURE(f.A.x);
    CAPTURE(f.A.y);
    CAPTURE(f.u.x);
    CAPTURE(f.u.y);
    const auto e = T::box_reference<2>({f.A.x, f.A.y}, {f.u.x, f.u.y});
    // within the data's rounding of a side line or a corner, the tolerance policy decides
    if (e.margin < 1e-13 * (1 + std::max(std::abs(f.A.x), std::abs(f.A.y)))) continue;
    ++compared;
    check_against_reference(f, true);
    check_against_reference(f, false);
  }
  CHECK(compared > 5900);
}

TEST_CASE("geometry/ray_square: the hit is on the side named, N its normal, t = |AI|") {
  for (std::uint64_t seed = 0; seed < 6000; ++seed) {
    Rng rng(seed, 1);
    CAPTURE(seed);
    const Figure f = draw_figure(rng, static_cast<int>(seed % 3));
    const RaySquare s = intersect_canonical_square(Ray2::unit(f.A, f.u));
    CHECK(s.inside == s.faces.empty());
    CHECK(s.faces.size() <= 2);
    if (!s.hit) continue;
    const Face face = *s.face;
    const double I[2] = {s.hit->I.x, s.hit->I.y}, N[2] = {s.hit->N.x, s.hit->N.y};
    CHECK(exactly(I[face.axis], face.sign));
    CHECK(std::abs(I[1 - face.axis]) <= 1 + 1e-12 * (1 + s.hit->t));
    CHECK(exactly(N[face.axis], face.sign));
    CHECK(exactly(N[1 - face.axis], 0));
    // from outside the side hit is a candidate; the ray heads into it (or leaves by it)
    if (!s.inside) CHECK(s.faces.contains(face));
    const double u_n = face.axis == 0 ? f.u.x : f.u.y;
    CHECK((s.inside ? u_n * face.sign > 0 : u_n * face.sign < 0));
    const double a = std::max(std::abs(f.A.x), std::abs(f.A.y));
    CHECK(norm(s.hit->I - f.A) == T::within(s.hit->t, 8 * kEps, 8 * kEps * a));
  }
}

TEST_CASE("geometry/ray_square: the square's symmetries permute the answer exactly") {
  // the eight maps of the square onto itself: (x, y) → (±x, ±y) or (±y, ±x), exact on doubles
  struct Symmetry {
    bool swap;
    double sx, sy;
    Vec2 apply(Vec2 v) const { return swap ? Vec2{sx * v.y, sy * v.x} : Vec2{sx * v.x, sy * v.y}; }
    Face apply(Face f) const {
      const int axis = swap ? 1 - f.axis : f.axis;
      return {axis, f.sign * static_cast<int>(axis == 0 ? sx : sy)};
    }
  };
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed, 2);
    CAPTURE(seed);
    const Figure f = draw_figure(rng, static_cast<int>(seed % 3));
    const RaySquare s = intersect_canonical_square(Ray2::unit(f.A, f.u));
    const Symmetry m{rng.chance(0.5), T::sign(rng), T::sign(rng)};
    CAPTURE(m.swap);
    const RaySquare t =
        intersect_canonical_square(Ray2::unit(to_point(m.apply(to_vec(f.A))), m.apply(f.u)));
    CHECK(t.inside == s.inside);
    CHECK(t.faces.size() == s.faces.size());
    s.faces.for_each([&](Face face) { CHECK(t.faces.contains(m.apply(face))); });
    REQUIRE(t.hit.has_value() == s.hit.has_value());
    if (!s.hit) continue;
    // a corner hit may go to the other side: the x-first tie rule is not symmetric
    const Vec2 I = m.apply(to_vec(s.hit->I));
    if (std::abs(std::abs(s.hit->I.x) - 1) + std::abs(std::abs(s.hit->I.y) - 1) > 1e-9)
      CHECK(face_name(*t.face) == face_name(m.apply(*s.face)));
    CHECK(t.hit->t == T::within(s.hit->t, 4 * kEps, 0));
    CHECK(t.hit->I.x == T::within(I.x, 4 * kEps, 4 * kEps));
    CHECK(t.hit->I.y == T::within(I.y, 4 * kEps, 4 * kEps));
  }
}

TEST_SUITE_END();

TEST_CASE("geometry/ray_square_exact: issue 15's lines, decided exactly") {
  SUBCASE("1. a hit near a corner lies on the square") {
    const RaySquare s = intersect_canonical_square_exact(Ray2{{0, -5}, {-0.0009765625000000002, 0.00390625}});
    if (s.hit) {
      CHECK(std::abs(s.hit->I.x) <= 1);
      CHECK(std::abs(s.hit->I.y) <= 1);
    }
    // exactly: the line reaches y = −1 at x = −1 − 2^-50·…: just past the corner, a miss of −y,
    // and x = −1 is reached at y < −1: no hit at all
    CHECK_FALSE(s.hit.has_value());
  }
  SUBCASE("2. an origin inside by an ulp is inside, and exits") {
    const RaySquare s = intersect_canonical_square_exact(Ray2{{-0.9999999999999999, 0}, {0, 1}});
    CHECK(s.inside);
    CHECK(s.faces.empty());
    check_hit(s, 1, -0.9999999999999999, 1, {1, +1});
  }
}

TEST_CASE("geometry/ray_square_exact: at 1, 2 and 3 ulps from a side or a corner, the exact branch") {
  // A on a side (x = ±1 or y = ±1) moved by k ulps: a candidate (closed half-plane) when it is on
  // or beyond, inside when it is within. A ray from outside through a corner exactly, its
  // direction moved by k ulps in x: it enters through −x/+x or ±y accordingly (x first at the
  // corner itself).
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    auto nudge = [k](double x) {
      for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? INFINITY : -INFINITY);
      return x;
    };
    const double unit = std::ldexp(1.0, -static_cast<int>(rng.integer(2, 6)));
    if (seed % 2 == 0) {
      const int axis = static_cast<int>(rng.integer(0, 1));
      const double sign = T::sign(rng);
      double a[2] = {unit * static_cast<double>(rng.integer(-3, 3)), unit * static_cast<double>(rng.integer(-3, 3))};
      a[axis] = nudge(sign);
      const RaySquare s = intersect_canonical_square_exact(Ray2{{a[0], a[1]}, {-sign * (axis == 0), -sign * (axis == 1)}});
      const bool beyond = sign * a[axis] >= 1;  // exact comparison of doubles
      CHECK(s.faces.contains({axis, static_cast<int>(sign)}) == beyond);
      CHECK(s.inside == !beyond);
      REQUIRE(s.hit.has_value());  // heading in (or, from inside, across)
      if (sign * a[axis] == 1) CHECK(exactly(s.hit->t, 0));
    } else {
      // from beyond the corner (sx, sy), straight at it
      const double sx = T::sign(rng), sy = T::sign(rng);
      const double m = static_cast<double>(rng.integer(1, 64)), n = static_cast<double>(rng.integer(1, 64));
      const Point2 A{sx * (1 + m * unit), sy * (1 + n * unit)};
      Vec2 u{-sx * m * unit, -sy * n * unit};  // A + u = (sx, sy), the corner
      u = std::ldexp(1.0, static_cast<int>(rng.integer(-20, 20))) * u;
      u.x = nudge(u.x);
      const RaySquare s = intersect_canonical_square_exact(Ray2{A, u});
      // u_x has the sign of −sx: |u_x| grew when k did too. Then x = sx is reached first, with
      // |y| still > 1 (the x side missed), and the y side holds the landing point; when |u_x|
      // shrank, y = sy is reached with |x| > 1 and the x side is hit.
      const bool x_faster = k * -sx > 0;
      REQUIRE(s.hit.has_value());
      if (k == 0) CHECK(s.face->axis == 0);
      else CHECK(s.face->axis == (x_faster ? 1 : 0));
      CHECK(std::abs(s.hit->I.x) <= 1);
      CHECK(std::abs(s.hit->I.y) <= 1);
    }
  }
}
