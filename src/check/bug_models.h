#pragma once
// The classic bugs, as code: each function's method written the way the course writes it (in
// doubles, with its helpers' formulas), with switches that put in one of the bugs students
// make, the course's own snippets first among them:
//
//   square_parenthesis   MAX(fabs(J->x),fabs(J->y)>1.): the test of the hit point almost always
//                        true, so the ray almost never meets the square (the course's snippet)
//   side_rounding        MAX(fabs(J->x),fabs(J->y)) > 1.: the hit point's own side coordinate,
//                        which rounding puts just past 1 half of the time, tested with the other
//   t_le_zero            t <= 0 where the contract says t < 0 (a ray starting on the figure,
//                        into it or along its tangent, meets it at t = 0); for the square, the
//                        open half-plane x_A > 1; for segments, ends excluded (<= 0, >= 1)
//   inside_as_miss       an origin inside handled as one outside: a miss, or the hit behind A
//                        (the course's snippets)
//   far_point            J = A + (t + √(r² − d²))·u, the far intersection, instead of I
//   direction_not_unit   a formula for a unit u used with a direction that is not (t = AB·AC
//                        without the division; the canonical circle's method on the carried,
//                        unnormalised direction)
//   normal_not_unit      N = J − C without the division by its length
//   normal_inward        N pointing into the figure
//   normal_not_inverse_transpose   the ellipse's normal carried back like a vector (M·n) rather
//                        than by the inverse transpose (M⁻ᵀ·n)
//   params_swapped       the segments' parameters exchanged: I = A + t_cd·AB, or C + t_ab·CD
//   exact_zero_test      if (v == 0.) where G2Xiszero(v) is needed: collinear segments given as
//                        decimals then "intersect" at a point made of rounding noise
//
// The classifier (classify.h) runs a model with a bug switched on over the same cases and names
// the bug when its answers are the student's.
#include <cstdint>
#include <span>
#include <string_view>

#include "check/functions.h"

namespace epure::check {

enum class Bug : std::uint8_t {
  square_parenthesis,
  side_rounding,
  t_le_zero,
  inside_as_miss,
  far_point,
  direction_not_unit,
  normal_not_unit,
  normal_inward,
  normal_not_inverse_transpose,
  params_swapped,
  params_swapped_cd,  // the same bug (its code is params_swapped), the other way round
  exact_zero_test,
};
inline constexpr int kBugCount = 12;
using Bugs = std::uint32_t;  // a set: bit i is Bug i
constexpr Bugs bit(Bug b) { return Bugs{1} << static_cast<int>(b); }

// The code report.json gives ("params_swapped" for both of its variants).
std::string_view bug_code(Bug b);
// The bugs a function can show.
std::span<const Bug> bugs_of(Fn fn);

// The method, with `bugs` switched on (0: the method right, as the mended course writes it).
Outcome model(const Case& c, Bugs bugs);

}  // namespace epure::check
