#pragma once
// A turned ellipse or rectangle decided on the decimals written (README, "What a number
// means"). The figure's kernels (ray_transformed.h) carry the ray into the canonical frame in
// doubles; here the decisions that carrying rounds are taken again, exactly, wherever they can be:
//
// - an angle that is a whole multiple of 90°, 45° or 30° as written (0, 90, -90, 450.0, 135, -60:
//   the decimal, not its double) has cos and sin in {0, ±1, ±½, ±½√2, ±½√3}: a quarter turn is a
//   permutation with signs, the others exact numbers p + q√2 or p + q√3 (quadratic.h), so every
//   decision is the sign of a polynomial of the decimals in that field (the sizes multiplied
//   out: inside the ellipse is b²x'² + a²y'² < a²b², x' and y' the turned A − C);
// - an ellipse whose radii are the same decimal is a circle, whatever its angle: its decisions
//   are ray_circle's on the decimals.
//
// Each polynomial is first bounded in floating point with its error (midpoint and radius); only
// where that cannot tell a sign is it evaluated exactly on the decimals (decimal.h). When the
// exact decisions are those of the kernels' doubles, the kernels' result is kept; otherwise the
// hit is rebuilt from the exact decisions. Either way its t, I and N are then checked against
// their values from the decimals in double-double (cos θ and sin θ to about 2^-100): kept, to
// the bit, within 3.25 ulps of their bound of those, else those (within 4 ulps of the exact
// figure's at any angle, near tangency too, where the carried ray's rounding is magnified).
//
// At any other angle with unequal sizes the same polynomials are filtered with cos θ and sin θ
// enclosed within a proven bound (cos_sin_degrees' rounding, and the angle's own when its
// decimal is not a double): a sign the filter is certain of is the exact one; a line it cannot
// tell (within about 1e-15 of the line's largest number from a boundary) is refused with a
// DegenerateFigure naming the angle, never answered on the carried ray.
#include <optional>

#include "geometry/decimal.h"
#include "geometry/ray_transformed.h"

namespace epure::geo {

// A turned figure's numbers as written: the ray (A, u), the centre, the sizes (radii or
// half-sizes) along the figure's own axes, the angle in degrees.
struct WrittenTurned {
  DPoint2 A, u, C;
  Decimal sx, sy;
  Decimal angle_deg;
};

// The angle as a whole number of quarter turns, 0 to 3, when it is one as written; none
// otherwise (and for a multiple of 90 beyond 2^53 degrees, which no double angle reaches).
std::optional<int> quarter_turns(const Decimal& angle_deg);

// The ray and the figure, decided on the decimals where the cases above allow. `ray` is the
// kernels' ray (the doubles of A, and u rescaled by a power of two), `direction` the same
// direction as decimals (solve::raw_direction): t is in its units.
RayEllipse intersect_written(const WrittenTurned& w, const DPoint2& direction, const Ray2& ray,
                             const Ellipse& ellipse);
RayRectangle intersect_written(const WrittenTurned& w, const DPoint2& direction, const Ray2& ray,
                               const Rectangle& rectangle);

}  // namespace epure::geo
