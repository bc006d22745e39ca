// ns per call of each geometry kernel on a fixed random batch, next to a deliberately plain
// reference in the same binary: the textbook quadratic formula for circle, sphere and ellipse
// (always a square root, no early exit) and the slab method for square, cube and rectangle.
// The target: the course-method kernels no slower than their reference. For the circle
// and the square, a third line: the course's method written as plainly as the references
// (ref::*_course_lean, no tolerance, no construction data), to tell the method's cost from that
// of our kernels' care for precision.
//
// Each benchmark cycles through one batch of 4096 instances drawn by PCG32 (rays aimed near the
// figure two times in three, one origin in ten inside, as a worksheet mixes them), one call per
// iteration, so Time is ns per call. The references are noinline, as our kernels (in their own
// library) are, and every result goes through DoNotOptimize whole. Counters: `hit` is the share
// of hits in the batch; `agree` (references only) the share of instances where the reference
// and our kernel agree on hit or miss and on t within 1e-9: the two compute the same thing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "exercises/rng.h"
#include "geometry/projection.h"
#include "geometry/ray_3d.h"
#include "geometry/ray_circle.h"
#include "geometry/ray_square.h"
#include "geometry/ray_transformed.h"
#include "geometry/segments.h"

namespace {

namespace geo = epure::geo;
using geo::Point2;
using geo::Point3;
using geo::Vec2;
using geo::Vec3;

constexpr std::size_t kBatch = 4096;  // a power of two: the index wraps with a mask
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ---- The batches --------------------------------------------------------------------------

class Draw {
 public:
  explicit Draw(std::uint64_t stream) : rng_(20240611, stream) {}

  double coordinate() { return rng_.uniform(-6, 6); }
  double size() { return rng_.uniform(0.5, 4); }
  double angle() { return rng_.uniform(-180, 180); }
  bool chance(double p) { return rng_.chance(p); }
  Point2 point2() { return {coordinate(), coordinate()}; }
  Point3 point3() { return {coordinate(), coordinate(), coordinate()}; }

  Vec2 unit2() {
    const double a = rng_.uniform(0, 2 * std::numbers::pi);
    return {std::cos(a), std::sin(a)};
  }
  Vec3 unit3() {
    const double z = rng_.uniform(-1, 1), a = rng_.uniform(0, 2 * std::numbers::pi);
    const double s = std::sqrt(1 - z * z);
    return {s * std::cos(a), s * std::sin(a), z};
  }

  // A ray towards a figure centred at C of size `radius`: from inside one time in ten; else from
  // anywhere, aimed within 1.5 radius of C two times in three, any way otherwise. Unit direction.
  geo::Ray2 ray2(Point2 C, double radius) {
    const Point2 A = chance(0.1) ? C + (0.9 * radius * rng_.uniform()) * unit2() : point2();
    Vec2 u = chance(2.0 / 3) ? (C + (1.5 * radius * rng_.uniform()) * unit2()) - A : unit2();
    if (u.x == 0 && u.y == 0) u = unit2();
    return geo::Ray2::unit(A, u);
  }
  geo::Ray3 ray3(Point3 C, double radius) {
    const Point3 A = chance(0.1) ? C + (0.9 * radius * rng_.uniform()) * unit3() : point3();
    Vec3 u = chance(2.0 / 3) ? (C + (1.5 * radius * rng_.uniform()) * unit3()) - A : unit3();
    if (u.x == 0 && u.y == 0 && u.z == 0) u = unit3();
    return geo::Ray3::unit(A, u);
  }

 private:
  epure::Rng rng_;
};

template <class T, class F>
std::vector<T> batch(std::uint64_t stream, F&& make) {
  Draw draw(stream);
  std::vector<T> items;
  items.reserve(kBatch);
  for (std::size_t i = 0; i < kBatch; ++i) items.push_back(make(draw));
  return items;
}

struct ProjectionCase {
  Point2 A, B, C;
};
struct SegmentsCase {
  Point2 A, B, C, D;
};
struct CircleCase {
  geo::Ray2 ray;
  geo::Circle circle;
};
struct EllipseCase {
  geo::Ray2 ray;
  geo::Ellipse ellipse;
};
struct RectangleCase {
  geo::Ray2 ray;
  geo::Rectangle rectangle;
};
struct SphereCase {
  geo::Ray3 ray;
  geo::Sphere sphere;
};

const auto& projections() {
  static const auto cases = batch<ProjectionCase>(1, [](Draw& d) {
    const Point2 A = d.point2();
    Point2 B = d.point2();
    if (B.x == A.x && B.y == A.y) B.x += 1;
    return ProjectionCase{A, B, d.point2()};
  });
  return cases;
}

// CD passes through a point of the line (AB) near the segment half the time: a healthy share of
// crossings, the rest outside.
const auto& segment_pairs() {
  static const auto cases = batch<SegmentsCase>(2, [](Draw& d) {
    const Point2 A = d.point2();
    Point2 B = d.point2();
    if (B.x == A.x && B.y == A.y) B.x += 1;
    const Point2 C = d.point2();
    Point2 D = d.point2();
    if (d.chance(0.5)) D = C + (0.5 + 1.5 * d.size() / 4) * ((A + (1.4 * d.size() / 4 - 0.2) * (B - A)) - C);
    if (D.x == C.x && D.y == C.y) D.y += 1;
    return SegmentsCase{A, B, C, D};
  });
  return cases;
}

const auto& circles() {
  static const auto cases = batch<CircleCase>(3, [](Draw& d) {
    const geo::Circle circle{d.point2(), d.size()};
    return CircleCase{d.ray2(circle.C, circle.r), circle};
  });
  return cases;
}

const auto& square_rays() {
  static const auto cases = batch<geo::Ray2>(4, [](Draw& d) { return d.ray2({0, 0}, 1); });
  return cases;
}

const auto& ellipses() {
  static const auto cases = batch<EllipseCase>(5, [](Draw& d) {
    const geo::Ellipse e{d.point2(), d.size(), d.size(), d.angle()};
    return EllipseCase{d.ray2(e.C, std::max(e.a, e.b)), e};
  });
  return cases;
}

const auto& rectangles() {
  static const auto cases = batch<RectangleCase>(6, [](Draw& d) {
    const geo::Rectangle r{d.point2(), d.size(), d.size(), d.angle()};
    return RectangleCase{d.ray2(r.C, std::hypot(r.w, r.h)), r};
  });
  return cases;
}

const auto& spheres() {
  static const auto cases = batch<SphereCase>(7, [](Draw& d) {
    const geo::Sphere sphere{d.point3(), d.size()};
    return SphereCase{d.ray3(sphere.C, sphere.r), sphere};
  });
  return cases;
}

const auto& cube_rays() {
  static const auto cases = batch<geo::Ray3>(8, [](Draw& d) { return d.ray3({0, 0, 0}, 1); });
  return cases;
}

// ---- The plain references -----------------------------------------------------------------
// What a first ray tracer writes: no tolerance, no construction data, no care for cancellation.
namespace ref {

struct Projection {
  double t;
  Point2 P;
};

[[gnu::noinline]] Projection project(Point2 A, Point2 B, Point2 C) {
  const Vec2 AB = B - A, AC = C - A;
  const double t = (AB.x * AC.x + AB.y * AC.y) / (AB.x * AB.x + AB.y * AB.y);
  return {t, A + t * AB};
}

struct Crossing {
  bool intersects;
  double t_ab, t_cd;
  Point2 I;
};

[[gnu::noinline]] Crossing intersect_segments(Point2 A, Point2 B, Point2 C, Point2 D) {
  const Vec2 AB = B - A, CD = D - C, AC = C - A;
  const double den = AB.x * CD.y - AB.y * CD.x;
  if (den == 0) return {false, 0, 0, {}};
  const double t_ab = (AC.x * CD.y - AC.y * CD.x) / den;
  const double t_cd = (AC.x * AB.y - AC.y * AB.x) / den;
  const bool in = t_ab >= 0 && t_ab <= 1 && t_cd >= 0 && t_cd <= 1;
  return {in, t_ab, t_cd, A + t_ab * AB};
}

// |M + t·u|² = 1 for M = A − C scaled to a unit figure: a t² + b t + c = 0, the nearest root
// t ≥ 0. The square root is taken whether or not there is a hit.
std::optional<double> unit_quadratic(double a, double b, double c) {
  const double disc = b * b - 4 * a * c;
  const double root = std::sqrt(std::max(disc, 0.0));
  if (disc < 0) return std::nullopt;
  double t = (-b - root) / (2 * a);
  if (t < 0) t = (-b + root) / (2 * a);
  if (t < 0) return std::nullopt;
  return t;
}

[[gnu::noinline]] std::optional<geo::Hit2> ray_circle(const geo::Ray2& ray, const geo::Circle& c) {
  const Vec2 u = ray.direction, m = ray.origin - c.C;
  const auto t = unit_quadratic(u.x * u.x + u.y * u.y, 2 * (m.x * u.x + m.y * u.y),
                                m.x * m.x + m.y * m.y - c.r * c.r);
  if (!t) return std::nullopt;
  const Point2 I = ray.at(*t);
  return geo::Hit2{*t, I, (I - c.C) / c.r};
}

[[gnu::noinline]] std::optional<geo::Hit3> ray_sphere(const geo::Ray3& ray, const geo::Sphere& s) {
  const Vec3 u = ray.direction, m = ray.origin - s.C;
  const auto t = unit_quadratic(u.x * u.x + u.y * u.y + u.z * u.z,
                                2 * (m.x * u.x + m.y * u.y + m.z * u.z),
                                m.x * m.x + m.y * m.y + m.z * m.z - s.r * s.r);
  if (!t) return std::nullopt;
  const Point3 I = ray.at(*t);
  return geo::Hit3{*t, I, (I - s.C) / s.r};
}

// Slab method on [-1,1]^Dim: the ray is inside slab k for t between (±1 − A_k)/u_k; the box is
// the intersection of the slabs. Returns t, the axis and the side's sign.
struct SlabHit {
  double t;
  int axis, sign;
};
template <int Dim>
std::optional<SlabHit> slabs(const double* A, const double* u) {
  double t_near = -kInfinity, t_far = kInfinity;
  int near_axis = 0, far_axis = 0;
  for (int k = 0; k < Dim; ++k) {
    const double inv = 1 / u[k];
    double t0 = (-1 - A[k]) * inv, t1 = (1 - A[k]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near) t_near = t0, near_axis = k;
    if (t1 < t_far) t_far = t1, far_axis = k;
  }
  if (t_near > t_far || t_far < 0) return std::nullopt;
  if (t_near >= 0) return SlabHit{t_near, near_axis, u[near_axis] > 0 ? -1 : +1};  // entering
  return SlabHit{t_far, far_axis, u[far_axis] > 0 ? +1 : -1};                      // leaving
}

[[gnu::noinline]] std::optional<geo::Hit2> ray_square(const geo::Ray2& ray) {
  const double A[2] = {ray.origin.x, ray.origin.y}, u[2] = {ray.direction.x, ray.direction.y};
  const auto s = slabs<2>(A, u);
  if (!s) return std::nullopt;
  Vec2 N{};
  (s->axis == 0 ? N.x : N.y) = s->sign;
  return geo::Hit2{s->t, ray.at(s->t), N};
}

[[gnu::noinline]] std::optional<geo::Hit3> ray_cube(const geo::Ray3& ray) {
  const double A[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double u[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const auto s = slabs<3>(A, u);
  if (!s) return std::nullopt;
  double N[3] = {0, 0, 0};
  N[s->axis] = s->sign;
  return geo::Hit3{s->t, ray.at(s->t), {N[0], N[1], N[2]}};
}

// The course's methods, as plainly: for a unit direction, P is at t_proj = u·AC, CP² = AC² − t_proj²
// (Pythagoras in ACP), rejected early when behind or too far, then PI = √(r² − CP²).
[[gnu::noinline]] std::optional<geo::Hit2> ray_circle_course_lean(const geo::Ray2& ray,
                                                                   const geo::Circle& c) {
  const Vec2 u = ray.direction, AC = c.C - ray.origin;
  const double t_proj = u.x * AC.x + u.y * AC.y;
  const double ac2 = AC.x * AC.x + AC.y * AC.y, r2 = c.r * c.r;
  const bool inside = ac2 < r2;
  if (!inside && t_proj < 0) return std::nullopt;  // behind
  const double d2 = ac2 - t_proj * t_proj;
  if (d2 > r2) return std::nullopt;  // miss
  const double t = inside ? t_proj + std::sqrt(r2 - d2) : t_proj - std::sqrt(r2 - d2);
  const Point2 I = ray.at(t);
  return geo::Hit2{t, I, (I - c.C) / c.r};
}

// From outside, only the sides whose outer half-plane holds A can be met first; from inside,
// the side met first along each axis.
[[gnu::noinline]] std::optional<geo::Hit2> ray_square_course_lean(const geo::Ray2& ray) {
  const double A[2] = {ray.origin.x, ray.origin.y}, u[2] = {ray.direction.x, ray.direction.y};
  const bool inside = std::abs(A[0]) < 1 && std::abs(A[1]) < 1;
  double best = inside ? kInfinity : -kInfinity;
  int axis = -1, sign = 0;
  for (int k = 0; k < 2; ++k) {
    for (int s : {+1, -1}) {
      if (inside ? !(s * u[k] > 0) : !(s * A[k] >= 1 && s * u[k] < 0)) continue;
      const double t = (s - A[k]) / u[k];
      if (!inside && std::abs(A[1 - k] + t * u[1 - k]) > 1) continue;  // not on the side
      if (inside ? t < best : t > best) best = t, axis = k, sign = s;
    }
  }
  if (axis < 0) return std::nullopt;
  Vec2 N{};
  (axis == 0 ? N.x : N.y) = sign;
  return geo::Hit2{best, ray.at(best), N};
}

// Into the figure's frame: A − C and u rotated by −angle, then divided by the half-axes.
struct Frame {
  double c, s;
  Vec2 m, u;
};
Frame frame(const geo::Ray2& ray, Point2 C, double sx, double sy, double angle_deg) {
  const double radians = angle_deg * (std::numbers::pi / 180);
  const double c = std::cos(radians), s = std::sin(radians);
  const Vec2 m = ray.origin - C, u = ray.direction;
  return {c, s, {(c * m.x + s * m.y) / sx, (c * m.y - s * m.x) / sy},
          {(c * u.x + s * u.y) / sx, (c * u.y - s * u.x) / sy}};
}
Vec2 unit_world_normal(const Frame& f, Vec2 n) {  // n in the frame, already divided by sx, sy
  const Vec2 w{f.c * n.x - f.s * n.y, f.s * n.x + f.c * n.y};
  return w / std::sqrt(w.x * w.x + w.y * w.y);
}

[[gnu::noinline]] std::optional<geo::Hit2> ray_ellipse(const geo::Ray2& ray, const geo::Ellipse& e) {
  const Frame f = frame(ray, e.C, e.a, e.b, e.angle_deg);
  const auto t = unit_quadratic(f.u.x * f.u.x + f.u.y * f.u.y, 2 * (f.m.x * f.u.x + f.m.y * f.u.y),
                                f.m.x * f.m.x + f.m.y * f.m.y - 1);
  if (!t) return std::nullopt;
  const Vec2 Ic = f.m + *t * f.u;  // gradient of (x/a)² + (y/b)²: (Ic.x/a, Ic.y/b)
  return geo::Hit2{*t, ray.at(*t), unit_world_normal(f, {Ic.x / e.a, Ic.y / e.b})};
}

[[gnu::noinline]] std::optional<geo::Hit2> ray_rectangle(const geo::Ray2& ray, const geo::Rectangle& r) {
  const Frame f = frame(ray, r.C, r.w, r.h, r.angle_deg);
  const double A[2] = {f.m.x, f.m.y}, u[2] = {f.u.x, f.u.y};
  const auto s = slabs<2>(A, u);
  if (!s) return std::nullopt;
  const Vec2 n = s->axis == 0 ? Vec2{s->sign / r.w, 0} : Vec2{0, s->sign / r.h};
  return geo::Hit2{s->t, ray.at(s->t), unit_world_normal(f, n)};
}

}  // namespace ref

// ---- The benchmarks -----------------------------------------------------------------------

bool same_t(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

template <class Hit>
bool agree(const std::optional<Hit>& ours, const std::optional<Hit>& theirs) {
  if (ours.has_value() != theirs.has_value()) return false;
  return !ours || same_t(ours->t, theirs->t);
}

// One call per iteration, cycling through the batch; `hit` and `agree` as counters.
template <class Case, class F>
void run(benchmark::State& state, const std::vector<Case>& cases, F&& call) {
  std::size_t i = 0;
  for (auto _ : state) {
    auto result = call(cases[i]);
    benchmark::DoNotOptimize(result);
    i = (i + 1) & (kBatch - 1);
  }
}

template <class Case, class Hit>
void count(benchmark::State& state, const std::vector<Case>& cases, Hit&& hit) {
  double hits = 0;
  for (const auto& c : cases) hits += hit(c) ? 1 : 0;
  state.counters["hit"] = hits / kBatch;
}

template <class Case, class Ours, class Theirs>
void compare(benchmark::State& state, const std::vector<Case>& cases, Ours&& ours, Theirs&& theirs) {
  double agreeing = 0;
  for (const auto& c : cases) agreeing += agree(ours(c), theirs(c)) ? 1 : 0;
  state.counters["agree"] = agreeing / kBatch;
}

// Our results as optional hits, for the counters.
std::optional<geo::Hit2> ours_circle(const CircleCase& c) { return geo::intersect(c.ray, c.circle).hit; }
std::optional<geo::Hit2> ours_square(const geo::Ray2& r) { return geo::intersect_canonical_square(r).hit; }
std::optional<geo::Hit2> ours_ellipse(const EllipseCase& c) { return geo::intersect(c.ray, c.ellipse).hit; }
std::optional<geo::Hit2> ours_rectangle(const RectangleCase& c) { return geo::intersect(c.ray, c.rectangle).hit; }
std::optional<geo::Hit3> ours_sphere(const SphereCase& c) { return geo::intersect(c.ray, c.sphere).hit; }
std::optional<geo::Hit3> ours_cube(const geo::Ray3& r) { return geo::intersect_canonical_cube(r).hit; }

std::optional<geo::Hit2> ref_circle(const CircleCase& c) { return ref::ray_circle(c.ray, c.circle); }
std::optional<geo::Hit2> ref_square(const geo::Ray2& r) { return ref::ray_square(r); }
std::optional<geo::Hit2> lean_circle(const CircleCase& c) { return ref::ray_circle_course_lean(c.ray, c.circle); }
std::optional<geo::Hit2> lean_square(const geo::Ray2& r) { return ref::ray_square_course_lean(r); }
std::optional<geo::Hit2> ref_ellipse(const EllipseCase& c) { return ref::ray_ellipse(c.ray, c.ellipse); }
std::optional<geo::Hit2> ref_rectangle(const RectangleCase& c) { return ref::ray_rectangle(c.ray, c.rectangle); }
std::optional<geo::Hit3> ref_sphere(const SphereCase& c) { return ref::ray_sphere(c.ray, c.sphere); }
std::optional<geo::Hit3> ref_cube(const geo::Ray3& r) { return ref::ray_cube(r); }

void project_course(benchmark::State& state) {
  run(state, projections(), [](const ProjectionCase& c) { return geo::project(c.A, c.B, c.C); });
}
void project_plain(benchmark::State& state) {
  run(state, projections(), [](const ProjectionCase& c) { return ref::project(c.A, c.B, c.C); });
}

void segments_course(benchmark::State& state) {
  const auto& cases = segment_pairs();
  run(state, cases, [](const SegmentsCase& c) { return geo::intersect_segments(c.A, c.B, c.C, c.D); });
  count(state, cases, [](const SegmentsCase& c) { return geo::intersect_segments(c.A, c.B, c.C, c.D).intersects(); });
}
void segments_plain(benchmark::State& state) {
  const auto& cases = segment_pairs();
  run(state, cases, [](const SegmentsCase& c) { return ref::intersect_segments(c.A, c.B, c.C, c.D); });
  count(state, cases, [](const SegmentsCase& c) { return ref::intersect_segments(c.A, c.B, c.C, c.D).intersects; });
}

void ray_circle_course(benchmark::State& state) {
  run(state, circles(), [](const CircleCase& c) { return geo::intersect(c.ray, c.circle); });
  count(state, circles(), ours_circle);
}
void ray_circle_quadratic(benchmark::State& state) {
  run(state, circles(), ref_circle);
  count(state, circles(), ref_circle);
  compare(state, circles(), ours_circle, ref_circle);
}

void ray_circle_lean(benchmark::State& state) {
  run(state, circles(), lean_circle);
  count(state, circles(), lean_circle);
  compare(state, circles(), ours_circle, lean_circle);
}

void ray_square_course(benchmark::State& state) {
  run(state, square_rays(), [](const geo::Ray2& r) { return geo::intersect_canonical_square(r); });
  count(state, square_rays(), ours_square);
}
void ray_square_slab(benchmark::State& state) {
  run(state, square_rays(), ref_square);
  count(state, square_rays(), ref_square);
  compare(state, square_rays(), ours_square, ref_square);
}

void ray_square_lean(benchmark::State& state) {
  run(state, square_rays(), lean_square);
  count(state, square_rays(), lean_square);
  compare(state, square_rays(), ours_square, lean_square);
}

void ray_ellipse_course(benchmark::State& state) {
  run(state, ellipses(), [](const EllipseCase& c) { return geo::intersect(c.ray, c.ellipse); });
  count(state, ellipses(), ours_ellipse);
}
void ray_ellipse_quadratic(benchmark::State& state) {
  run(state, ellipses(), ref_ellipse);
  count(state, ellipses(), ref_ellipse);
  compare(state, ellipses(), ours_ellipse, ref_ellipse);
}

void ray_rectangle_course(benchmark::State& state) {
  run(state, rectangles(), [](const RectangleCase& c) { return geo::intersect(c.ray, c.rectangle); });
  count(state, rectangles(), ours_rectangle);
}
void ray_rectangle_slab(benchmark::State& state) {
  run(state, rectangles(), ref_rectangle);
  count(state, rectangles(), ref_rectangle);
  compare(state, rectangles(), ours_rectangle, ref_rectangle);
}

void ray_sphere_course(benchmark::State& state) {
  run(state, spheres(), [](const SphereCase& c) { return geo::intersect(c.ray, c.sphere); });
  count(state, spheres(), ours_sphere);
}
void ray_sphere_quadratic(benchmark::State& state) {
  run(state, spheres(), ref_sphere);
  count(state, spheres(), ref_sphere);
  compare(state, spheres(), ours_sphere, ref_sphere);
}

void ray_cube_course(benchmark::State& state) {
  run(state, cube_rays(), [](const geo::Ray3& r) { return geo::intersect_canonical_cube(r); });
  count(state, cube_rays(), ours_cube);
}
void ray_cube_slab(benchmark::State& state) {
  run(state, cube_rays(), ref_cube);
  count(state, cube_rays(), ref_cube);
  compare(state, cube_rays(), ours_cube, ref_cube);
}

// Ours first, its reference next (and the lean course method): the table reads in groups.
// The exact kernels of `epure solve` (issue 15), on the same batches.
void project_exact(benchmark::State& state) {
  run(state, projections(), [](const ProjectionCase& c) { return geo::project_exact(c.A, c.B, c.C); });
}
void segments_exact(benchmark::State& state) {
  run(state, segment_pairs(),
      [](const SegmentsCase& c) { return geo::intersect_segments_exact(c.A, c.B, c.C, c.D); });
}
void ray_circle_exact(benchmark::State& state) {
  run(state, circles(), [](const CircleCase& c) { return geo::intersect_exact(c.ray, c.circle); });
}
void ray_square_exact(benchmark::State& state) {
  run(state, square_rays(), [](const geo::Ray2& r) { return geo::intersect_canonical_square_exact(r); });
}
void ray_ellipse_exact(benchmark::State& state) {
  run(state, ellipses(), [](const EllipseCase& c) { return geo::intersect_exact(c.ray, c.ellipse); });
}
void ray_rectangle_exact(benchmark::State& state) {
  run(state, rectangles(), [](const RectangleCase& c) { return geo::intersect_exact(c.ray, c.rectangle); });
}
void ray_sphere_exact(benchmark::State& state) {
  run(state, spheres(), [](const SphereCase& c) { return geo::intersect_exact(c.ray, c.sphere); });
}
void ray_cube_exact(benchmark::State& state) {
  run(state, cube_rays(), [](const geo::Ray3& r) { return geo::intersect_canonical_cube_exact(r); });
}

BENCHMARK(project_course);
BENCHMARK(project_plain);
BENCHMARK(segments_course);
BENCHMARK(segments_plain);
BENCHMARK(ray_circle_course);
BENCHMARK(ray_circle_quadratic);
BENCHMARK(ray_circle_lean);
BENCHMARK(ray_square_course);
BENCHMARK(ray_square_slab);
BENCHMARK(ray_square_lean);
BENCHMARK(ray_ellipse_course);
BENCHMARK(ray_ellipse_quadratic);
BENCHMARK(ray_rectangle_course);
BENCHMARK(ray_rectangle_slab);
BENCHMARK(ray_sphere_course);
BENCHMARK(ray_sphere_quadratic);
BENCHMARK(ray_cube_course);
BENCHMARK(ray_cube_slab);
BENCHMARK(project_exact);
BENCHMARK(segments_exact);
BENCHMARK(ray_circle_exact);
BENCHMARK(ray_square_exact);
BENCHMARK(ray_ellipse_exact);
BENCHMARK(ray_rectangle_exact);
BENCHMARK(ray_sphere_exact);
BENCHMARK(ray_cube_exact);

}  // namespace

BENCHMARK_MAIN();
