#pragma once
// Exercise 3 of the course: ray/circle by projection and Pythagoras, and its 3D twin ray/sphere
// (in ray_3d.h). P, the projection of C on the ray's line, is the middle of the chord [IJ]; the
// triangles CPI and CPJ are right-angled at P, so PI² = r² − CP² (Pythagoras).
//
// The early rejections come in the course's order: a ray from outside that points away from the
// centre (t_proj < 0) is `behind`; then one whose line passes farther than r from C is a `miss`.
// The square root is taken only for a hit. Unlike the course's code, a ray that starts inside
// the circle hits it on its way out. A ray starting on the circle is outside: heading in, it
// hits at t = 0; heading out, it is behind. A tangent line counts as a hit (d² = r²), and so does
// a line within the data's rounding of tangency, with PI = 0.
#include <optional>

#include "geometry/decimal.h"
#include "geometry/ray.h"

namespace epure::geo {

enum class NoHit { behind, miss };
const char* to_string(NoHit reason);

struct Circle {
  Point2 C;
  double r;
};

struct RayCircle {
  Vec2 AC;
  double t_proj;  // parameter of P on the ray: u·AC / u·u (= û·AC for a unit direction)
  Point2 P;       // the projection of C on the ray's line
  double d2;      // CP², the squared distance from C to the line
  bool inside;    // A strictly inside the circle
  // Exactly one of these is present.
  std::optional<Hit2> hit;
  std::optional<NoHit> reason;
  // PI = √(r² − d²), the third side of the Pythagoras triangle, in units of length: with a hit.
  std::optional<double> half_chord;
};

// Throws DegenerateFigure("r") unless r > 0 and ("u") for a zero direction.
RayCircle intersect(const Ray2& ray, const Circle& circle);

// The course's canonical circle: centre O, radius 1.
RayCircle intersect_canonical_circle(const Ray2& ray);

// The same with every decision exact for the given doubles (`epure solve`, README): inside is
// ‖AC‖² < r², behind u·AC < 0 from outside or on the circle, miss ‖u‖²r² < ‖u ∧ AC‖², tangent
// when equal (PI = 0). No window: a line 1e-15 from tangency gets its true half chord, r² − d²
// computed without cancellation. At t = 0, I = A and N = (A − C)/r from the exact A − C.
// `intersect` reads the data as a worksheet's decimals (within rounding of tangency is tangent).
RayCircle intersect_exact(const Ray2& ray, const Circle& circle);
RayCircle intersect_canonical_circle_exact(const Ray2& ray);
// The same for the numbers as written (decimal.h): A, u, C, r (README, one meaning for a number).
RayCircle intersect_exact(const DPoint2& A, const DPoint2& u, const DPoint2& C, const Decimal& r);

// The values `epure solve` prints that its kernels can leave beyond 4 ulps: t_proj·‖u‖ and, with
// a hit, t·‖u‖, I and N, `length` being ‖u‖ as the caller rounds it and res either kernel's
// result for this ray and circle. Each is res's own (res.t_proj·length, hit->t·length, hit->I,
// hit->N) wherever it is within 4 ulps of max(S, |·|) (S the largest of |A|, |C| and r; N·r as
// a length), otherwise the accurate value, rounded (ray_ball.h). The decisions are res's.
template <class V, class P>
struct PrintedValues {
  double t_proj;
  double t;  // 0 without a hit
  P I;       // with a hit
  V N;       // with a hit
};
PrintedValues<Vec2, Point2> printed_values(const Ray2& ray, const Circle& circle, const RayCircle& res,
                                           double length);
PrintedValues<Vec2, Point2> printed_values(const DPoint2& A, const DPoint2& u, const DPoint2& C, const Decimal& r,
                                           const RayCircle& res, double length);

}  // namespace epure::geo
