#pragma once
// What ray_ellipse and ray_rectangle share, the course's open questions answered by
// transformations. The figure is a canonical one (the unit circle, the square [-1,1]²) placed by
// T = translate(C) ∘ rotate(θ) ∘ scale(sx, sy), with (sx, sy) the radii (a, b) or the half-sizes
// (w, h). The student carries the ray into the canonical frame with T⁻¹ (A_c = T⁻¹(A), u_c = T⁻¹
// applied to û as a vector, not renormalised, so t names the same point in both frames), solves
// the course's canonical problem there, and brings the hit back: I = A + t·û and the normal by
// the inverse transpose. Each kind file says what is canonical-specific; this file holds the
// drawing of the data, the exact forms of the frame change, the student's frame change (for the
// tolerances), the questions, the shared worked steps and the shared parts of the diagrams.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "exercises/kind_support.h"
#include "geometry/ray_transformed.h"

namespace epure::kinds::transformed {

enum class Shape { ellipse, rectangle };

struct Data {
  geo::Point2 A;
  geo::Vec2 u;
  geo::Point2 C;
  double sx = 1, sy = 1;  // radii (a, b) or half-sizes (w, h)
  double angle_deg = 0;   // counter-clockwise rotation of the sx-axis
};

// The solve input the data make (kind "ray_ellipse" with radii, "ray_rectangle" with half).
std::string instance_text(const Data& d, Shape shape);

// The core's answer, whichever the canonical figure: what the shared parts need.
struct Solved {
  geo::Transform2 to_world;
  geo::Ray2 canonical_ray;  // (A_c, u_c)
  bool inside = false;
  std::optional<geo::Hit2> hit;            // world frame
  std::optional<geo::Hit2> canonical_hit;  // canonical frame: I_c, N_c
};
template <class Result>
Solved solved_of(const Result& r) {
  return {r.to_world, r.canonical_ray, r.inside, r.hit, r.canonical.hit};
}
geo::Ray2 world_ray(const Data& d);  // (A, û): t is a length

// ---- constraints -------------------------------------------------------------------------------

// The constraints both kinds have, with their defaults.
std::map<std::string, double> common_constraints();

struct Limits {
  double margin;         // canonical clearance from the boundary: clear hit, clear miss, A clearly in or out
  double min_incidence;  // the ray meets the boundary at least this steeply (sine of the angle)
  double min_gap;        // world distance from A to I, so their labels stand apart
  double max_aspect;     // sx/sy or sy/sx at most
  double min_aspect;     // and at least: an ellipse that is not a circle
  double width, height;  // the drawing area [0, width] × [0, height]
  double max_canonical;  // |A_c| in the canonical frame at most, so the unit figure stays visible
  double max_tolerance;  // the largest derived tolerance of an answer: a well-conditioned instance
};
// The spec's values or the defaults; hard instances are allowed twice as close to the
// degenerate cases (margins halved), still safely away from them. `max_amplification` bounds
// how many rounding steps δ = ½·10^−decimals an answer may move when the student rounds as told:
// a figure where honest rounding moves t by a whole unit is ill-conditioned, not hard.
Limits limits(const ExerciseContext& ctx, const ExerciseKind& kind);

// Draws the data of one attempt per difficulty (easy: angle 0° or 90°, integer data, û rational;
// standard: integer data, angle a multiple of 30° or 45°; hard: one decimal, any whole-degree
// angle), with the figure and A inside the drawing area and the aspect ratio within limits.
// Empty when this attempt fails those checks; the branch is checked by the caller.
std::optional<Data> draw_data(Rng& rng, Difficulty level, Shape shape, bool inside, const Limits& lim);

// ---- exact forms -------------------------------------------------------------------------------

// An exact value, or none when the instance has no form we keep (an angle whose cosine is not a
// quadratic surd, two different radicands, a nested root, 64-bit overflow): the key then gives
// the decimal value alone. Operations on a missing value give a missing value.
class Ex {
 public:
  Ex() = default;
  Ex(exact::Surd s) : v_(s) {}
  Ex(exact::Rational r) : v_(exact::Surd(r)) {}
  static Ex integer(std::int64_t n) { return Ex(exact::Rational(n)); }
  static Ex datum(double x);  // the rational a datum denotes (rational_of)

  bool has_value() const { return v_.has_value(); }
  const std::optional<exact::Surd>& get() const { return v_; }
  bool is_rational() const { return v_ && v_->is_rational(); }

  friend Ex operator+(const Ex& x, const Ex& y);
  friend Ex operator-(const Ex& x, const Ex& y);
  friend Ex operator*(const Ex& x, const Ex& y);
  friend Ex operator/(const Ex& x, const Ex& y);
  friend Ex operator-(const Ex& x);
  // √x when x is rational (a square root of a surd is not kept).
  friend Ex sqrt(const Ex& x);

 private:
  std::optional<exact::Surd> v_;
};

struct ExVec {
  Ex x, y;
};
Ex dot(const ExVec& p, const ExVec& q);

// cos θ and sin θ for θ a whole multiple of 30° or 45°; missing otherwise.
ExVec exact_cos_sin(double degrees);

// The frame change, exactly: û, cos θ and sin θ, A − C and its rotation by −θ, A_c, û rotated
// by −θ and u_c.
struct ExactFrame {
  Ex norm_u;
  ExVec u_hat, cos_sin, CA, CA_rotated, Ac, u_rotated, uc;
};
ExactFrame exact_frame(const Data& d);

// Back to the world: I = A + t·û, n = rotate(θ)·scale(1/sx, 1/sy)·N_c, N = n/‖n‖.
struct ExactWorld {
  Ex t;
  ExVec Nc, I, n, N;
};
ExactWorld exact_world(const Data& d, const ExactFrame& f, const Ex& t, const ExVec& Nc);

// A sheet is only issued when the exact value and the core's double agree (within 1e-9
// relative): else std::logic_error, a generator bug caught by the tests.
void cross_check(const Ex& e, double core, const char* what);
void cross_check(const ExVec& e, geo::Vec2 core, const char* what);

// Whether every derived tolerance is within the limit.
bool well_conditioned(const std::vector<double>& tolerances, const Limits& lim);

// ---- the student's method (tolerances) ---------------------------------------------------------

// A student rounds a value only when it has more decimals than asked: the nudge applies to
// intermediate k only then (an exact 0.6 stays 0.6).
class Rounding {
 public:
  Rounding(const Nudge& nudge, int decimals);
  double operator()(int k, double value) const;

 private:
  const Nudge& nudge_;
  double scale_;  // 10^decimals
};

// The frame change by hand, rounded where the student rounds: û (intermediates 0, 1), cos θ and
// sin θ (2, 3), A_c (4, 5), u_c (6, 7). The canonical part goes on from index kFrameSteps.
struct StudentFrame {
  geo::Vec2 u_hat;
  double cos, sin;
  geo::Point2 Ac;
  geo::Vec2 uc;
};
inline constexpr int kFrameSteps = 8;
StudentFrame student_frame(const Data& d, const Rounding& r);
// I = A + t·û and N = normalise(rotate(θ)·scale(1/sx, 1/sy)·N_c), with the student's rounded
// û, cos θ, sin θ: {I.x, I.y, N.x, N.y}.
std::vector<double> student_world(const Data& d, const StudentFrame& f, double t, geo::Vec2 Nc);

// ---- questions ---------------------------------------------------------------------------------

// The fields both kinds ask, in order; t, I, N only with a hit.
std::vector<std::string> fields();
// Asks A_c, u_c, inside, hit (and t, I, N with a hit). `tol` holds the derived tolerances in the
// student method's output order: Ac.x, Ac.y, uc.x, uc.y (, t, I.x, I.y, N.x, N.y).
void ask(Questions& q, const Solved& s, const std::vector<double>& tol, const ExactFrame& f,
         const ExactWorld& w);

// ---- texts -------------------------------------------------------------------------------------

// The statement's data, named as the kind's templates name them (${a}, ${b} or ${w}, ${h}).
TextVars data_vars(const ExerciseContext& ctx, const Data& d, Shape shape);
// "T^{-1} = scale(1/2, 1/3) ∘ rotate(−30°) ∘ translate((−4, −5))", from the kind's `link`.
std::string link_text(const ExerciseContext& ctx, const Data& d, Shape shape);
// A worked step's paragraph: the kind's template `step.<name>`.
void step(render::Section& s, const ExerciseContext& ctx, std::string_view name, const TextVars& vars = {});
// The frame change: T⁻¹, û, cos θ and sin θ, A_c, u_c.
void frame_steps(render::Section& s, const ExerciseContext& ctx, const Data& d, Shape shape,
                 const Solved& solved, const ExactFrame& f);
// Back to the world: I, then the normal by the inverse transpose.
void world_steps(render::Section& s, const ExerciseContext& ctx, const Data& d, Shape shape,
                 const Solved& solved, const ExactWorld& w);

// ---- diagrams ----------------------------------------------------------------------------------

// The world frame on a grid: the figure, C, its two semi-axes labelled, A, the ray and û.
render::Panel world_panel(const Data& d, Shape shape, const Solved& s);
// The hit in the world frame: I and the normal N.
void add_world_hit(render::Panel& panel, const geo::Hit2& hit);
// The canonical frame's view and grid around the unit figure, A_c and the hit.
render::Panel canonical_panel(const Solved& s);
// The canonical ray: A_c, the ray along u_c, the arrow u_c.
void add_canonical_ray(render::Panel& panel, const Solved& s);
// I_c and N_c.
void add_canonical_hit(render::Panel& panel, const geo::Hit2& hit);

// The question's scene (the world frame with the data) and the key's (world and canonical frames
// side by side, T⁻¹ between them).
render::Scene question_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s);
render::Scene key_scene(const ExerciseContext& ctx, const Data& d, Shape shape, const Solved& s,
                        render::Panel canonical);

// ---- for the tests -------------------------------------------------------------------------------

// Each kind's hand method with nothing rounded, in the order the tolerances use: {Ac.x, Ac.y,
// uc.x, uc.y} and with a hit {t, I.x, I.y, N.x, N.y}. It must agree with the core.
std::vector<double> ellipse_student_answers(const Data& d);
std::vector<double> rectangle_student_answers(const Data& d);

}  // namespace epure::kinds::transformed
