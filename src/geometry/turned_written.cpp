#include "geometry/turned_written.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

#include "geometry/affine.h"
#include "geometry/bounded.h"
#include "geometry/degenerate.h"
#include "geometry/quadratic.h"
#include "geometry/ray_circle.h"
#include "support/portable.h"

namespace epure::geo {

namespace {

using exact::ExactDecimal;

// The sign of a polynomial: certain from its bounded value, or none (NotCertain thrown, then
// the same polynomial is evaluated on exact decimals); exact decimals' own sign.
struct NotCertain {};
int sign(const Bounded& x) {
  if (x.mid == 0 && x.err == 0) return 0;  // a datum that is zero exactly
  const int s = x.certain_sign();
  if (s == 0) throw NotCertain{};
  return s;
}
int sign(const ExactDecimal& x) { return x.sign(); }
template <int K>
int sign(const exact::Quadratic<K>& x) { return x.sign(); }

double to_double(const ExactDecimal& x) {
  const exact::TwoTerm v = exact::two_term(x);
  return v.hi + v.lo;
}
template <int K>
double to_double(const exact::Quadratic<K>& x) { return x.value(); }
double to_double(const Bounded& x) { return x.mid; }

// A datum, and p + q·√k (a cosine or sine of the table below), in each kind of number.
Bounded number(const Decimal& d, Bounded*) { return Bounded::of(d); }
ExactDecimal number(const Decimal& d, ExactDecimal*) { return exact::exact_value(d); }
template <int K>
exact::Quadratic<K> number(const Decimal& d, exact::Quadratic<K>*) { return {exact::exact_value(d), {}}; }
Bounded trig(double p, double q, int k, Bounded*) {
  const double x = p + q * std::sqrt(static_cast<double>(k));  // √k correctly rounded, then one sum
  return {x, 0x1p-51 * std::abs(x) + 0x1p-1070};
}
ExactDecimal trig(double p, double, int, ExactDecimal*) { return exact::exact_value(p); }
template <int K>
exact::Quadratic<K> trig(double p, double q, int, exact::Quadratic<K>*) {
  return {exact::exact_value(p), exact::exact_value(q)};
}

// A double-double (hi + lo, about 2^-104 of itself): the values of a turned figure from the
// decimals with cos θ and sin θ to that precision, where the carried ray's doubles are several
// ulps off (its rounded cos θ, sin θ, A − C and sizes, magnified near tangency). Portable's
// Dekker products (no fma): the same bits natively and in the browser.
struct Dd {
  double hi = 0, lo = 0;
  friend Dd operator+(Dd a, Dd b) {
    const auto s = portable::detail::dd_add({a.hi, a.lo}, {b.hi, b.lo});
    return {s.hi, s.lo};
  }
  friend Dd operator-(Dd a) { return {-a.hi, -a.lo}; }
  friend Dd operator-(Dd a, Dd b) { return a + (-b); }
  friend Dd operator*(Dd a, Dd b) {
    const auto p = portable::detail::dd_mul({a.hi, a.lo}, {b.hi, b.lo});
    return {p.hi, p.lo};
  }
};
double to_double(const Dd& x) { return x.hi + x.lo; }
Dd number(const Decimal& d, Dd*) {  // its nearest double and rounded rest
  const auto s = portable::detail::two_sum(d.hi, d.lo);
  return {s.hi, s.lo};
}
// √2 and √3 to 2^-106 of themselves
constexpr Dd kSqrt2{0x1.6a09e667f3bcdp+0, -0x1.bdd3413b26456p-54};
constexpr Dd kSqrt3{0x1.bb67ae8584caap+0, 0x1.cec95d0b5c1e3p-54};
Dd trig(double p, double q, int k, Dd*) {  // p + q·√k, p and q in {0, ±½, ±1}: exact products
  if (q == 0) return {p, 0};
  const Dd root = k == 2 ? kSqrt2 : kSqrt3;
  return Dd{p, 0} + Dd{q * root.hi, q * root.lo};
}
// cos θ and sin θ of the decimal angle in double-double: its double reduced to a quarter turn
// and a rest in [−45°, 45°] exactly (as cos_sin_degrees does), the decimal's rest added, times
// π/180 in double-double, then the Taylor series in Horner's form with double-double
// coefficients (−1)^k/(2k+1)! and (−1)^k/(2k)! to x^27 and x^28 (the next below 2^-110 for
// |x| ≤ π/4): about 2^-100 of each, without dd_sin_cos's divisions (a tenth of its time).
constexpr Dd kSinSeries[] = {
    {0x1.0000000000000p+0, 0x0.0p+0}, {-0x1.5555555555555p-3, -0x1.5555555555555p-57},
    {0x1.1111111111111p-7, 0x1.1111111111111p-63}, {-0x1.a01a01a01a01ap-13, -0x1.a01a01a01a01ap-73},
    {0x1.71de3a556c734p-19, -0x1.c154f8ddc6c00p-73}, {-0x1.ae64567f544e4p-26, 0x1.c062e06d1f209p-80},
    {0x1.6124613a86d09p-33, 0x1.f28e0cc748ebep-87}, {-0x1.ae7f3e733b81fp-41, -0x1.1d8656b0ee8cbp-97},
    {0x1.952c77030ad4ap-49, 0x1.ac981465ddc6cp-103}, {-0x1.2f49b46814157p-57, -0x1.2650f61dbdcb4p-112},
    {0x1.71b8ef6dcf572p-66, -0x1.d043ae40c4647p-120}, {-0x1.761b41316381ap-75, 0x1.3423c7d91404fp-130},
    {0x1.3f3ccdd165fa9p-84, -0x1.58ddadf344487p-139}, {-0x1.d1ab1c2dccea3p-94, -0x1.054d0c78aea14p-149}};
constexpr Dd kCosSeries[] = {
    {0x1.0000000000000p+0, 0x0.0p+0}, {-0x1.0000000000000p-1, 0x0.0p+0},
    {0x1.5555555555555p-5, 0x1.5555555555555p-59}, {-0x1.6c16c16c16c17p-10, 0x1.f49f49f49f49fp-65},
    {0x1.a01a01a01a01ap-16, 0x1.a01a01a01a01ap-76}, {-0x1.27e4fb7789f5cp-22, -0x1.cbbc05b4fa99ap-76},
    {0x1.1eed8eff8d898p-29, -0x1.2aec959e14c06p-83}, {-0x1.93974a8c07c9dp-37, -0x1.05d6f8a2efd1fp-92},
    {0x1.ae7f3e733b81fp-45, 0x1.1d8656b0ee8cbp-101}, {-0x1.6827863b97d97p-53, -0x1.eec01221a8b0bp-107},
    {0x1.e542ba4020225p-62, 0x1.ea72b4afe3c2fp-120}, {-0x1.0ce396db7f853p-70, 0x1.aebcdbd20331cp-124},
    {0x1.f2cf01972f578p-80, -0x1.9ada5fcc1ab14p-135}, {-0x1.88e85fc6a4e5ap-89, 0x1.71c37ebd16540p-143},
    {0x1.0a18a2635085dp-98, 0x1.b9e2e28e1aa54p-153}};
std::array<Dd, 2> dd_cos_sin(const Decimal& angle_deg) {
  using portable::detail::two_sum;
  constexpr Dd kPiOver180{0x1.1df46a2529d39p-6, 0x1.5c1d8becdd291p-62};
  const double turns = std::fmod(angle_deg.hi, 360.0);
  const double quarter = std::nearbyint(turns / 90.0);
  const double rest = turns - 90.0 * quarter;
  const auto r = two_sum(rest, angle_deg.lo);
  const Dd x = Dd{r.hi, r.lo} * kPiOver180, x2 = x * x;
  Dd sn = kSinSeries[std::size(kSinSeries) - 1], cs = kCosSeries[std::size(kCosSeries) - 1];
  for (std::size_t k = std::size(kSinSeries) - 1; k-- > 0;) sn = kSinSeries[k] + x2 * sn;
  for (std::size_t k = std::size(kCosSeries) - 1; k-- > 0;) cs = kCosSeries[k] + x2 * cs;
  sn = sn * x;
  const Dd c = cs, s = sn;
  switch (((static_cast<int>(quarter) % 4) + 4) % 4) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

// An angle as written whose cos and sin are p + q·√k with p, q in {0, ±½, ±1}: a whole number
// of quarter turns (k = 1), of 45° (k = 2) or of 30° (k = 3). Any other angle is k = 0: its cos
// and sin are only known within a bound (general_angle), so its decisions are the filter's alone.
struct SpecialAngle {
  int k = 1;
  int quarter = 0;                         // k = 1: R(θ) is that many quarter turns
  double cp = 1, cq = 0, sp = 0, sq = 0;   // cos θ = cp + cq·√k, sin θ = sp + sq·√k
  Bounded cos, sin;                        // k = 0: cos θ and sin θ enclosed
};

// cos θ and sin θ of any angle as written, each within a bound of the double given. The double
// angle's cos and sin (cos_sin_degrees) are off by its radians' rounding (the quarter-turn
// reduction is exact; rest·(π/180), |rest| ≤ 45°, is within 2^-52 of its value, the sine's slope
// at most 1) plus their own correct rounding (2^-54): below 2^-51, counted as 2^-50. The decimal
// angle differs from its double by lo (within its error), which moves them by at most
// |lo|·π/180 < 0.0175·|lo|.
SpecialAngle general_angle(const Decimal& angle_deg) {
  const CosSin cs = cos_sin_degrees(angle_deg.hi);
  const double err = 0x1p-50 + (std::abs(angle_deg.lo) + angle_deg.error()) * 0.0175 * (1 + 0x1p-50);
  SpecialAngle a;
  a.k = 0;
  a.cos = {cs.cos, err};
  a.sin = {cs.sin, err};
  return a;
}
std::optional<SpecialAngle> special_angle(const Decimal& angle_deg) {
  // the decimal is its double exactly (lo = 0), a whole number of degrees (fmod is exact)
  const double a = angle_deg.hi;
  if (angle_deg.lo != 0 || !(std::abs(a) <= 0x1p53) || std::fmod(a, 15.0) != 0) return std::nullopt;
  double m = std::fmod(a, 360.0);
  if (m < 0) m += 360;
  const int degrees = static_cast<int>(m);
  const double c_sign = degrees < 90 || degrees > 270 ? 1 : -1, s_sign = degrees < 180 ? 1 : -1;
  const int in_quadrant = degrees % 90;  // the angle to the previous axis
  const int from_x = degrees % 180 < 90 ? in_quadrant : 90 - in_quadrant;  // |θ| folded to [0, 90]
  if (in_quadrant == 0) return SpecialAngle{1, degrees / 90, 1, 0, 0, 0, {}, {}};
  if (in_quadrant == 45) return SpecialAngle{2, 0, 0, c_sign * 0.5, 0, s_sign * 0.5, {}, {}};
  if (from_x == 30) return SpecialAngle{3, 0, 0, c_sign * 0.5, s_sign * 0.5, 0, {}, {}};
  if (from_x == 60) return SpecialAngle{3, 0, c_sign * 0.5, 0, 0, s_sign * 0.5, {}, {}};
  return std::nullopt;  // 15°, 75°: √6 ± √2, not worth a field of degree 4
}

// f(tag) with the exact number type of the angle's field (with the filter's bounded numbers for
// an angle of no exact field: its hit is rebuilt from their midpoints).
template <class F>
auto on_exact(int k, F&& f) {
  if (k == 0) return f(static_cast<Bounded*>(nullptr));
  if (k == 2) return f(static_cast<exact::Quadratic<2>*>(nullptr));
  if (k == 3) return f(static_cast<exact::Quadratic<3>*>(nullptr));
  return f(static_cast<ExactDecimal*>(nullptr));
}

// The data in the figure's own frame: X = R(−θ)(A − C), U = R(−θ)u, exactly (a quarter turn is a
// permutation with signs: R(−90°)(x, y) = (y, −x)), the sizes s along its axes.
template <class Num>
struct Turned {
  std::array<Num, 2> X, U, s;
  // Unpacked as `const auto &X = f.X, &U = f.U, &s = f.s;`, not as a structured binding: clang 14
  // (the fuzz build's, emscripten's) lets no lambda capture a structured binding.
};
template <class Num>
std::array<Num, 2> turn_back(const Num& x, const Num& y, int q) {
  switch (q) {
    case 1: return {y, -x};
    case 2: return {-x, -y};
    case 3: return {-y, x};
    default: return {x, y};
  }
}
template <class Num>
Turned<Num> turned(const WrittenTurned& w, const DPoint2& direction, const SpecialAngle& angle) {
  Num* tag = nullptr;
  const Num dx = number(w.A[0], tag) - number(w.C[0], tag), dy = number(w.A[1], tag) - number(w.C[1], tag);
  const Num ux = number(direction[0], tag), uy = number(direction[1], tag);
  const std::array<Num, 2> s{number(w.sx, tag), number(w.sy, tag)};
  if (angle.k == 1) return {turn_back(dx, dy, angle.quarter), turn_back(ux, uy, angle.quarter), s};
  Num c, sn;
  if constexpr (std::is_same_v<Num, Bounded>) {
    c = angle.k == 0 ? angle.cos : trig(angle.cp, angle.cq, angle.k, tag);
    sn = angle.k == 0 ? angle.sin : trig(angle.sp, angle.sq, angle.k, tag);
  } else if constexpr (std::is_same_v<Num, Dd>) {
    if (angle.k == 0) {
      const auto cs = dd_cos_sin(w.angle_deg);
      c = cs[0];
      sn = cs[1];
    } else {
      c = trig(angle.cp, angle.cq, angle.k, tag);
      sn = trig(angle.sp, angle.sq, angle.k, tag);
    }
  } else {
    c = trig(angle.cp, angle.cq, angle.k, tag);
    sn = trig(angle.sp, angle.sq, angle.k, tag);
  }
  // R(−θ)v = (c·x + s·y, c·y − s·x)
  return {{c * dx + sn * dy, c * dy - sn * dx}, {c * ux + sn * uy, c * uy - sn * ux}, s};
}

// What decides a ray and a figure, as the kernels decide it.
struct Decisions {
  bool inside = false;
  bool hit = false;
  bool at_origin = false;    // the hit is A itself (t = 0)
  std::optional<Face> face;  // the rectangle's side hit
  bool tangent = false;      // the ellipse's line tangent: a hit with no chord
  bool operator==(const Decisions& o) const {
    return inside == o.inside && hit == o.hit && at_origin == o.at_origin && face == o.face;
  }
};

// ‖u_c‖² − (u_c ∧ A_c)² times a²b²: the ellipse's line through a chord (+), tangent (0) or beside.
template <class Num>
Num ellipse_chord(const Turned<Num>& f) {
  const auto &X = f.X, &U = f.U, &s = f.s;
  const Num a2 = s[0] * s[0], b2 = s[1] * s[1];
  const Num cross = U[0] * X[1] - U[1] * X[0];
  return b2 * (U[0] * U[0]) + a2 * (U[1] * U[1]) - cross * cross;
}

// The ellipse x²/a² + y²/b² = 1 in its frame, as ray_circle decides the canonical circle
// (ray_circle.h), each polynomial multiplied by a power of a²b² > 0: inside ‖A_c‖² < 1, behind
// A_c·u_c > 0 from outside or on it, miss ‖u_c‖² < (u_c ∧ A_c)², tangent when equal.
template <class Num>
Decisions decide_ellipse(const Turned<Num>& f) {
  const auto &X = f.X, &U = f.U, &s = f.s;
  const Num a2 = s[0] * s[0], b2 = s[1] * s[1];
  const int excess = sign(b2 * (X[0] * X[0]) + a2 * (X[1] * X[1]) - a2 * b2);
  Decisions d;
  d.inside = excess < 0;
  if (d.inside) {
    d.hit = true;
    return d;
  }
  if (sign(b2 * (X[0] * U[0]) + a2 * (X[1] * U[1])) > 0) return d;  // behind
  const int chord = sign(ellipse_chord(f));
  d.hit = chord >= 0;
  d.tangent = chord == 0;
  d.at_origin = d.hit && excess == 0;
  return d;
}

// The rectangle |x| ≤ w, |y| ≤ h in its frame, as the box kernel decides the canonical square
// (ray_box.h: candidate sides, the side met first or last, the landing point on the side, the x
// side first at a corner), each comparison multiplied by the sizes it divides by.
template <class Num>
Decisions decide_rectangle(const Turned<Num>& f) {
  const auto &X = f.X, &U = f.U, &s = f.s;
  const std::array<int, 2> sign_u{sign(U[0]), sign(U[1])};
  Decisions d;
  bool candidate[2][2] = {};  // [axis][σ = +1 ? 0 : 1]: σ·X_k ≥ s_k
  for (int k = 0; k < 2; ++k) {
    candidate[k][0] = sign(X[k] - s[k]) >= 0;
    candidate[k][1] = sign(X[k] + s[k]) <= 0;
  }
  d.inside = !(candidate[0][0] || candidate[0][1] || candidate[1][0] || candidate[1][1]);
  // The gap to side (k, σ) in units of s_k: s_k − σX_k inside, σX_k − s_k from a candidate side.
  auto gap = [&](Face face) {
    const Num g = s[face.axis] - (face.sign > 0 ? X[face.axis] : -X[face.axis]);
    return d.inside ? g : -g;
  };
  auto abs_u = [&](int k) { return sign_u[k] < 0 ? -U[k] : U[k]; };
  // side j met before side k: gap_j·|u_k| < gap_k·|u_j| (over s_j·s_k > 0)
  auto earlier = [&](Face j, Face k) { return sign(gap(j) * abs_u(k.axis) - gap(k) * abs_u(j.axis)) < 0; };
  if (d.inside) {
    for (int k = 0; k < 2; ++k) {
      if (sign_u[k] == 0) continue;
      const Face face{k, sign_u[k]};
      if (!d.face || earlier(face, *d.face)) d.face = face;
    }
    d.hit = true;
    return d;
  }
  for (int sigma : {+1, -1})
    for (int n = 0; n < 2; ++n) {
      const Face face{n, sigma};
      if (!candidate[n][sigma > 0 ? 0 : 1] || !(sigma * sign_u[n] < 0)) continue;
      const Num g = gap(face);
      const int j = 1 - n;
      // on the side: (s_j ∓ X_j)·|u_n| ∓ gap·u_j ≥ 0 for both signs (over s_j·s_n)
      bool on_side = true;
      for (int side : {+1, -1}) {
        const Num room = side > 0 ? s[j] - X[j] : s[j] + X[j];
        const Num along = side > 0 ? g * U[j] : -(g * U[j]);
        if (sign(room * abs_u(n) - along) < 0) on_side = false;
      }
      if (!on_side) continue;
      if (d.face) {
        const bool later = earlier(*d.face, face);
        const bool tie = !later && !earlier(face, *d.face);
        if (!later && !(tie && face.axis < d.face->axis)) continue;
      }
      d.face = face;
      d.at_origin = sign(g) == 0;
    }
  d.hit = d.face.has_value();
  return d;
}

// The decisions: by the floating-point filter where it tells every sign (the figure clear of every
// boundary by far more than the carried ray's rounding), else on the exact numbers. At an angle
// of no exact field the filter is all there is: a figure it cannot tell (within about 1e-15 of
// the line's largest number from a boundary: A − C is rounded at A's scale) is refused, never
// answered on the rounded ray.
template <class Decide>
Decisions decide(const WrittenTurned& w, const DPoint2& direction, const SpecialAngle& angle, Decide decide_on,
                 std::string_view figure) {
  try {
    return decide_on(turned<Bounded>(w, direction, angle));
  } catch (const NotCertain&) {
    if (angle.k == 0)
      throw DegenerateFigure(
          "angle", fmt::format("{}: the ray is within rounding (about 1e-15 of the line's largest number) of a boundary of "
                               "the {} turned by {}°, where epure cannot decide exactly (it can at whole multiples "
                               "of 30° and 45°); move the ray off the boundary or turn the figure by such an angle",
                               figure == "ellipse" ? "ray_ellipse" : "ray_rectangle", figure, w.angle_deg.hi));
    return on_exact(angle.k, [&](auto* tag) {
      using Num = std::remove_pointer_t<decltype(tag)>;
      return decide_on(turned<Num>(w, direction, angle));
    });
  }
}

// The kernels' decisions, as Decisions says them.
template <class Result>
Decisions kernel_decisions(const Result& e) {
  Decisions d{e.inside, e.hit.has_value(), e.hit && !(e.hit->t > 0), std::nullopt};
  if constexpr (requires { e.canonical.face; })
    if (e.hit) d.face = e.canonical.face;
  return d;
}

// The hit rebuilt from exact decisions that the carried ray's doubles did not take (within their
// rounding of a boundary): t from the carried ray, of the sign and branch decided, the point on
// the figure, the normal by the inverse transpose. I is A at t = 0, else A + t·u.
Point2 world_point(const Ray2& ray, double t) { return t > 0 ? ray.at(t) : ray.origin; }

// t of the ellipse's hit decided, from the exact decimals: the point X + t·U of its frame on
// b²x² + a²y² = a²b², α t² + 2β t + γ = 0; the near root from outside, the far one from inside,
// −β/α at tangency, each written without cancellation. Within a few ulps, of the sign decided.
template <class Num>
double ellipse_t(const Turned<Num>& f, const Decisions& d) {
  const auto &X = f.X, &U = f.U, &s = f.s;
  const Num a2 = s[0] * s[0], b2 = s[1] * s[1];
  const Num alpha_exact = b2 * (U[0] * U[0]) + a2 * (U[1] * U[1]);
  const double alpha = to_double(alpha_exact);
  const Num beta_exact = b2 * (X[0] * U[0]) + a2 * (X[1] * U[1]);
  const Num gamma_exact = b2 * (X[0] * X[0]) + a2 * (X[1] * X[1]) - a2 * b2;
  const double beta = to_double(beta_exact), gamma = to_double(gamma_exact);
  if (d.tangent) return -beta / alpha;
  const double root = std::sqrt(std::max(0.0, to_double(beta_exact * beta_exact - alpha_exact * gamma_exact)));
  if (d.inside) return beta <= 0 ? (root - beta) / alpha : -gamma / (beta + root);
  return gamma / (root - beta);
}

template <class Num>
RayEllipse rebuilt(RayEllipse e, const Decisions& d, const Turned<Num>& f, const Ray2& ray) {
  e.inside = e.canonical.inside = d.inside;
  e.hit.reset();
  e.canonical.hit.reset();
  if (!d.hit) {
    e.canonical.reason = e.canonical.t_proj < 0 && !d.inside ? NoHit::behind : NoHit::miss;
    return e;
  }
  e.canonical.reason.reset();
  const double t = d.at_origin ? 0.0 : ellipse_t(f, d);
  const Vec2 Ic = to_vec(e.canonical_ray.origin) + t * e.canonical_ray.direction;
  const Vec2 Nc = normalized(Ic).value_or(Vec2{1, 0});
  e.canonical.hit = Hit2{t, to_point(Ic), Nc};
  e.hit = Hit2{t, world_point(ray, t), detail::world_normal(e.to_world, Nc, "radii")};
  return e;
}

template <class Num>
RayRectangle rebuilt(RayRectangle e, const Decisions& d, const Turned<Num>& f, const Ray2& ray) {
  e.inside = e.canonical.inside = d.inside;
  e.hit.reset();
  e.canonical.hit.reset();
  e.canonical.face = d.face;
  if (!d.hit) return e;
  const Vec2 Ac = to_vec(e.canonical_ray.origin), uc = e.canonical_ray.direction;
  const int n = d.face->axis, j = 1 - n;
  const double sigma = d.face->sign;
  const std::array<double, 2> a{Ac.x, Ac.y}, u{uc.x, uc.y};
  // t = gap / |u_n| from the exact decimals (within about an ulp, of the sign decided)
  const Num gap = d.inside ? (d.face->sign > 0 ? f.s[n] - f.X[n] : f.s[n] + f.X[n])
                                    : (d.face->sign > 0 ? f.X[n] - f.s[n] : -f.X[n] - f.s[n]);
  const double t = d.at_origin ? 0.0 : std::abs(to_double(gap) / to_double(f.U[n]));
  std::array<double, 2> I{};
  I[n] = sigma;
  I[j] = std::clamp(a[j] + t * u[j], -1.0, 1.0);
  Vec2 Nc{0, 0};
  (n == 0 ? Nc.x : Nc.y) = sigma;
  e.canonical.hit = Hit2{t, {I[0], I[1]}, Nc};
  e.hit = Hit2{t, world_point(ray, t), detail::world_normal(e.to_world, Nc, "half")};
  return e;
}

}  // namespace

std::optional<int> quarter_turns(const Decimal& angle_deg) {
  const auto angle = special_angle(angle_deg);
  if (!angle || angle->k != 1) return std::nullopt;
  return angle->quarter;
}

namespace {

double ulp_of(double x) {
  const double m = std::abs(x);
  return std::nextafter(m, INFINITY) - m;
}
Dd dd_div(Dd a, Dd b) {
  const auto q = portable::detail::dd_div({a.hi, a.lo}, {b.hi, b.lo});
  return {q.hi, q.lo};
}
Dd dd_sqrt(Dd x) {  // the double root and one Newton step
  if (!(x.hi > 0)) return {};
  const double r = std::sqrt(x.hi);
  return Dd{r, 0} + Dd{(x - Dd{r, 0} * Dd{r, 0}).hi / (2 * r), 0};
}
// cos θ and sin θ in double-double, θ the angle as written.
std::array<Dd, 2> dd_rotation(const WrittenTurned& w, const SpecialAngle& angle) {
  Dd* tag = nullptr;
  if (angle.k == 0) return dd_cos_sin(w.angle_deg);
  if (angle.k != 1) return {trig(angle.cp, angle.cq, angle.k, tag), trig(angle.sp, angle.sq, angle.k, tag)};
  constexpr double c[] = {1, 0, -1, 0}, sn[] = {0, 1, 0, -1};
  return {Dd{c[angle.quarter], 0}, Dd{sn[angle.quarter], 0}};
}

// The hit of decided decisions from the decimals in double-double: t along the decimal
// direction, I = A + t·u, the world normal (the gradient turned back, normalised), each rounded
// once from about 2^-100 of its value (but near tangency, where t's root is that much less
// precise relatively: still far below an ulp short of 2^-50 of β²).
struct DdHit {
  Hit2 hit;  // rounded
  Dd t;      // t before its rounding
};
// An exact number as a double-double, to about 2^-104 of itself: p + q√K without cancellation,
// (p² − Kq²)/(p − q√K) where p and q√K nearly cancel.
Dd dd_of(const ExactDecimal& x) {
  const exact::TwoTerm v = exact::two_term(x);
  return {v.hi, v.lo};
}
template <int K>
Dd dd_of(const exact::Quadratic<K>& x) {
  const Dd root = K == 2 ? kSqrt2 : kSqrt3;
  const Dd p = dd_of(x.p), q = dd_of(x.q) * root;
  if (x.p.sign() * x.q.sign() >= 0) return p + q;
  return dd_div(dd_of(x.p * x.p - exact::exact_value(static_cast<double>(K)) * (x.q * x.q)), p - q);
}

// The ellipse's γ (A's place: b²x² + a²y² − a²b²) and discriminant β² − αγ, which near the
// boundary and near tangency are made of the data's last digits: in double-double from the
// decimals' hi + lo they are off by about ε² of the data (2^-104 of A, far from the origin: 1e-24
// of a small figure at 70), more than themselves when A is a hair of 1e-23 inside (a decimal of
// 25 digits). Where the double-double is within 2^-40 of its terms, they are taken exactly in
// the angle's field (multiples of 30°, 45°, 90°), then rounded to double-double; elsewhere (every
// worksheet line) the double-double stays. At other angles such a line is refused before.
struct Coefficients {
  Dd gamma, disc;
};
constexpr double kCoarse = 0x1p-40;  // of the terms: the double-double keeps 2^-60 of the value beyond
template <class Num>
Coefficients exact_coefficients(const Turned<Num>& f) {
  const auto &X = f.X, &U = f.U, &s = f.s;
  const Num a2 = s[0] * s[0], b2 = s[1] * s[1];
  const Num alpha = b2 * (U[0] * U[0]) + a2 * (U[1] * U[1]);
  const Num beta = b2 * (X[0] * U[0]) + a2 * (X[1] * U[1]);
  const Num gamma = b2 * (X[0] * X[0]) + a2 * (X[1] * X[1]) - a2 * b2;
  return {dd_of(gamma), dd_of(beta * beta - alpha * gamma)};
}
// The same in the exact field of a special angle (k = 1, 2, 3).
Coefficients exact_coefficients(const WrittenTurned& w, const DPoint2& direction, const SpecialAngle& angle) {
  if (angle.k == 2) return exact_coefficients(turned<exact::Quadratic<2>>(w, direction, angle));
  if (angle.k == 3) return exact_coefficients(turned<exact::Quadratic<3>>(w, direction, angle));
  return exact_coefficients(turned<ExactDecimal>(w, direction, angle));
}
// A rectangle's gap to the side decided and the direction across it, exactly (as γ above).
template <class Num>
std::array<Dd, 2> exact_gap(const Turned<Num>& e, const Decisions& d) {
  const int n = d.face->axis;
  const Num g = d.inside ? (d.face->sign > 0 ? e.s[n] - e.X[n] : e.s[n] + e.X[n])
                         : (d.face->sign > 0 ? e.X[n] - e.s[n] : -e.X[n] - e.s[n]);
  return {dd_of(g), dd_of(e.U[n])};
}
std::array<Dd, 2> exact_gap(const WrittenTurned& w, const DPoint2& direction, const SpecialAngle& angle,
                            const Decisions& d) {
  if (angle.k == 2) return exact_gap(turned<exact::Quadratic<2>>(w, direction, angle), d);
  if (angle.k == 3) return exact_gap(turned<exact::Quadratic<3>>(w, direction, angle), d);
  return exact_gap(turned<ExactDecimal>(w, direction, angle), d);
}

DdHit dd_hit(const Turned<Dd>& f, const Decisions& d, const WrittenTurned& w, const DPoint2& direction, bool ellipse,
             const SpecialAngle& angle) {
  Dd* tag = nullptr;
  // cos θ, sin θ made here: passed in as the caller's temporary, g++ 12 -O3 read them as
  // uninitialised (valgrind; a quarter turn's values) once this function grew
  const std::array<Dd, 2> rot = dd_rotation(w, angle);
  const auto &X = f.X, &U = f.U, &s = f.s;
  Dd t;
  Dd g0, g1;  // the outward normal in the figure's frame (not normalised)
  if (ellipse) {
    const Dd a2 = s[0] * s[0], b2 = s[1] * s[1];
    const Dd alpha = b2 * (U[0] * U[0]) + a2 * (U[1] * U[1]);
    const Dd beta = b2 * (X[0] * U[0]) + a2 * (X[1] * U[1]);
    Dd gamma = b2 * (X[0] * X[0]) + a2 * (X[1] * X[1]) - a2 * b2;
    Dd disc = beta * beta - alpha * gamma;
    const double gamma_terms = (b2 * (X[0] * X[0])).hi + (a2 * (X[1] * X[1])).hi + (a2 * b2).hi;
    const double disc_terms = (beta * beta).hi + std::abs((alpha * gamma).hi);
    if (angle.k != 0 && (std::abs(gamma.hi) < kCoarse * gamma_terms || std::abs(disc.hi) < kCoarse * disc_terms)) {
      const Coefficients exact = exact_coefficients(w, direction, angle);
      gamma = exact.gamma;
      disc = exact.disc;
    }
    const Dd root = dd_sqrt(disc);
    if (d.tangent) t = dd_div(-beta, alpha);  // the line tangent as written: no chord
    else if (d.inside) t = beta.hi <= 0 ? dd_div(root - beta, alpha) : dd_div(-gamma, beta + root);
    else t = dd_div(gamma, root - beta);
    const Dd P0 = X[0] + t * U[0], P1 = X[1] + t * U[1];
    g0 = b2 * P0;
    g1 = a2 * P1;
  } else {
    const int n = d.face->axis;
    Dd gap = d.inside ? (d.face->sign > 0 ? s[n] - X[n] : s[n] + X[n])
                      : (d.face->sign > 0 ? X[n] - s[n] : -X[n] - s[n]);
    Dd along = U[n];
    // A a hair from the side, or the ray nearly along it: both exactly, as γ above
    const double u_terms = std::abs(U[0].hi) + std::abs(U[1].hi);
    if (angle.k != 0 && (std::abs(gap.hi) < kCoarse * std::abs(s[n].hi) || std::abs(along.hi) < kCoarse * u_terms)) {
      const std::array<Dd, 2> exact = exact_gap(w, direction, angle, d);
      gap = exact[0];
      along = exact[1];
    }
    t = dd_div(gap, along.hi < 0 ? -along : along);
    if (t.hi < 0) t = {};
    (n == 0 ? g0 : g1) = Dd{static_cast<double>(d.face->sign), 0};
  }
  const Dd I0 = number(w.A[0], tag) + t * number(direction[0], tag);
  const Dd I1 = number(w.A[1], tag) + t * number(direction[1], tag);
  // R(θ)g = (c·g0 − s·g1, s·g0 + c·g1)
  const Dd n0 = rot[0] * g0 - rot[1] * g1, n1 = rot[1] * g0 + rot[0] * g1;
  const Dd norm = dd_sqrt(n0 * n0 + n1 * n1);
  return {Hit2{to_double(t), {to_double(I0), to_double(I1)}, {to_double(dd_div(n0, norm)), to_double(dd_div(n1, norm))}},
          t};
}

// A hit of the exact decisions `d` (the kernels', or one rebuilt from the exact numbers, whose N
// comes from the carried ray), checked against its values from the decimals in double-double
// (dd_hit, each rounded once from far below an ulp: within 0.5 of its bound plus a little): kept
// when each value is within kKeptWithin of its bound of those (the contract's bound: t and I
// against ulp(max(S, |value|)), S the figure's largest datum; N against max(ulp(1), ulp(S)/its
// smallest size)), so within 4 of the exact figure's, and the keys' bits stay; else the hit
// from the decimals. A hit at A (t = 0) is exact already.
constexpr double kKeptWithin = 3.25;
template <class Result>
Result refined(Result e, const Decisions& d, const WrittenTurned& w, const DPoint2& direction,
               const SpecialAngle& angle) {
  if (!e.hit || !(e.hit->t > 0)) return e;
  constexpr bool ellipse = std::is_same_v<Result, RayEllipse>;
  if constexpr (!ellipse)
    if (!d.face) return e;
  const Turned<Dd> frame = turned<Dd>(w, direction, angle);
  const DdHit dd = dd_hit(frame, d, w, direction, ellipse, angle);
  const Hit2& h = dd.hit;
  const double S = std::max({std::abs(w.A[0].hi), std::abs(w.A[1].hi), std::abs(w.C[0].hi), std::abs(w.C[1].hi),
                             std::abs(w.sx.hi), std::abs(w.sy.hi)});
  const double n_unit = std::max(ulp_of(1), ulp_of(S) / std::min(std::abs(w.sx.hi), std::abs(w.sy.hi)));
  auto near = [](double a, double b, double unit) { return std::abs(a - b) <= kKeptWithin * unit; };
  // t is printed times the direction's length as solve rounds it (solve::raw_direction): compared
  // as printed, against t·‖u‖ in double-double, and printed as that when replaced
  Dd* tag = nullptr;
  const double length = norm(hi_vec(direction));
  const Dd ux = number(direction[0], tag), uy = number(direction[1], tag);
  const double printed = to_double(dd.t * dd_sqrt(ux * ux + uy * uy));
  const Hit2& k = *e.hit;
  if (near(k.t * length, printed, ulp_of(std::max(S, std::abs(printed)))) &&
      near(k.I.x, h.I.x, ulp_of(std::max(S, std::abs(h.I.x)))) &&
      near(k.I.y, h.I.y, ulp_of(std::max(S, std::abs(h.I.y)))) && near(k.N.x, h.N.x, n_unit) &&
      near(k.N.y, h.N.y, n_unit))
    return e;
  e.hit = h;
  e.hit->t = printed / length;
  return e;
}

// The kernels' result where their decisions are the exact ones (their values to the bit: the keys
// do not move), else the one rebuilt from the exact decisions; also where `redo` says the
// kernels' values are not to be kept.
template <class Result, class Decide>
Result on_the_decimals(Result e, const WrittenTurned& w, const DPoint2& direction, const Ray2& ray,
                       const SpecialAngle& angle, Decide decide_on, std::string_view figure, bool redo = false) {
  const Decisions exact = decide(w, direction, angle, decide_on, figure);
  if (exact == kernel_decisions(e) && !redo) return refined(e, exact, w, direction, angle);
  return on_exact(angle.k, [&](auto* tag) {
    using Num = std::remove_pointer_t<decltype(tag)>;
    return refined(rebuilt(e, exact, turned<Num>(w, direction, angle), ray), exact, w, direction, angle);
  });
}

}  // namespace

RayEllipse intersect_written(const WrittenTurned& w, const DPoint2& direction, const Ray2& ray,
                             const Ellipse& ellipse) {
  RayEllipse e = intersect_exact(ray, ellipse);
  if (same_value(w.sx, w.sy)) {
    // a circle: ray_circle's decisions on the decimals, its hit where they differ or where the
    // chord is shorter than 2^-12 of the radius (the carried ray's rounding is magnified there)
    const RayCircle c = intersect_exact(w.A, direction, w.C, w.sx);
    const Decisions circle{c.inside, c.hit.has_value(), c.hit && !(c.hit->t > 0), std::nullopt};
    const bool near_tangent = c.half_chord && *c.half_chord <= 0x1p-12 * w.sx.hi;
    if (circle == kernel_decisions(e) && !near_tangent) {
      const auto special = special_angle(w.angle_deg);
      return refined(e, circle, w, direction, special ? *special : general_angle(w.angle_deg));
    }
    e.inside = c.inside;
    e.hit = c.hit;
    return e;
  }
  const auto special = special_angle(w.angle_deg);
  const SpecialAngle angle = special ? *special : general_angle(w.angle_deg);
  // a line within 2^-12 of tangency (its chord polynomial within 2^40 of its error bound): the
  // carried ray's rounding is magnified in the kernels' chord, so the hit is redone (from the
  // exact numbers; at another angle the kernels' values are as good as the filter's midpoints)
  const Bounded chord = ellipse_chord(turned<Bounded>(w, direction, angle));
  const bool near_tangent = angle.k != 0 && !(std::abs(chord.mid) > 0x1p40 * chord.err);
  return on_the_decimals(e, w, direction, ray, angle, [](const auto& f) { return decide_ellipse(f); }, "ellipse",
                         near_tangent);
}

RayRectangle intersect_written(const WrittenTurned& w, const DPoint2& direction, const Ray2& ray,
                               const Rectangle& rectangle) {
  RayRectangle e = intersect_exact(ray, rectangle);
  const auto special = special_angle(w.angle_deg);
  const SpecialAngle angle = special ? *special : general_angle(w.angle_deg);
  return on_the_decimals(e, w, direction, ray, angle, [](const auto& f) { return decide_rectangle(f); },
                         "rectangle");
}

}  // namespace epure::geo
