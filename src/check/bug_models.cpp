#include "check/bug_models.h"

#include <array>
#include <cmath>
#include <limits>

namespace epure::check {

namespace {

// Plain doubles, the course's helpers' formulas (templates/check/starter/*/g2x.h): what a
// student's C computes, operation for operation.
struct V2 {
  double x, y;
};
V2 sub(V2 b, V2 a) { return {b.x - a.x, b.y - a.y}; }
V2 add(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V2 mul(double k, V2 a) { return {k * a.x, k * a.y}; }
double dot(V2 u, V2 v) { return u.x * v.x + u.y * v.y; }
double cross(V2 u, V2 v) { return u.x * v.y - u.y * v.x; }
V2 normalized(V2 v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y);
  return n > 0 ? V2{v.x / n, v.y / n} : v;
}

struct V3 {
  double x, y, z;
};
V3 sub(V3 b, V3 a) { return {b.x - a.x, b.y - a.y, b.z - a.z}; }
V3 add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 mul(double k, V3 a) { return {k * a.x, k * a.y, k * a.z}; }
double dot(V3 u, V3 v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
V3 cross(V3 u, V3 v) { return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x}; }
V3 normalized(V3 v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return n > 0 ? V3{v.x / n, v.y / n, v.z / n} : v;
}

double coord(V2 v, int k) { return k == 0 ? v.x : v.y; }
double coord(V3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }
template <class V>
V basis(int k, double s) {
  V v{};
  if constexpr (sizeof(V) == sizeof(V2)) {
    (k == 0 ? v.x : v.y) = s;
  } else {
    (k == 0 ? v.x : k == 1 ? v.y : v.z) = s;
  }
  return v;
}

bool on(Bugs bugs, Bug b) { return (bugs & bit(b)) != 0; }

Outcome none() { return Outcome{}; }

Outcome point(V2 J, V2 N) { return Outcome{true, {J.x, J.y, N.x, N.y, 0, 0}}; }
Outcome point(V3 J, V3 N) { return Outcome{true, {J.x, J.y, J.z, N.x, N.y, N.z}}; }

// ---- ball: circle and sphere, as the course's rayon_inter_cercle (mended: an origin inside
// leaves through the far point) ----------------------------------------------------------------
template <class V>
double squared_distance(V u, V AC) {
  if constexpr (sizeof(V) == sizeof(V2)) {
    const double d = cross(u, AC);
    return d * d;
  } else {
    const V3 w = cross(u, AC);
    return dot(w, w);
  }
}

// The parameter of the point met along u (unit), or nothing.
template <class V>
std::optional<double> ball_t(V A, V u, V C, double r, Bugs bugs) {
  const V AC = sub(C, A);
  const double t = dot(u, AC);
  const bool inside = !on(bugs, Bug::inside_as_miss) && dot(AC, AC) < r * r;
  const bool away = on(bugs, Bug::t_le_zero) ? t <= 0. : t < 0.;
  if (!inside && away) return std::nullopt;
  const double d2 = squared_distance(u, AC);
  if (d2 > r * r) return std::nullopt;
  const double h = std::sqrt(r * r - d2);
  return inside || on(bugs, Bug::far_point) ? t + h : t - h;
}

template <class V>
Outcome ball(V A, V u, V C, double r, Bugs bugs) {
  const auto t = ball_t(A, u, C, r, bugs);
  if (!t) return none();
  const V J = add(A, mul(*t, u));
  V N = sub(J, C);
  if (!on(bugs, Bug::normal_not_unit)) N = normalized(N);
  if (on(bugs, Bug::normal_inward)) N = mul(-1, N);
  return point(J, N);
}

// ---- box: square and cube, as the course's rayon_inter_carre_canonique (mended: the bounds'
// parenthesis, the side's own coordinate left out of the test, candidates on closed half-planes,
// an origin inside) --------------------------------------------------------------------------
template <class V, int Dim>
bool off_side(V J, int axis, Bugs bugs) {
  if (on(bugs, Bug::square_parenthesis)) {
    // MAX(fabs(J->x), fabs(J->y) > 1.) as C reads it: nonzero unless J->x is 0 and |J->y| <= 1
    double first = std::abs(coord(J, 0));
    for (int k = 1; k + 1 < Dim; ++k) first = std::max(first, std::abs(coord(J, k)));
    const double last = std::abs(coord(J, Dim - 1)) > 1. ? 1. : 0.;
    return (first < last ? last : first) != 0;
  }
  double m = 0;
  for (int k = 0; k < Dim; ++k)
    if (k != axis || on(bugs, Bug::side_rounding)) m = std::max(m, std::abs(coord(J, k)));
  return m > 1.;
}

template <class V, int Dim>
Outcome box(V A, V u, Bugs bugs) {
  bool any = false;
  std::array<bool, 2 * Dim> candidate{};
  for (int k = 0; k < Dim; ++k)
    for (int s = 0; s < 2; ++s) {
      const double a = coord(A, k) * (s == 0 ? 1 : -1);
      candidate[static_cast<std::size_t>(2 * k + s)] = on(bugs, Bug::t_le_zero) ? a > 1. : a >= 1.;
      any = any || candidate[static_cast<std::size_t>(2 * k + s)];
    }
  // the side the ray leaves through (the far point from outside, the answer from inside)
  auto exit = [&]() -> Outcome {
    double best = std::numeric_limits<double>::infinity();
    int face = -1;
    for (int f = 0; f < 2 * Dim; ++f) {
      const V n = basis<V>(f / 2, f % 2 == 0 ? 1. : -1.);
      const double ps2 = dot(u, n);
      if (ps2 <= 0.) continue;
      const double t = (1. - dot(A, n)) / ps2;
      if (t < best) best = t, face = f;
    }
    if (face < 0) return none();
    V N = basis<V>(face / 2, face % 2 == 0 ? 1. : -1.);
    if (on(bugs, Bug::normal_inward)) N = mul(-1, N);
    return point(add(A, mul(best, u)), N);
  };
  if (!any) {
    if (on(bugs, Bug::inside_as_miss)) return none();
    return exit();
  }
  for (int f = 0; f < 2 * Dim; ++f) {
    if (!candidate[static_cast<std::size_t>(f)]) continue;
    const V n = basis<V>(f / 2, f % 2 == 0 ? 1. : -1.);
    const double ps1 = dot(sub(n, A), n);
    if (ps1 > 0.) continue;
    const double ps2 = dot(u, n);
    if (ps2 >= 0.) continue;
    const double t = ps1 / ps2;
    const V J = add(A, mul(t, u));
    if (off_side<V, Dim>(J, f / 2, bugs)) continue;
    if (on(bugs, Bug::far_point)) return exit();
    return point(J, on(bugs, Bug::normal_inward) ? mul(-1, n) : n);
  }
  return none();
}

// ---- the open questions: the canonical figure in its own frame ------------------------------
struct Frame {
  V2 C;
  double s1, s2, co, si;
  V2 point_in(V2 A) const {  // world -> canonical, as a point
    const V2 d = sub(A, C);
    return {(co * d.x + si * d.y) / s1, (-si * d.x + co * d.y) / s2};
  }
  V2 vector_in(V2 u) const { return {(co * u.x + si * u.y) / s1, (-si * u.x + co * u.y) / s2}; }
  V2 point_out(V2 P) const {  // canonical -> world
    const double x = s1 * P.x, y = s2 * P.y;
    return {C.x + co * x - si * y, C.y + si * x + co * y};
  }
  V2 rotate(V2 v) const { return {co * v.x - si * v.y, si * v.x + co * v.y}; }
};

Frame frame_of(const Inputs& in) {
  const double a = in[8] * 3.14159265358979323846 / 180;
  return {{in[4], in[5]}, in[6], in[7], std::cos(a), std::sin(a)};
}

Outcome ellipse(const Inputs& in, Bugs bugs) {
  const Frame f = frame_of(in);
  const V2 A = f.point_in({in[0], in[1]});
  V2 u = f.vector_in({in[2], in[3]});
  double length = 1;
  if (!on(bugs, Bug::direction_not_unit)) {
    length = std::sqrt(dot(u, u));
    u = mul(1 / length, u);
  }
  const auto t = ball_t(A, u, V2{0, 0}, 1., bugs);
  if (!t) return none();
  const V2 Jc = add(A, mul(*t, u));
  // the normal: (M⁻¹)ᵀ·Jc = R·(x/a, y/b); carried as a vector, M·Jc = R·(a·x, b·y)
  V2 N = on(bugs, Bug::normal_not_inverse_transpose) ? f.rotate({f.s1 * Jc.x, f.s2 * Jc.y})
                                                     : f.rotate({Jc.x / f.s1, Jc.y / f.s2});
  if (!on(bugs, Bug::normal_not_unit)) N = normalized(N);
  if (on(bugs, Bug::normal_inward)) N = mul(-1, N);
  return point(f.point_out(Jc), N);
}

Outcome rectangle(const Inputs& in, Bugs bugs) {
  const Frame f = frame_of(in);
  const Outcome c = box<V2, 2>(f.point_in({in[0], in[1]}), f.vector_in({in[2], in[3]}), bugs);
  if (!c.hit) return c;
  const V2 J = f.point_out({c.out[0], c.out[1]});
  const V2 N = f.rotate({c.out[2], c.out[3]});  // a side's normal: (M⁻¹)ᵀ·n, normalised, is R·n
  return point(J, N);
}

}  // namespace

std::string_view bug_code(Bug b) {
  switch (b) {
    case Bug::square_parenthesis: return "square_parenthesis";
    case Bug::side_rounding: return "side_rounding";
    case Bug::t_le_zero: return "t_le_zero";
    case Bug::inside_as_miss: return "inside_as_miss";
    case Bug::far_point: return "far_point";
    case Bug::direction_not_unit: return "direction_not_unit";
    case Bug::normal_not_unit: return "normal_not_unit";
    case Bug::normal_inward: return "normal_inward";
    case Bug::normal_not_inverse_transpose: return "normal_not_inverse_transpose";
    case Bug::params_swapped:
    case Bug::params_swapped_cd: return "params_swapped";
    case Bug::exact_zero_test: return "exact_zero_test";
  }
  return "?";
}

std::span<const Bug> bugs_of(Fn fn) {
  using B = Bug;
  static constexpr std::array<B, 1> projection{B::direction_not_unit};
  static constexpr std::array<B, 4> segments{B::exact_zero_test, B::params_swapped, B::params_swapped_cd, B::t_le_zero};
  static constexpr std::array<B, 5> ball{B::inside_as_miss, B::t_le_zero, B::far_point, B::normal_not_unit,
                                         B::normal_inward};
  static constexpr std::array<B, 4> canonical{B::inside_as_miss, B::t_le_zero, B::far_point, B::normal_inward};
  static constexpr std::array<B, 6> box{B::square_parenthesis, B::side_rounding, B::inside_as_miss,
                                        B::t_le_zero,          B::far_point,     B::normal_inward};
  static constexpr std::array<B, 7> ellipse{B::direction_not_unit, B::inside_as_miss, B::t_le_zero,
                                            B::far_point,          B::normal_not_unit, B::normal_inward,
                                            B::normal_not_inverse_transpose};
  switch (fn) {
    case Fn::projection: return projection;
    case Fn::segments: return segments;
    case Fn::circle:
    case Fn::sphere: return ball;
    case Fn::circle_canonical: return canonical;
    case Fn::square_canonical:
    case Fn::rectangle:
    case Fn::cube_canonical: return box;
    case Fn::ellipse: return ellipse;
  }
  return {};
}

Outcome model(const Case& c, Bugs bugs) {
  const Inputs& in = c.in;
  switch (c.fn) {
    case Fn::projection: {
      const V2 A{in[0], in[1]}, B{in[2], in[3]}, C{in[4], in[5]};
      const V2 AB = sub(B, A), AC = sub(C, A);
      const double t = on(bugs, Bug::direction_not_unit) ? dot(AB, AC) : dot(AB, AC) / dot(AB, AB);
      return point(add(A, mul(t, AB)), V2{0, 0});
    }
    case Fn::segments: {
      const V2 A{in[0], in[1]}, B{in[2], in[3]}, C{in[4], in[5]}, D{in[6], in[7]};
      const V2 AB = sub(B, A), CD = sub(D, C);
      const double v = cross(AB, CD);
      if (on(bugs, Bug::exact_zero_test) ? v == 0. : (v < 1e-10 && v > -1e-10)) return none();  // G2Xiszero
      const V2 AC = sub(C, A);
      const double t1 = cross(AC, CD) / v, t2 = cross(AC, AB) / v;
      const bool strict = on(bugs, Bug::t_le_zero);
      auto outside = [strict](double t) { return strict ? t <= 0. || t >= 1. : t < 0. || t > 1.; };
      if (outside(t1) || outside(t2)) return none();
      if (on(bugs, Bug::params_swapped)) return point(add(A, mul(t2, AB)), V2{0, 0});
      if (on(bugs, Bug::params_swapped_cd)) return point(add(C, mul(t1, CD)), V2{0, 0});
      return point(add(A, mul(t1, AB)), V2{0, 0});
    }
    case Fn::circle: return ball(V2{in[0], in[1]}, V2{in[2], in[3]}, V2{in[4], in[5]}, in[6], bugs);
    case Fn::circle_canonical: return ball(V2{in[0], in[1]}, V2{in[2], in[3]}, V2{0, 0}, 1., bugs);
    case Fn::square_canonical: return box<V2, 2>(V2{in[0], in[1]}, V2{in[2], in[3]}, bugs);
    case Fn::ellipse: return ellipse(in, bugs);
    case Fn::rectangle: return rectangle(in, bugs);
    case Fn::sphere: return ball(V3{in[0], in[1], in[2]}, V3{in[3], in[4], in[5]}, V3{in[6], in[7], in[8]}, in[9], bugs);
    case Fn::cube_canonical: return box<V3, 3>(V3{in[0], in[1], in[2]}, V3{in[3], in[4], in[5]}, bugs);
  }
  return none();
}

}  // namespace epure::check
