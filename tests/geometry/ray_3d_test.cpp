// Pins geometry/ray_3d.h, the course's closing remark: ray/sphere (ray/circle with a 3D cross
// product) and ray/canonical cube [-1,1]³ (six faces, at most three candidates). The contract's
// worked examples; in numbered cases the same branches as in 2D: zero direction, r ≤ 0, behind
// before miss, tangent, start on the sphere heading in or out, start inside, corners and edges
// of the cube (ties go to the first axis), grazing along a face, 1e-200 to 1e200, a unit figure
// seen from 1e8, directions of any length. Property tests against the independent quadruple-
// precision quadratic (sphere) and slab method (cube): branch, t_proj, d², t, I, N; hit on the
// figure, N unit and outward (the face's axis normal for the cube), t = |AI|, through the centre
// at |AC| − r, and the cube's 48 symmetries permuting the answer.
#include "geometry/ray_3d.h"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "geometry/degenerate.h"
#include "geometry/tolerance.h"
#include "support/approx.h"
#include "support/ball_reference.h"
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

void check_point(Point3 got, Point3 expected, double tolerance) {
  CHECK(got.x == T::within(expected.x, tolerance, tolerance));
  CHECK(got.y == T::within(expected.y, tolerance, tolerance));
  CHECK(got.z == T::within(expected.z, tolerance, tolerance));
}
void check_vec(Vec3 got, Vec3 expected, double tolerance) {
  check_point({got.x, got.y, got.z}, {expected.x, expected.y, expected.z}, tolerance);
}
double max_abs(Point3 p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

template <class F>
void check_refused(F&& call, const std::string& field) {
  try {
    call();
    FAIL("no exception");
  } catch (const DegenerateFigure& e) {
    CHECK(e.field() == field);
  }
}

std::vector<std::string> names(const FaceSet<3>& faces) {
  std::vector<std::string> out;
  faces.for_each([&](Face f) { out.emplace_back(face_name(f)); });
  return out;
}
using Names = std::vector<std::string>;

// ---- sphere --------------------------------------------------------------------------------

struct SphereFigure {
  Point3 A;
  Vec3 u;
  Sphere sphere;
};

// Anywhere, inside, far and aimed, nearly tangent, through the centre (as for the circle).
SphereFigure draw_sphere(Rng& rng, int kind) {
  const double size = T::decades(rng, -8, 8);
  const Point3 C = T::point3(rng, size);
  const double r = size * T::decades(rng, -2, 0.5);
  const Vec3 along = *normalized(T::direction3(rng));
  // a unit vector perpendicular to `along`
  const Vec3 side = *normalized(cross(along, T::direction3(rng)));
  const double length = T::decades(rng, -3, 3);
  switch (kind) {
    case 0:
      return {T::point3(rng, 4 * size), T::direction3(rng), {C, r}};
    case 1:
      return {C + rng.uniform(0, 0.999) * r * *normalized(T::direction3(rng)),
              T::direction3(rng),
              {C, r}};
    case 2: {
      const double distance = r * T::decades(rng, 0.5, 6), offset = rng.uniform(-0.99, 0.99) * r;
      return {C + (-distance * along + offset * side), length * along, {C, r}};
    }
    case 3: {
      const double distance = r * T::decades(rng, -1, 4) * T::sign(rng);
      const double offset = r * (1 + T::decades(rng, -13, -3) * T::sign(rng));
      return {C + (-distance * along + offset * side), length * along, {C, r}};
    }
    default: {
      const double distance = r * (1 + T::decades(rng, -3, 4));
      return {C + -distance * along, length * along, {C, r}};
    }
  }
}

bool ambiguous(const T::BallExpected<T::R3>& e, Real r) {
  const Real band = 256 * kEps * T::max(r, e.ac);
  if (T::abs(e.ac - r) < band) return true;
  if (!e.inside && T::abs(e.t_proj) < band) return true;
  return T::abs(T::sqrt(e.d2) - r) < band;
}

// As in ray_circle_test.cpp: `unit_ray` as `epure solve` calls it, the line then known to ε of
// |AC|; with the direction as given, to the arithmetic's rounding only.
void check_sphere(const SphereFigure& f, bool unit_ray) {
  const Ray3 ray = unit_ray ? Ray3::unit(f.A, f.u) : Ray3{f.A, f.u};
  const double length_u = unit_ray ? 1.0 : norm(f.u);
  const RaySphere got = intersect(ray, f.sphere);
  const auto e =
      T::ball_reference(T::real(f.A), T::real(f.u), T::real(f.sphere.C), Real(f.sphere.r));
  const double r = f.sphere.r, ac = d(e.ac);
  CAPTURE(unit_ray);
  const double wobble = unit_ray ? ac : r;
  CHECK(got.inside == e.inside);
  CHECK(got.t_proj * length_u == T::within(d(e.t_proj), 8 * kEps, 8 * kEps * wobble));
  CHECK(got.d2 ==
        T::within(d(e.d2), 8 * kEps, 8 * kEps * wobble * (std::sqrt(d(e.d2)) + kEps * wobble)));
  if (e.behind || e.miss) {
    CHECK(got.reason == (e.behind ? NoHit::behind : NoHit::miss));
    CHECK_FALSE(got.hit.has_value());
    return;
  }
  REQUIRE(got.hit.has_value());
  const double h = d(e.half_chord);
  const double slide = 16 * kEps * wobble * (1 + r / h);
  CHECK(*got.half_chord == T::within(h, 16 * kEps, slide));
  CHECK(got.hit->t * length_u ==
        T::within(d(*e.t), 16 * kEps, slide + 16 * kEps * (unit_ray ? ac : 0)));
  const double I_size = std::min(max_abs(f.A) + d(*e.t), max_abs(f.sphere.C) + r);
  const double I_tolerance = 16 * kEps * I_size + slide;
  CHECK(got.hit->I.x == T::within(d(e.I.x), 0, I_tolerance));
  CHECK(got.hit->I.y == T::within(d(e.I.y), 0, I_tolerance));
  CHECK(got.hit->I.z == T::within(d(e.I.z), 0, I_tolerance));
  CHECK(got.hit->N.x == T::within(d(e.N.x), 0, slide / r + 16 * kEps));
  CHECK(got.hit->N.y == T::within(d(e.N.y), 0, slide / r + 16 * kEps));
  CHECK(got.hit->N.z == T::within(d(e.N.z), 0, slide / r + 16 * kEps));
}

// ---- cube ----------------------------------------------------------------------------------

struct CubeFigure {
  Point3 A;
  Vec3 u;
};
CubeFigure draw_cube(Rng& rng, int kind) {
  switch (kind) {
    case 0:
      return {T::point3(rng, 4), T::direction3(rng)};
    case 1:
      return {T::point3(rng, 0.999), T::direction3(rng)};
    default: {
      const double distance = T::decades(rng, 0.5, 8);
      const Point3 target = T::point3(rng, 1.2);
      const Point3 A = target + distance * *normalized(T::direction3(rng));
      return {A, T::decades(rng, -3, 3) * (target - A)};
    }
  }
}

void check_cube(const CubeFigure& f, bool unit_ray) {
  const Ray3 ray = unit_ray ? Ray3::unit(f.A, f.u) : Ray3{f.A, f.u};
  const double length_u = unit_ray ? 1.0 : norm(f.u);
  const RayCube c = intersect_canonical_cube(ray);
  const auto e = T::box_reference<3>({f.A.x, f.A.y, f.A.z}, {f.u.x, f.u.y, f.u.z});
  CAPTURE(unit_ray);
  CHECK(c.inside == e.inside);
  for (int k = 0; k < 3; ++k) {
    CHECK(c.faces.contains({k, +1}) == e.faces[k]);
    CHECK(c.faces.contains({k, -1}) == e.faces[3 + k]);
  }
  CHECK(c.faces.size() <= 3);
  REQUIRE(c.hit.has_value() == e.t.has_value());
  if (!c.hit) return;
  const double t = d(*e.t);
  CHECK(c.face->axis == e.axis);
  CHECK(c.face->sign == e.sign);
  CHECK(c.hit->t * length_u == T::within(t, 8 * kEps, 8 * kEps * max_abs(f.A)));
  const double wobble = unit_ray ? 4 * kEps * t : 0;
  CHECK(c.hit->I.x == T::within(d(e.I[0]), 4 * kEps, 4 * kEps + wobble));
  CHECK(c.hit->I.y == T::within(d(e.I[1]), 4 * kEps, 4 * kEps + wobble));
  CHECK(c.hit->I.z == T::within(d(e.I[2]), 4 * kEps, 4 * kEps + wobble));
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/ray_3d: the contract's worked examples") {
  SUBCASE("1. sphere: straight at the centre along z") {
    const RaySphere s = intersect(Ray3::unit({0, 0, -5}, {0, 0, 1}), Sphere{{0, 0, 0}, 2});
    CHECK(exactly(s.t_proj, 5));
    CHECK(exactly(s.d2, 0));
    CHECK_FALSE(s.inside);
    REQUIRE(s.hit.has_value());
    CHECK(exactly(s.hit->t, 3));
    check_point(s.hit->I, {0, 0, -2}, 0);
    check_vec(s.hit->N, {0, 0, -1}, 0);
  }
  SUBCASE("2. sphere: pointing away, behind") {
    const RaySphere s = intersect(Ray3::unit({0, 0, 5}, {0, 0, 1}), Sphere{{0, 0, 0}, 2});
    CHECK(exactly(s.t_proj, -5));
    CHECK(s.reason == NoHit::behind);
    CHECK_FALSE(s.hit.has_value());
  }
  SUBCASE("3. cube: straight at the −z face, direction of length 3") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({0.5, 0.5, -4}, {0, 0, 3}));
    CHECK(names(c.faces) == Names{"-z"});
    CHECK_FALSE(c.inside);
    REQUIRE(c.hit.has_value());
    CHECK(exactly(c.hit->t, 3));
    check_point(c.hit->I, {0.5, 0.5, -1}, 0);
    check_vec(c.hit->N, {0, 0, -1}, 0);
  }
  SUBCASE("4. cube: from the centre, out through +x") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({0, 0, 0}, {1, 0.5, 0.25}));
    CHECK(names(c.faces).empty());
    CHECK(c.inside);
    REQUIRE(c.hit.has_value());
    CHECK(c.hit->t == doctest::Approx(1.14564392373896).epsilon(4 * kEps));
    check_point(c.hit->I, {1, 0.5, 0.25}, 2 * kEps);
    check_vec(c.hit->N, {1, 0, 0}, 0);
  }
}

TEST_CASE("geometry/ray_3d: every branch of ray/sphere") {
  const Sphere unit{{0, 0, 0}, 1};
  SUBCASE("1. zero direction (u), r ≤ 0 (r)") {
    check_refused([&] { intersect(Ray3{{0, 0, 0}, {0, 0, 0}}, unit); }, "u");
    check_refused([&] { Ray3::unit({0, 0, 0}, {0, -0.0, 0}); }, "u");
    for (double r : {0.0, -2.0, std::numeric_limits<double>::quiet_NaN()}) {
      CAPTURE(r);
      check_refused(
          [&] {
            intersect(Ray3::unit({0, 0, 0}, {1, 0, 0}), Sphere{{0, 0, 0}, r});
          },
          "r");
    }
  }
  SUBCASE("2. behind before miss; miss") {
    CHECK(intersect(Ray3::unit({-5, 5, 5}, {-1, 0, 0}), unit).reason == NoHit::behind);
    const RaySphere m = intersect(Ray3::unit({-5, 0, 3}, {1, 0, 0}), unit);
    CHECK(m.reason == NoHit::miss);
    CHECK(exactly(m.d2, 9));
  }
  SUBCASE("3. tangent: a hit at P") {
    const RaySphere s = intersect(Ray3::unit({-5, 0, 2}, {1, 0, 0}), Sphere{{0, 0, 0}, 2});
    REQUIRE(s.hit.has_value());
    CHECK(exactly(s.hit->t, 5));
    check_point(s.hit->I, {0, 0, 2}, 0);
    check_vec(s.hit->N, {0, 0, 1}, 0);
    CHECK(exactly(*s.half_chord, 0));
  }
  SUBCASE("4. from inside: the exit; from the centre, t = r") {
    const RaySphere s = intersect(Ray3::unit({0.5, 0, 0}, {-1, 0, 0}), unit);
    CHECK(s.inside);
    CHECK(exactly(s.hit->t, 1.5));
    check_vec(s.hit->N, {-1, 0, 0}, 0);
    const RaySphere c = intersect(Ray3::unit({1, 2, 3}, {-2, 7, 1}), Sphere{{1, 2, 3}, 4});
    CHECK(c.hit->t == doctest::Approx(4).epsilon(2 * kEps));
  }
  SUBCASE("5. from the sphere: in at t = 0 (I = A), out behind") {
    const RaySphere in = intersect(Ray3::unit({0, 0.6, 0.8}, {0, -1, 0}), unit);
    CHECK_FALSE(in.inside);
    REQUIRE(in.hit.has_value());
    CHECK(exactly(in.hit->t, 0));
    check_point(in.hit->I, {0, 0.6, 0.8}, 0);
    check_vec(in.hit->N, {0, 0.6, 0.8}, 2 * kEps);
    CHECK(intersect(Ray3::unit({0, 0.6, 0.8}, {0, 1, 0}), unit).reason == NoHit::behind);
  }
  SUBCASE("6. every scale, 1e-200 to 1e200") {
    for (double k : {1e-200, 1e-8, 1e8, 1e200}) {
      CAPTURE(k);
      const RaySphere s =
          intersect(Ray3::unit({0, k, -5 * k}, {0, 0, 7}), Sphere{{0, 0, 0}, 2 * k});
      REQUIRE(s.hit.has_value());
      CHECK(s.hit->t == doctest::Approx((5 - std::sqrt(3.0)) * k).epsilon(4 * kEps));
      check_vec(s.hit->N, {0, 0.5, -std::sqrt(3.0) / 2}, 4 * kEps);
    }
  }
  SUBCASE("7. a unit sphere seen from 1e8: the hit point to the last digits") {
    const RaySphere s = intersect(Ray3::unit({1e8, 0.6, 0}, {-1, 0, 0}), unit);
    check_point(s.hit->I, {0.8, 0.6, 0}, 2 * kEps);
    check_vec(s.hit->N, {0.8, 0.6, 0}, 2 * kEps);
  }
  SUBCASE("8. an exact tangent whose direction was rounded to unit length stays tangent") {
    const RaySphere s = intersect(Ray3::unit({-8, -19, 7}, {3, 4, 0}), Sphere{{0, 0, 7}, 5});
    REQUIRE(s.hit.has_value());
    CHECK(exactly(*s.half_chord, 0));
    CHECK(s.hit->t == doctest::Approx(20).epsilon(4 * kEps));
    check_point(s.hit->I, {4, -3, 7}, 4 * kEps);
  }
  SUBCASE("9. directions of any length: t in units of the direction") {
    for (double k : {1e-300, 1e-8, 1e8, 1e300}) {
      CAPTURE(k);
      const RaySphere s = intersect(Ray3{{0, 0, -5}, {0, 0, k}}, Sphere{{0, 0, 0}, 2});
      CHECK(s.hit->t * k == T::within(3, 2 * kEps, 0));
      CHECK(s.t_proj * k == T::within(5, 2 * kEps, 0));
    }
  }
}

TEST_CASE("geometry/ray_3d: every branch of ray/cube") {
  SUBCASE("1. zero direction: field u") {
    check_refused([] { intersect_canonical_cube(Ray3{{0, 0, 0}, {0, 0, 0}}); }, "u");
  }
  SUBCASE("2. up to three candidate faces, in the contract's order") {
    CHECK(names(intersect_canonical_cube(Ray3::unit({3, 3, 3}, {1, 0, 0})).faces) ==
          Names{"+x", "+y", "+z"});
    CHECK(names(intersect_canonical_cube(Ray3::unit({-3, 0, 3}, {1, 0, 0})).faces) ==
          Names{"+z", "-x"});
    CHECK(names(intersect_canonical_cube(Ray3::unit({-3, -3, -3}, {1, 0, 0})).faces) ==
          Names{"-x", "-y", "-z"});
    CHECK(names(intersect_canonical_cube(Ray3::unit({0, 1, 0}, {1, 0, 0})).faces) == Names{"+y"});
  }
  SUBCASE("3. a corner from outside: the x face (first axis)") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({-3, -3, -3}, {1, 1, 1}));
    REQUIRE(c.hit.has_value());
    CHECK(c.hit->t == doctest::Approx(2 * std::sqrt(3.0)).epsilon(4 * kEps));
    check_point(c.hit->I, {-1, -1, -1}, 0);
    CHECK(face_name(*c.face) == "-x");
  }
  SUBCASE("4. an edge from outside: the first axis's face") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({0.5, -3, -3}, {0, 1, 1}));
    REQUIRE(c.hit.has_value());
    check_point(c.hit->I, {0.5, -1, -1}, 0);
    CHECK(face_name(*c.face) == "-y");
  }
  SUBCASE("5. out through a corner from inside: +x") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({0, 0, 0}, {2, 2, 2}));
    CHECK(c.inside);
    check_point(c.hit->I, {1, 1, 1}, 0);
    CHECK(face_name(*c.face) == "+x");
  }
  SUBCASE("6. on a face: in at t = 0 with I = A, out or along it: no hit") {
    const RayCube in = intersect_canonical_cube(Ray3::unit({0.2, 0.3, 1}, {0.1, 0, -1}));
    CHECK_FALSE(in.inside);
    CHECK(exactly(in.hit->t, 0));
    check_point(in.hit->I, {0.2, 0.3, 1}, 0);
    check_vec(in.hit->N, {0, 0, 1}, 0);
    CHECK_FALSE(intersect_canonical_cube(Ray3::unit({0.2, 0.3, 1}, {0, 0, 1})).hit.has_value());
    CHECK_FALSE(intersect_canonical_cube(Ray3::unit({0.2, 0.3, 1}, {1, 1, 0})).hit.has_value());
  }
  SUBCASE("7. grazing along a face from outside: touches its near edge") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({-3, 0, 1}, {1, 0, 0}));
    REQUIRE(c.hit.has_value());
    check_point(c.hit->I, {-1, 0, 1}, 0);
    CHECK(face_name(*c.face) == "-x");
  }
  SUBCASE("8. misses: beside, parallel outside, away") {
    CHECK_FALSE(intersect_canonical_cube(Ray3::unit({-3, 0, 1.5}, {1, 0, 0})).hit.has_value());
    CHECK_FALSE(intersect_canonical_cube(Ray3::unit({-3, 0, 0}, {-1, 0, 0})).hit.has_value());
    CHECK_FALSE(intersect_canonical_cube(Ray3::unit({-3, -3, 0}, {1, 0.2, 0})).hit.has_value());
  }
  SUBCASE("9. from 1e8: the landing point to the last digits") {
    const RayCube c = intersect_canonical_cube(Ray3::unit({0.25, 1e8, -0.5}, {0, -1, 0}));
    CHECK(c.hit->t == doctest::Approx(1e8 - 1).epsilon(kEps));
    check_point(c.hit->I, {0.25, 1, -0.5}, 0);
  }
  SUBCASE("10. directions of any length") {
    for (double k : {1e-300, 1e8, 1e300}) {
      CAPTURE(k);
      const RayCube c = intersect_canonical_cube(Ray3{{0.5, 0.5, -4}, {0, 0, k}});
      CHECK(c.hit->t * k == T::within(3, 2 * kEps, 0));
    }
  }
}

TEST_CASE("geometry/ray_3d: random spheres against quadruple precision") {
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const SphereFigure f = draw_sphere(rng, static_cast<int>(seed % 5));
    const auto e =
        T::ball_reference(T::real(f.A), T::real(f.u), T::real(f.sphere.C), Real(f.sphere.r));
    if (ambiguous(e, f.sphere.r)) continue;
    ++compared;
    check_sphere(f, true);
    check_sphere(f, false);
  }
  CHECK(compared > 3600);
}

TEST_CASE(
    "geometry/ray_3d: sphere hits lie on the sphere, N unit and outward, t = |AI|, centre rays at "
    "|AC| − r") {
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    Rng rng(seed, 1);
    CAPTURE(seed);
    const SphereFigure f = draw_sphere(rng, static_cast<int>(seed % 5));
    const RaySphere s = intersect(Ray3::unit(f.A, f.u), f.sphere);
    const double r = f.sphere.r, ac = norm(f.sphere.C - f.A);
    if (seed % 5 == 4) {
      // drawn through the centre from outside
      REQUIRE(s.hit.has_value());
      CHECK(s.hit->t == T::within(ac - r, 8 * kEps, 8 * kEps * ac));
    }
    if (!s.hit) continue;
    const T::R3 CI = T::real(s.hit->I) - T::real(f.sphere.C);
    const double size = std::min(max_abs(f.A) + s.hit->t, max_abs(f.sphere.C) + r);
    CHECK(d(T::norm(CI)) == T::within(r, 0, 16 * kEps * (size + r) + kRoundoff * std::max(r, ac)));
    CHECK(norm(s.hit->N) == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(d(T::dot(T::real(s.hit->N), CI)) > 0);
    CHECK(norm(s.hit->I - f.A) == T::within(s.hit->t, 16 * kEps, 16 * kEps * (size + ac)));
  }
}

TEST_CASE("geometry/ray_3d: random cube rays against the slab method in quadruple precision") {
  int compared = 0;
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const CubeFigure f = draw_cube(rng, static_cast<int>(seed % 3));
    const auto e = T::box_reference<3>({f.A.x, f.A.y, f.A.z}, {f.u.x, f.u.y, f.u.z});
    if (e.margin < 1e-13 * (1 + max_abs(f.A))) continue;
    ++compared;
    check_cube(f, true);
    check_cube(f, false);

    const RayCube c = intersect_canonical_cube(Ray3::unit(f.A, f.u));
    if (!c.hit) continue;
    const double I[3] = {c.hit->I.x, c.hit->I.y, c.hit->I.z},
                 N[3] = {c.hit->N.x, c.hit->N.y, c.hit->N.z};
    const Face face = *c.face;
    CHECK(exactly(I[face.axis], face.sign));
    CHECK(exactly(N[face.axis], face.sign));
    for (int k = 0; k < 3; ++k)
      if (k != face.axis) {
        CHECK(std::abs(I[k]) <= 1);
        CHECK(exactly(N[k], 0));
      }
    if (!c.inside) CHECK(c.faces.contains(face));
    CHECK(norm(c.hit->I - f.A) == T::within(c.hit->t, 8 * kEps, 8 * kEps * max_abs(f.A)));
  }
  CHECK(compared > 3900);
}

TEST_CASE("geometry/ray_3d: the cube's 48 symmetries permute the answer") {
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    Rng rng(seed, 2);
    CAPTURE(seed);
    const CubeFigure f = draw_cube(rng, static_cast<int>(seed % 3));
    // a permutation of the axes and a sign for each: exact on doubles
    std::array<int, 3> axis{0, 1, 2};
    for (int i = 2; i > 0; --i) std::swap(axis[i], axis[rng.integer(0, i)]);
    const std::array<double, 3> sign{T::sign(rng), T::sign(rng), T::sign(rng)};
    auto map = [&](Vec3 v) {
      const double c[3] = {v.x, v.y, v.z};
      double m[3];
      for (int k = 0; k < 3; ++k) m[axis[k]] = sign[axis[k]] * c[k];
      return Vec3{m[0], m[1], m[2]};
    };
    const RayCube a = intersect_canonical_cube(Ray3::unit(f.A, f.u));
    const Vec3 A2 = map(to_vec(f.A));
    const RayCube b = intersect_canonical_cube(Ray3::unit({A2.x, A2.y, A2.z}, map(f.u)));
    CHECK(a.inside == b.inside);
    CHECK(a.faces.size() == b.faces.size());
    a.faces.for_each([&](Face face) {
      CHECK(
          b.faces.contains({axis[face.axis], face.sign * static_cast<int>(sign[axis[face.axis]])}));
    });
    REQUIRE(a.hit.has_value() == b.hit.has_value());
    if (!a.hit) continue;
    // normalising the direction need not round alike for permuted coordinates (std::hypot of
    // three): the line may turn by ε about A, which moves I by ε·t
    CHECK(b.hit->t == T::within(a.hit->t, 4 * kEps, 0));
    const Vec3 I = map(to_vec(a.hit->I));
    const double tolerance = 4 * kEps * (1 + a.hit->t);
    CHECK(b.hit->I.x == T::within(I.x, 0, tolerance));
    CHECK(b.hit->I.y == T::within(I.y, 0, tolerance));
    CHECK(b.hit->I.z == T::within(I.z, 0, tolerance));
  }
}

TEST_SUITE_END();

TEST_CASE("geometry/ray_3d exact: at 1, 2 and 3 ulps from a boundary, the branch is the exact one") {
  // The sphere: A on it at a Pythagorean point (1, 2, 2)·k of radius 3k, r moved by k ulps (inside
  // when r grew); a tangent line through that point, r moved (a chord when r grew, a miss when it
  // shrank). The cube: A on a face moved by k ulps (a candidate on or beyond, inside within);
  // from beyond an edge of the cube straight at it, u_x moved (the y or the x face hit, x first
  // on the edge itself).
  static constexpr double kTriples[][4] = {{1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9}, {2, 6, 9, 11}};
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    Rng rng(seed);
    CAPTURE(seed);
    const int k = static_cast<int>(rng.integer(-3, 3));
    CAPTURE(k);
    auto nudge = [k](double x) {
      for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? INFINITY : -INFINITY);
      return x;
    };
    const double unit = std::ldexp(1.0, static_cast<int>(rng.integer(-8, 4)));
    if (seed % 4 < 2) {
      const auto& tr = kTriples[rng.integer(0, 3)];
      const double far = std::ldexp(1.0, static_cast<int>(rng.integer(0, 30)));
      auto grid = [&] { return unit * std::round(rng.uniform(-far, far)); };
      const Point3 C{grid(), grid(), grid()};
      const Vec3 CP{unit * tr[0] * T::sign(rng), unit * tr[1] * T::sign(rng), unit * tr[2] * T::sign(rng)};
      const double r = nudge(unit * tr[3]);
      if (seed % 4 == 0) {
        const RaySphere s = intersect_exact(Ray3{C + CP, -1.0 * CP}, {C, r});
        CHECK(s.inside == (k > 0));
        REQUIRE(s.hit.has_value());
        if (k == 0) CHECK(exactly(s.hit->t, 0));
      } else {
        // a tangent at P: perpendicular to CP, integer coordinates (CP × e_x or CP × e_y)
        const Vec3 e = std::abs(CP.x) < std::abs(CP.y) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        const Vec3 tangent = cross(CP, e);
        const double back = static_cast<double>(rng.integer(1, 1024));
        const RaySphere s = intersect_exact(Ray3{C + CP + (-back) * tangent, tangent}, {C, r});
        CHECK(s.hit.has_value() == (k >= 0));
        if (k == 0) CHECK(exactly(*s.half_chord, 0));
        if (k < 0) CHECK(s.reason == NoHit::miss);
      }
    } else if (seed % 4 == 2) {
      const int axis = static_cast<int>(rng.integer(0, 2));
      const double sign = T::sign(rng);
      double a[3] = {unit / 64 * static_cast<double>(rng.integer(-3, 3)),
                     unit / 64 * static_cast<double>(rng.integer(-3, 3)),
                     unit / 64 * static_cast<double>(rng.integer(-3, 3))};
      a[axis] = nudge(sign);
      double u[3] = {0, 0, 0};
      u[axis] = -sign;
      const RayCube c = intersect_canonical_cube_exact(Ray3{{a[0], a[1], a[2]}, {u[0], u[1], u[2]}});
      const bool beyond = sign * a[axis] >= 1;
      CHECK(c.faces.contains({axis, static_cast<int>(sign)}) == beyond);
      CHECK(c.inside == !beyond);
      REQUIRE(c.hit.has_value());
      if (sign * a[axis] == 1) CHECK(exactly(c.hit->t, 0));
    } else {
      // beyond the edge x = sx, y = sy (z = 0), straight at it
      const double sx = T::sign(rng), sy = T::sign(rng);
      const double step = unit / 16;
      const double m = static_cast<double>(rng.integer(1, 64)), n = static_cast<double>(rng.integer(1, 64));
      const Point3 A{sx * (1 + m * step), sy * (1 + n * step), 0};
      Vec3 u{-sx * m * step, -sy * n * step, 0};
      u = std::ldexp(1.0, static_cast<int>(rng.integer(-20, 20))) * u;
      u.x = nudge(u.x);
      const RayCube c = intersect_canonical_cube_exact(Ray3{A, u});
      const bool x_faster = k * -sx > 0;  // |u_x| grew: x = sx reached first, |y| still > 1
      REQUIRE(c.hit.has_value());
      CHECK(c.face->axis == (k != 0 && x_faster ? 1 : 0));
      CHECK(std::abs(c.hit->I.x) <= 1);
      CHECK(std::abs(c.hit->I.y) <= 1);
      CHECK(std::abs(c.hit->I.z) <= 1);
    }
  }
}
