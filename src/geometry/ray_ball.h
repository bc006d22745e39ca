#pragma once
// The course's ray/circle method written once for the circle (2D) and the sphere (3D): both are
// "points at distance r from C". Internal to ray_circle.cpp and ray_3d.cpp.
#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/decimal_vec.h"
#include "geometry/degenerate.h"
#include "geometry/exact_vec.h"
#include "geometry/exponent.h"
#include "geometry/predicates.h"
#include "geometry/tolerance.h"
#include "geometry/vec.h"

namespace epure::geo::detail {

inline double max_abs(Vec2 v) { return std::max(std::abs(v.x), std::abs(v.y)); }
inline double max_abs(Vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }
inline double max_abs(Point2 p) { return max_abs(to_vec(p)); }
inline double max_abs(Point3 p) { return max_abs(to_vec(p)); }

// ‖v‖² − r², rounded about once: the sign and digits of "how far outside" when A is near the
// circle, where ‖AC‖ − r would be made of rounding.
inline double excess_of_square(const ExactVec2& v, double r) {
  exact::CompensatedSum s;
  s.add_product(v.hi.x, v.hi.x).add_product(v.hi.y, v.hi.y).add_product(-r, r);
  s.add(2 * (v.hi.x * v.lo.x + v.hi.y * v.lo.y) + (v.lo.x * v.lo.x + v.lo.y * v.lo.y));
  return s.value();
}
inline double excess_of_square(const ExactVec3& v, double r) {
  exact::CompensatedSum s;
  s.add_product(v.hi.x, v.hi.x).add_product(v.hi.y, v.hi.y).add_product(v.hi.z, v.hi.z);
  s.add_product(-r, r);
  s.add(2 * (v.hi.x * v.lo.x + v.hi.y * v.lo.y + v.hi.z * v.lo.z) +
        (v.lo.x * v.lo.x + v.lo.y * v.lo.y + v.lo.z * v.lo.z));
  return s.value();
}

// The part w of AC perpendicular to the ray's line (AC = t_proj·u + w) and its length d = CP,
// both from the cross product u ∧ AC of the exact AC: no cancellation, so d keeps its digits
// when the ray is nearly tangent and w when A is far from the figure.
struct Offset2 {
  Vec2 w;
  double d;
};
inline Offset2 offset_from_line(Vec2 u, double length_u, const ExactVec2& AC) {
  const double s = cross(as_exact(u), AC) / length_u;  // AC = t_proj·u + s·perp(û)
  return {s * perp(u / length_u), std::abs(s)};
}
struct Offset3 {
  Vec3 w;
  double d;
};
inline Offset3 offset_from_line(Vec3 u, double length_u, const ExactVec3& AC) {
  const Vec3 n = cross(as_exact(u), AC);  // ‖n‖ = ‖u‖·d
  // u × (AC × u) = ‖u‖²·AC − (u·AC)·u = ‖u‖²·w, and AC × u = −n
  return {cross(n, u) / (length_u * length_u), plain_norm(n) / length_u};
}

template <class Result, class Hit, class Ray, class Point>
Result intersect_ball(const Ray& ray, Point C, double r) {
  if (!(r > 0) || !std::isfinite(r)) throw DegenerateFigure("r", "must be > 0");
  const double largest_u = max_abs(ray.direction);
  if (!(largest_u > 0)) throw DegenerateFigure("u", "zero direction");
  if (!std::isfinite(largest_u)) throw DegenerateFigure("u", "not a finite direction");
  const Point A = ray.origin;

  Result res{};
  res.AC = C - A;

  // The figure (A, C, r) brought near unit size by 2^-e and the direction by 2^-f: exact, and
  // every t below is in units of the scaled direction, t_world = t·2^(e−f).
  const int e = binary_exponent(std::max({max_abs(A), max_abs(C), r}));
  const int f = binary_exponent(largest_u);
  const auto u = times_pow2(ray.direction, -f);
  const double rs = times_pow2(r, -e);
  const auto AC = exact_difference(times_pow2(C, -e), times_pow2(A, -e));
  const double length_u = plain_norm(u);
  const double uu = length_u * length_u;
  auto to_world_t = [&](double t) { return times_pow2(t, e - f); };

  const double ac = plain_norm(AC.hi);
  // P = A + t_proj·u with (AC − t_proj·u)·u = 0
  const double t_proj = dot(as_exact(u), AC) / uu;
  res.t_proj = to_world_t(t_proj);
  res.P = A + res.t_proj * ray.direction;
  const auto offset = offset_from_line(u, length_u, AC);
  const double d = offset.d;
  res.d2 = times_pow2(d * d, 2 * e);

  // AC and d are exact to a few ε of ‖AC‖: compare lengths with r within that.
  const Near near{kRoundoff * std::max(rs, ac)};
  res.inside = near.below(ac, rs);
  const bool on_circle = near.on(ac, rs);
  // behind: outside and pointing away from C (the course's first test, t_proj < 0). A t_proj
  // within rounding of 0 is a ray perpendicular to AC: not behind (then a miss, or a tangent hit
  // at t = 0 from the circle itself).
  if (!res.inside && Near{kRoundoff * ac / length_u}.below(t_proj, 0.0)) {
    res.reason = NoHit::behind;
    return res;
  }
  // miss: the line passes farther than r from C (d² > r²)
  if (near.above(d, rs)) {
    res.reason = NoHit::miss;
    return res;
  }
  // Pythagoras in CPI: PI² = r² − d², factored to keep its digits near tangency. A line within
  // rounding of tangency is tangent (PI = 0): the root of a rounding error is a far larger
  // error (an exact tangent whose u was rounded to unit length would get PI ≈ 1e-7·r).
  const double h = near.on(d, rs) ? 0.0 : std::sqrt((rs - d) * (rs + d));
  res.half_chord = times_pow2(h, e);
  const double h_param = h / length_u;
  // The roots t_proj ∓ h have the product c = (‖AC‖² − r²) / u·u. Each root is taken in the
  // form that does not cancel (the smaller one as c over the larger, when both are positive).
  const double c = on_circle ? 0.0 : excess_of_square(AC, rs) / uu;
  double t;
  double along;  // (t − t_proj)·‖u‖: −h at the entry, +h at the exit
  if (res.inside) {
    t = t_proj >= 0 ? t_proj + h_param : c / (t_proj - h_param);
    along = h;
  } else {
    const double sum = t_proj + h_param;
    t = sum > 0 ? std::max(0.0, c / sum) : 0.0;
    along = -h;
  }
  // I − C = (t − t_proj)·u − w, of length r: no cancellation, whatever the size of AC.
  const auto radial = (along / length_u) * u - offset.w;
  const double radial_length = plain_norm(radial);
  Hit hit{};
  hit.t = to_world_t(t);
  // I is A itself at t = 0; otherwise A + t·u or C + (I − C), whichever rounds less: the
  // second keeps the digits of a hit on a small figure seen from far away.
  const double from_a = max_abs(A) + std::abs(hit.t) * max_abs(ray.direction);
  const double from_c = max_abs(C) + r;
  if (!(t > 0)) hit.I = A;
  else if (from_c < from_a) hit.I = C + times_pow2(radial, e);
  else hit.I = A + hit.t * ray.direction;
  hit.N = radial_length > 0 ? radial / radial_length : -1.0 * (AC.hi / ac);
  res.hit = hit;
  return res;
}

// The same, every decision exact for the given doubles (predicates.h): epure solve's.
inline Vec2 as_vec(const ExactVec2& v) { return v.hi + v.lo; }
inline Vec3 as_vec(const ExactVec3& v) { return v.hi + v.lo; }

// The numbers as given: decimals as written (decimal.h), or doubles as themselves.
template <class Result, class Hit, class Ray, class DPoint>
Result intersect_ball_exact(const DPoint& dA, const DPoint& du, const DPoint& dC, const Decimal& dr) {
  const double r = dr.hi;
  if (!(r > 0) || !std::isfinite(r)) throw DegenerateFigure("r", "must be > 0");
  const auto direction = hi_vec(du);
  const double largest_u = max_abs(direction);
  if (!(largest_u > 0)) throw DegenerateFigure("u", "zero direction");
  if (!std::isfinite(largest_u)) throw DegenerateFigure("u", "not a finite direction");
  const auto A = hi_point(dA), C = hi_point(dC);
  const Ray ray{A, direction};

  Result res{};
  res.AC = C - A;

  // The figure (A, C, r) brought near unit size by 2^-e and the direction by 2^-f: exact, and
  // every t below is in units of the scaled direction, t_world = t·2^(e−f).
  const int e = binary_exponent(std::max({max_abs(A), max_abs(C), r}));
  const int f = binary_exponent(largest_u);
  const auto u = times_pow2(ray.direction, -f);
  const auto U = decimal_vector(du, f);  // u with its decimals' rests, for the decisions
  const DecimalScalar RS(dr, e);
  const double rs = RS.hi;
  const auto AC = decimal_difference(dC, dA, e);
  const double length_u = plain_norm(u);
  // ‖u‖² as the worksheet kernel takes it (length_u², the square root's rounding twice): a
  // key's solution is `epure solve`'s to the bit on every worksheet instance (tests/cli/
  // generate.sh). It leaves t_proj of a far origin up to 5 ulps off: printed_values (below)
  // replaces such values, and only those.
  const double uu = length_u * length_u;
  auto to_world_t = [&](double t) { return times_pow2(t, e - f); };

  // Every decision below is the sign of a polynomial of the data, exact (predicates.h):
  // inside ‖AC‖² < r², behind u·AC < 0, miss ‖u‖²r² < ‖u ∧ AC‖² (d² > r²), tangent when equal.
  const Certain excess = certain_excess(AC, RS);  // ‖AC‖² − r²
  const Certain toward = certain_dot(U, AC);  // u·AC
  // P = A + t_proj·u with (AC − t_proj·u)·u = 0; of u·AC's sign
  const double t_proj = toward.value / uu;
  res.t_proj = to_world_t(t_proj);
  res.P = A + res.t_proj * ray.direction;
  const auto offset = offset_from_line(u, length_u, AC);
  res.d2 = times_pow2(offset.d * offset.d, 2 * e);
  res.inside = excess.sign < 0;

  // behind: outside (or on the circle) and pointing away from C, the course's first test
  if (!res.inside && toward.sign < 0) {
    res.reason = NoHit::behind;
    return res;
  }
  // miss: the line passes farther than r from C, d² > r², i.e. disc = ‖u‖²(r² − d²) < 0. d, from
  // the exact AC's cross product, is within 2ε of itself: r − d beyond 8ε of r + d has the sign
  // of disc, and the textbook PI = √((r − d)(r + d)) is accurate as long as its error, about
  // ε·d²/PI, is within a few ulps of the figure's size. Otherwise (near tangency) disc is evaluated
  // to its last digits, or exactly (predicates.h): no window snaps a near tangent to a tangent.
  const double d = offset.d;
  const double gap = rs - d;
  // (decimal data: d was found with u's double, off by ε‖AC‖ at most, and r's by ε·r)
  const double rests = U.err == 0 && RS.err == 0 ? 0 : 2 * kEpsilon * (plain_norm(AC.hi) + rs);
  const bool clear = std::abs(gap) > 8 * kEpsilon * (rs + d) + rests;
  if (clear && gap < 0) {
    res.reason = NoHit::miss;
    return res;
  }
  const double h_plain = std::sqrt(gap * (rs + d));
  const double size = times_pow2(std::max({max_abs(A), max_abs(C), r}), -e);
  double h = h_plain;  // PI = √(r² − d²)
  if (!(clear && d * d <= 4 * h_plain * size)) {
    const Certain disc = certain_discriminant(U, AC, RS);
    if (disc.sign < 0) {
      res.reason = NoHit::miss;
      return res;
    }
    h = std::sqrt(disc.value) / length_u;  // 0 exactly when tangent
  }
  res.half_chord = times_pow2(h, e);
  const double h_param = h / length_u;
  // The roots t_proj ∓ h have the product c = (‖AC‖² − r²) / u·u. Each root is taken in the
  // form that does not cancel (the smaller one as c over the larger, when both are positive).
  const double c = excess.value / uu;
  double t;
  double along;  // (t − t_proj)·‖u‖: −h at the entry, +h at the exit
  if (res.inside) {
    t = toward.sign >= 0 ? t_proj + h_param : c / (t_proj - h_param);
    along = h;
  } else {
    // outside or on the circle, u·AC ≥ 0: t_proj ≥ 0, and t = 0 exactly when A is on it
    const double sum = t_proj + h_param;
    t = excess.sign == 0 ? 0.0 : c / sum;
    along = -h;
  }
  Hit hit{};
  hit.t = to_world_t(t);
  if (!(t > 0)) {
    // A itself: N = (A − C) / r with A − C exact
    hit.I = A;
    hit.N = (-1.0 / rs) * as_vec(AC);
    res.hit = hit;
    return res;
  }
  // I − C = (t − t_proj)·u − w, of length r: no cancellation, whatever the size of AC.
  const auto radial = (along / length_u) * u - offset.w;
  const double radial_length = plain_norm(radial);
  // I is A + t·u or C + (I − C), whichever rounds less: the second keeps the digits of a hit
  // on a small figure seen from far away.
  const double from_a = max_abs(A) + std::abs(hit.t) * max_abs(ray.direction);
  const double from_c = max_abs(C) + r;
  if (from_c < from_a) hit.I = C + times_pow2(radial, e);
  else hit.I = A + hit.t * ray.direction;
  hit.N = radial_length > 0 ? radial / radial_length : -1.0 * (AC.hi / plain_norm(AC.hi));
  res.hit = hit;
  return res;
}

template <class Result, class Hit, class Ray, class Point>
Result intersect_ball_exact(const Ray& ray, Point C, double r) {
  return intersect_ball_exact<Result, Hit, Ray>(decimal_point(ray.origin), decimal_point(ray.direction),
                                                decimal_point(C), Decimal::of(r));
}


// ---- The lengths `epure solve` prints: t_proj·‖u‖ and t·‖u‖ ------------------------------
// Both kernels' t_proj divides u·AC by length_u² (the square of the rounded length, the
// worksheet formula): with ‖u‖ as solve rounds it, the printed length is off by at most 13.5
// roundings of itself (2D 10: u·AC 1, length_u² 2·2 + 1, the quotient 1, ‖u‖ by hypot 2, the
// product 1; 3D: 2·2.5 + 1 for length_u², 4.5 for libstdc++'s three-argument hypot), 16 with
// the second-order terms, 8ε: within 4 ulps of
// max(S, |·|) while |t_proj| ≲ S/4, not beyond (5 ulps measured). Rather than change those bits
// (the keys print them, tests/cli/generate.sh), each length the bound cannot vouch for is
// compared with an accurate value a (double-double; its error e_a, bounded beside it, is below
// 1/16 ulp but for A next to a tangent point, where the length stays as it is) and
// kept if it is within 4 ulps of it; otherwise a, rounded, is printed. t has no such bound (its
// error goes through the half chord): it is compared whenever it is positive. So the printed
// bits change only where they were beyond 4 ulps.
using DD = exact::TwoTerm;  // hi + lo, normalised
inline DD dd_sum(DD a, DD b) {
  const DD s = exact::two_sum(a.hi, b.hi);
  return exact::two_sum(s.hi, s.lo + (a.lo + b.lo));
}
inline DD dd_product(DD a, DD b) {
  const DD p = exact::two_product(a.hi, b.hi);
  return exact::two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
inline DD dd_quotient(DD a, DD b) {
  const double q = a.hi / b.hi;
  const DD qb = dd_product({q, 0}, b);
  const double rest = ((a.hi - qb.hi) - qb.lo + a.lo) / b.hi;  // a.hi − qb.hi exact (Sterbenz)
  return exact::two_sum(q, rest);
}
inline DD dd_sqrt(DD a) {
  if (!(a.hi > 0)) return {0, 0};
  const double s = std::sqrt(a.hi);
  return exact::two_sum(s, (std::fma(-s, s, a.hi) + a.lo) / (2 * s));
}
inline DD as_dd(const Certain& c) { return {c.value, c.lo}; }
// ‖u‖², every term positive: to ε² of itself
inline DD squared_norm(Vec2 u) {
  exact::CompensatedSum s;
  return s.add_product(u.x, u.x).add_product(u.y, u.y).two_term();
}
inline DD squared_norm(Vec3 u) {
  exact::CompensatedSum s;
  return s.add_product(u.x, u.x).add_product(u.y, u.y).add_product(u.z, u.z).two_term();
}

// The spacing of the doubles at m (m positive, normal), and the bound the contract allows.
inline double ulp_at(double m) { return times_pow2(1.0, binary_exponent(m) - 52); }
// 4 ulps of max(S, |x|), the true |x| possibly in the binade below the computed one
inline double allowed_error(double S, double x) {
  return 4 * ulp_at(std::max(S, std::abs(x) * (1 - 0x1p-50)));
}

// w if within `allowed` of the accurate a (a ± e_a), else a rounded.
inline double checked_within(double w, DD a, double e_a, double allowed) {
  // the margin covers e_a and the rounding of the difference itself
  const double off = std::abs((w - a.hi) - a.lo);
  return off <= allowed - e_a - allowed * 0x1p-10 ? w : a.hi;
}
// A length: within 4 ulps of max(S, |a|), in the figure's units.
inline double checked(double w, DD a, double e_a, double S) {
  return checked_within(w, a, e_a, allowed_error(S, a.hi));
}

// The coordinates of a vector, to treat both dimensions alike.
inline std::array<double, 2> parts(Vec2 v) { return {v.x, v.y}; }
inline std::array<double, 3> parts(Vec3 v) { return {v.x, v.y, v.z}; }
inline Vec2 from_parts(const std::array<double, 2>& a) { return {a[0], a[1]}; }
inline Vec3 from_parts(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
inline std::array<double, 2> parts(Point2 p) { return {p.x, p.y}; }
inline std::array<double, 3> parts(Point3 p) { return {p.x, p.y, p.z}; }
inline Point2 point_from_parts(const std::array<double, 2>& a) { return {a[0], a[1]}; }
inline Point3 point_from_parts(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

inline double dot_parts(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double dot_parts(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The a-priori bound: 8ε|w| (above) within 4 ulps, less a margin for the second-order terms.
inline bool vouched(double w, double S) {
  return 8 * kEpsilon * std::abs(w) <= (4 - 0x1p-6) * ulp_at(std::max(S, std::abs(w)));
}

// `length` is ‖ray.direction‖ as the caller rounds it; res is either kernel's result for the ray
// and the ball (C, r). Both kernels' decisions are kept: the root is the one they chose, and a
// tangent (no half chord) stays one.
// The data as given: decimals as written (decimal.h), their rests in every accurate value.
template <class Result, class DPoint>
auto printed_values(const DPoint& dA, const DPoint& du, const DPoint& dC, const Decimal& dr, const Result& res,
                    double length) {
  using Vec = decltype(hi_vec(du));
  using Point = decltype(hi_point(dA));
  const Point A = hi_point(dA), C = hi_point(dC);
  const Vec direction = hi_vec(du);
  const double r = dr.hi;
  PrintedValues<Vec, Point> out{res.t_proj * length, res.hit ? res.hit->t * length : 0.0,
                                res.hit ? res.hit->I : Point{}, res.hit ? res.hit->N : Vec{}};
  const double S = std::max({max_abs(A), max_abs(C), r});
  // t = 0 is A itself (on the figure), a decision and not a rounding
  const bool check_t = res.hit && res.hit->t > 0;
  if (vouched(out.t_proj, S) && !check_t) return out;

  // In the figure's units (2^-e), u near unit size: every product exact or compensated.
  const int e = binary_exponent(S);
  const int f = binary_exponent(max_abs(direction));
  const auto u = times_pow2(direction, -f);
  const auto U = decimal_vector(du, f);
  const DecimalScalar RS(dr, e);
  const double rs = RS.hi;
  const double Ss = times_pow2(S, -e);
  const auto AC = decimal_difference(dC, dA, e);
  // ‖u‖², ‖u‖ and τ = u·AC / ‖u‖ to a few ε² of themselves (u with its decimals' rests)
  const DD uu = dd_sum(squared_norm(u), {2 * dot_parts(u, U.lo), 0});
  const DD length_u = dd_sqrt(uu);
  const DD tau = dd_quotient(detail::compensated_dot(U, AC), length_u);
  // u·AC's error is 64ε² of its terms (predicates.h), at most ‖u‖·‖AC‖ ≤ 2√3‖u‖·S
  const double e_tau = 0x1p-90 * Ss + 0x1p-96 * std::abs(tau.hi);
  const double w_proj = times_pow2(out.t_proj, -e);
  out.t_proj = times_pow2(checked(w_proj, tau, e_tau, Ss), e);
  if (!check_t) return out;

  // PI = √(r² − d²) = √(disc / ‖u‖²), disc within 2^-59 of itself (predicates.cpp); 0 at a
  // tangent, as the kernel decided it
  double e_h = 0;
  DD h{0, 0};
  if (*res.half_chord > 0) {
    h = dd_sqrt(dd_quotient(as_dd(certain_discriminant(U, AC, RS)), uu));
    e_h = 0x1p-58 * h.hi;
  }
  // ‖AC‖² − r² = (τ − h)(τ + h), within 64ε² of ‖AC‖² + r² ≤ 13·S² (predicates.h)
  const DD excess = as_dd(certain_excess(AC, RS));
  const double e_excess = 0x1p-90 * Ss * Ss;
  // the root the kernel chose, each in its form without cancellation
  DD t;
  double e_t;
  const DD minus_h{-h.hi, -h.lo};
  // (at τ = 0 both forms are the same root: the choice is only against cancellation)
  if (res.inside && tau.hi >= 0) {
    t = dd_sum(tau, h);  // the exit, beyond P
    e_t = e_tau + e_h;
  } else {
    const DD divisor = res.inside ? dd_sum(tau, minus_h) : dd_sum(tau, h);  // of c's sign
    t = dd_quotient(excess, divisor);
    const double d = std::abs(divisor.hi);
    e_t = (e_excess + std::abs(t.hi) * (e_tau + e_h)) / d;
    // beyond a quarter ulp, A is within rounding of the tangent point, t a few ulps of S at
    // most: left as the kernel has it
    if (!(e_t < 0.25 * ulp_at(Ss))) return out;
  }
  e_t += 0x1p-96 * std::abs(t.hi);
  out.t = times_pow2(checked(times_pow2(out.t, -e), t, e_t, Ss), e);

  // N = (I − C) / ‖I − C‖ with I − C = t·u/‖u‖ − AC (‖I − C‖ = r but where the kernel made a near
  // tangent a tangent: N stays a unit vector there). Each coordinate of I − C is within
  // e_t + 2^-96 (|t| + 2S) of itself, N within twice that over r; the bound is 4 ulps of
  // max(1, S/r) (N·r as a length, compare_jsonl.py).
  const auto u_parts = parts(u), u_lo = parts(U.lo), ac_hi = parts(AC.hi), ac_lo = parts(AC.lo);
  std::array<DD, u_parts.size()> radial;
  DD radial2{0, 0};
  for (std::size_t i = 0; i < u_parts.size(); ++i) {
    radial[i] = dd_sum(dd_quotient(dd_product(t, exact::two_sum(u_parts[i], u_lo[i])), length_u), {-ac_hi[i], -ac_lo[i]});
    radial2 = dd_sum(radial2, dd_product(radial[i], radial[i]));
  }
  // each coordinate of I − C within this of itself
  const double e_radial = e_t + 0x1p-96 * (std::abs(t.hi) + 2 * Ss);
  // I = C + (I − C): A + t·û rounds t·û, and t itself is a length of up to 4 ulps of S, so the
  // kernel's I can reach 5 ulps where t·û is large beside S (an origin inside, a long chord).
  // Each coordinate within the radial's error plus the sum's rounding.
  const auto c_parts = parts(times_pow2(C, -e)), c_lo = parts(times_pow2(lo_vec(dC), -e));
  auto I = parts(out.I);
  for (std::size_t i = 0; i < I.size(); ++i) {
    const DD accurate = dd_sum(exact::two_sum(c_parts[i], c_lo[i]), radial[i]);
    const double e_i = e_radial + 0x1p-100 * (std::abs(accurate.hi) + Ss);
    I[i] = times_pow2(checked(times_pow2(I[i], -e), accurate, e_i, Ss), e);
  }
  out.I = point_from_parts(I);
  const DD radial_length = dd_sqrt(radial2);
  if (!(radial_length.hi > 0.5 * rs)) return out;  // not on the circle: a decision's, not a rounding
  const double e_n = 2 * e_radial / radial_length.hi + 0x1p-100;
  const double allowed_n = 4 * std::max(0x1p-52, ulp_at(Ss) / rs * (1 - 0x1p-50));
  auto N = parts(out.N);
  for (std::size_t i = 0; i < N.size(); ++i)
    N[i] = checked_within(N[i], dd_quotient(radial[i], radial_length), e_n, allowed_n);
  out.N = from_parts(N);
  return out;
}

// Doubles as themselves.
template <class Result, class Ray, class Point>
auto printed_values(const Ray& ray, Point C, double r, const Result& res, double length) {
  return printed_values(decimal_point(ray.origin), decimal_point(ray.direction), decimal_point(C), Decimal::of(r),
                        res, length);
}

}  // namespace epure::geo::detail
