#pragma once
// One method, evaluated many ways (STYLE.md). A kind writes the course's method once, as a
// template over an evaluator `M`, the way a student works it by hand:
//
//   template <class M> static void method(M& m, const Data& d) {
//     const auto AC = m.in(d.C) - m.in(d.A);
//     const auto uh = m.round("u_hat", m.mistake("direction_not_unit", u / norm(u), u));
//     const auto t_proj = m.number("t_proj", m.round("t_proj", dot(uh, AC)));
//     …
//   }
//
// and each evaluator reads it its own way:
// - Run<Exact>: every step in doubles and, where the data are rational, in exact form
//   (rationals and a + b√c): the key's exact answers and its worked steps (a recorder);
// - Run<Dual>: forward-mode derivatives of each answer with respect to every intermediate the
//   student rounds (`round`): how far an answer moves when a student rounds on the way, hence
//   its tolerance;
// - Run<Traced>: the student's own values substituted for their answers (`number`, `point`,
//   `boolean`, …), each value carrying the answers it was computed from: follow-through credit
//   comes from the data flow, never from a list of names;
// - any of them with one named mistake switched on (`mistake(code, right, wrong)` takes the
//   wrong road): the values that mistake gives, for grading, feedback and platform exports.
//
// The plain double evaluation (the double half of Exact) is checked against the geometry core
// on every instance the generator issues: a method that disagrees with the core is a bug.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "support/agrees.h"
#include "exercises/exact.h"
#include "geometry/vec.h"
#include "support/portable.h"

namespace epure::method {

// Bit i: the kind's i-th declared question (kQuestions). A value's deps are the answers it was
// computed from.
using Deps = std::uint32_t;

// Sets of faces with the contract's bits: +x +y +z −x −y −z are bits 0 … 5.
using FaceMask = std::uint8_t;

// ---------------------------------------------------------------------------------------------
// Number types

// The double value and, when every datum it comes from is rational and the arithmetic stays
// within exact.h's range and a single radicand, its exact form.
struct Exact {
  double v = 0;
  std::optional<exact::Surd> e;
};

// The value and its derivatives with respect to the rounded intermediates, slot by slot.
inline constexpr int kMaxRounded = 24;
struct Dual {
  double v = 0;
  std::array<double, kMaxRounded> d{};
};

// The value and the answers it was computed from.
struct Traced {
  double v = 0;
  Deps deps = 0;
};

inline double value(double x) { return x; }
inline double value(const Exact& x) { return x.v; }
inline double value(const Dual& x) { return x.v; }
inline double value(const Traced& x) { return x.v; }
inline Deps deps_of(double) { return 0; }
inline Deps deps_of(const Exact&) { return 0; }
inline Deps deps_of(const Dual&) { return 0; }
inline Deps deps_of(const Traced& x) { return x.deps; }

namespace detail {

// Beyond this radicand (numerator × denominator under the root) an exact form is neither short
// nor cheap: Surd reduces √c by trial division. Such values are given in decimals only.
inline constexpr std::int64_t kMaxRadicand = 100'000'000;

// f's exact form, or none when exact.h's arithmetic overflows. The forms that only grow too
// large for an exact form (two radicands, a radicand past kMaxRadicand) are told apart before:
// they are frequent, and a thrown exception costs microseconds (most of all in WebAssembly).
template <class F>
std::optional<exact::Surd> attempt(F&& f) {
  try {
    return f();
  } catch (const exact::ExactOverflow&) {
  } catch (const std::domain_error&) {
  }
  return std::nullopt;
}

template <class F>
std::optional<exact::Surd> both(const Exact& x, const Exact& y, F&& f) {
  if (!x.e || !y.e) return std::nullopt;
  return attempt([&] { return f(*x.e, *y.e); });
}

inline bool pure(const exact::Surd& x) { return x.a().is_zero() && !x.b().is_zero(); }

// Whether x and y have one radicand (a rational has any): exact.h's sums and products need it.
inline bool one_radicand(const exact::Surd& x, const exact::Surd& y) {
  return x.is_rational() || y.is_rational() || x.c() == y.c();
}

inline std::optional<exact::Surd> add(const exact::Surd& x, const exact::Surd& y) {
  if (!one_radicand(x, y)) return std::nullopt;
  return x + y;
}

// x·y; two pure surds of different radicands make a pure surd: b√c·b'√c' = bb'√(cc').
inline std::optional<exact::Surd> multiply(const exact::Surd& x, const exact::Surd& y) {
  if (pure(x) && pure(y) && x.c() != y.c()) {
    if (x.c() > kMaxRadicand / y.c()) return std::nullopt;
    return exact::Surd(exact::Rational(0), x.b() * y.b(), x.c() * y.c());
  }
  if (!one_radicand(x, y)) return std::nullopt;
  return x * y;
}

// x / y for surds of one radicand: multiplied by y's conjugate, y·ȳ is rational; a pure surd
// over another: b√c / b'√c' = (b / (b'c'))·√(cc').
inline std::optional<exact::Surd> divide(const exact::Surd& x, const exact::Surd& y) {
  if (y.is_rational()) return x / y.a();
  if (pure(x) && pure(y) && x.c() != y.c()) {
    if (x.c() > kMaxRadicand / y.c()) return std::nullopt;
    return exact::Surd(exact::Rational(0), x.b() / (y.b() * exact::Rational(y.c())), x.c() * y.c());
  }
  if (!one_radicand(x, y)) return std::nullopt;
  const exact::Surd conj(y.a(), -y.b(), y.c());
  const exact::Surd den = y * conj;
  return (x * conj) / den.a();
}

}  // namespace detail

inline Exact operator+(const Exact& x, const Exact& y) {
  return {x.v + y.v, detail::both(x, y, [](const auto& a, const auto& b) { return detail::add(a, b); })};
}
inline Exact operator-(const Exact& x, const Exact& y) {
  return {x.v - y.v, detail::both(x, y, [](const auto& a, const auto& b) { return detail::add(a, -b); })};
}
inline Exact operator*(const Exact& x, const Exact& y) {
  return {x.v * y.v, detail::both(x, y, [](const auto& a, const auto& b) { return detail::multiply(a, b); })};
}
inline Exact operator/(const Exact& x, const Exact& y) {
  return {x.v / y.v, detail::both(x, y, [](const auto& a, const auto& b) { return detail::divide(a, b); })};
}
inline Exact operator-(const Exact& x) {
  std::optional<exact::Surd> e;
  if (x.e) e = -*x.e;
  return {-x.v, e};
}
inline Exact sqrt(const Exact& x) {
  std::optional<exact::Surd> e;
  if (x.e && x.e->is_rational() && x.e->a().sign() >= 0) {
    const exact::Rational r = x.e->a();
    if (r.num() <= detail::kMaxRadicand / r.den()) e = detail::attempt([&] { return exact::Surd::sqrt(r); });
  }
  return {std::sqrt(x.v), e};
}

inline Dual operator+(const Dual& x, const Dual& y) {
  Dual r{x.v + y.v};
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = x.d[i] + y.d[i];
  return r;
}
inline Dual operator-(const Dual& x, const Dual& y) {
  Dual r{x.v - y.v};
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = x.d[i] - y.d[i];
  return r;
}
inline Dual operator*(const Dual& x, const Dual& y) {
  Dual r{x.v * y.v};
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = x.d[i] * y.v + x.v * y.d[i];
  return r;
}
inline Dual operator/(const Dual& x, const Dual& y) {
  Dual r{x.v / y.v};
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = (x.d[i] * y.v - x.v * y.d[i]) / (y.v * y.v);
  return r;
}
inline Dual operator-(const Dual& x) {
  Dual r{-x.v};
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = -x.d[i];
  return r;
}
inline Dual sqrt(const Dual& x) {
  Dual r{std::sqrt(x.v)};
  // d√x = dx / (2√x); at 0 the method has left the well-posed region (the generator keeps away)
  const double k = r.v > 0 ? 0.5 / r.v : 0.0;
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = x.d[i] * k;
  return r;
}

inline Traced operator+(Traced x, Traced y) { return {x.v + y.v, x.deps | y.deps}; }
inline Traced operator-(Traced x, Traced y) { return {x.v - y.v, x.deps | y.deps}; }
inline Traced operator*(Traced x, Traced y) { return {x.v * y.v, x.deps | y.deps}; }
inline Traced operator/(Traced x, Traced y) { return {x.v / y.v, x.deps | y.deps}; }
inline Traced operator-(Traced x) { return {-x.v, x.deps}; }
inline Traced sqrt(Traced x) { return {std::sqrt(x.v), x.deps}; }

inline double sqrt(double x) { return std::sqrt(x); }

// The angle of (c, s) in degrees, in (−180, 180]. Exact where the angle is a multiple of 45°
// (the only ones a hand computation gives in whole degrees); correctly rounded, as the core's
// angle (portable.h): the same bits natively and in the explorer's WebAssembly.
inline double atan2_degrees(double s, double c) { return portable::atan2(s, c) * (180.0 / std::numbers::pi); }
// Grading runs the method once per named mistake on one student's answers, mostly with the same
// sine and cosine (a mistake elsewhere): the correctly rounded atan2 is the run's dearest step,
// so the last pair's angle is kept, per thread.
inline Traced atan2_degrees(Traced s, Traced c) {
  thread_local bool have = false;
  thread_local std::uint64_t last_s = 0, last_c = 0;
  thread_local double last = 0;
  const auto bs = portable::bit_cast<std::uint64_t>(s.v), bc = portable::bit_cast<std::uint64_t>(c.v);
  if (!have || bs != last_s || bc != last_c) last = atan2_degrees(s.v, c.v), last_s = bs, last_c = bc, have = true;
  return {last, s.deps | c.deps};
}
inline Dual atan2_degrees(const Dual& s, const Dual& c) {
  Dual r{atan2_degrees(s.v, c.v)};
  const double k = (180.0 / std::numbers::pi) / (s.v * s.v + c.v * c.v);
  for (int i = 0; i < kMaxRounded; ++i) r.d[i] = k * (c.v * s.d[i] - s.v * c.d[i]);
  return r;
}
namespace detail {
inline bool is_zero(const exact::Surd& x) { return x.a().is_zero() && x.b().is_zero(); }
inline bool same(const exact::Surd& x, const exact::Surd& y) {
  return x.a() == y.a() && x.b() == y.b() && (x.b().is_zero() || x.c() == y.c());
}
}  // namespace detail
inline Exact atan2_degrees(const Exact& s, const Exact& c) {
  Exact r{atan2_degrees(s.v, c.v), std::nullopt};
  if (!s.e || !c.e) return r;
  const int ss = (s.v > 0) - (s.v < 0), cs = (c.v > 0) - (c.v < 0);
  auto whole = [](int deg) { return exact::Surd(exact::Rational(deg)); };
  if (detail::is_zero(*s.e) && !detail::is_zero(*c.e)) r.e = whole(cs > 0 ? 0 : 180);
  else if (detail::is_zero(*c.e) && !detail::is_zero(*s.e)) r.e = whole(90 * ss);
  else if (detail::same(*s.e, *c.e) || detail::same(*s.e, -*c.e)) r.e = whole((cs > 0 ? 45 : 135) * ss);
  return r;
}

// `x`, read from what `from` was read from: a value the method decides from an answer without
// computing it from that answer's number (the side I lies on gives N = ±e_k) still depends on
// it, for follow-through. The value and its exact form are x's; no derivative is added.
inline double depends_on(double, double x) { return x; }
inline Exact depends_on(const Exact&, const Exact& x) { return x; }
inline Dual depends_on(const Dual&, const Dual& x) { return x; }
inline Traced depends_on(const Traced& from, Traced x) { return {x.v, x.deps | from.deps}; }

// |x|, on the value's sign.
template <class T>
T magnitude(const T& x) {
  return value(x) < 0 ? -x : x;
}

// ---------------------------------------------------------------------------------------------
// Vectors over any number type

template <class T>
struct V2 {
  T x, y;
};
template <class T> V2<T> operator+(const V2<T>& a, const V2<T>& b) { return {a.x + b.x, a.y + b.y}; }
template <class T> V2<T> operator-(const V2<T>& a, const V2<T>& b) { return {a.x - b.x, a.y - b.y}; }
template <class T> V2<T> operator-(const V2<T>& a) { return {-a.x, -a.y}; }
template <class T> V2<T> operator*(const T& k, const V2<T>& a) { return {k * a.x, k * a.y}; }
template <class T> V2<T> operator/(const V2<T>& a, const T& k) { return {a.x / k, a.y / k}; }
template <class T> T dot(const V2<T>& a, const V2<T>& b) { return a.x * b.x + a.y * b.y; }
template <class T> T cross(const V2<T>& a, const V2<T>& b) { return a.x * b.y - a.y * b.x; }
template <class T> T norm2(const V2<T>& a) { return dot(a, a); }
template <class T> T norm(const V2<T>& a) { return sqrt(dot(a, a)); }
template <class T> geo::Point2 value(const V2<T>& a) { return {value(a.x), value(a.y)}; }

// In space (the course's "dimension 3"): the same operations, and the 3D cross product.
template <class T>
struct V3 {
  T x, y, z;
};
template <class T> V3<T> operator+(const V3<T>& a, const V3<T>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> V3<T> operator-(const V3<T>& a, const V3<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> V3<T> operator-(const V3<T>& a) { return {-a.x, -a.y, -a.z}; }
template <class T> V3<T> operator*(const T& k, const V3<T>& a) { return {k * a.x, k * a.y, k * a.z}; }
template <class T> V3<T> operator/(const V3<T>& a, const T& k) { return {a.x / k, a.y / k, a.z / k}; }
template <class T> T dot(const V3<T>& a, const V3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> T norm2(const V3<T>& a) { return dot(a, a); }
template <class T> T norm(const V3<T>& a) { return sqrt(dot(a, a)); }
template <class T> geo::Point3 value(const V3<T>& a) { return {value(a.x), value(a.y), value(a.z)}; }

// The names of a 3D point's coordinates, as answers or steps ("I.x", "I.y", "I.z"): a point in
// space is asked as three numbers. Static storage: recorded steps keep views of them.
using Names3 = std::array<std::string_view, 3>;

// ---------------------------------------------------------------------------------------------
// Decisions, words and face sets, with the answers they were read from

struct Cond {
  bool v = false;
  Deps deps = 0;
  explicit operator bool() const { return v; }
};
inline Cond operator!(Cond a) { return {!a.v, a.deps}; }
inline Cond operator&&(Cond a, Cond b) { return {a.v && b.v, a.deps | b.deps}; }
inline Cond operator||(Cond a, Cond b) { return {a.v || b.v, a.deps | b.deps}; }

template <class T> Cond less(const T& a, const T& b) { return {value(a) < value(b), deps_of(a) | deps_of(b)}; }
template <class T> Cond less_equal(const T& a, const T& b) { return {value(a) <= value(b), deps_of(a) | deps_of(b)}; }

namespace detail {
// The sign of a − b from their exact forms, when both have one and exact.h's arithmetic holds:
// a + b√c is signed exactly (a and b√c of opposite signs: compare a² with b²c).
inline std::optional<int> exact_sign_of_difference(const Exact& x, const Exact& y) {
  if (!x.e || !y.e || !one_radicand(*x.e, *y.e)) return std::nullopt;
  try {
    const exact::Surd d = *x.e - *y.e;
    const int sa = d.a().sign(), sb = d.b().sign();
    if (sb == 0 || sa == 0 || sa == sb) return sa != 0 ? sa : sb;
    const exact::Rational a2 = d.a() * d.a(), b2c = d.b() * d.b() * exact::Rational(d.c());
    if (a2 == b2c) return 0;
    return b2c < a2 ? sa : sb;
  } catch (const exact::ExactOverflow&) {
  } catch (const std::domain_error&) {
  }
  return std::nullopt;
}
}  // namespace detail

// a < b, decided on the exact forms under the exact evaluator (the key's run) wherever both
// sides have one: for a boundary the course draws closed, where data carried into another frame
// land exactly on it (A_c·n = 1 while the doubles say 0.9999999999999999), as the geometry core
// decides them. The other evaluators compare values, as less does.
template <class T>
Cond exactly_less(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, Exact>) {
    if (auto s = detail::exact_sign_of_difference(a, b)) return {*s < 0, 0};
  }
  return less(a, b);
}

struct Word {
  std::string_view w;  // a contract word, static storage
  Deps deps = 0;
};
// `yes` when c holds, else `no`, read from what c was read from.
inline Word pick(Cond c, std::string_view yes, std::string_view no) { return {c.v ? yes : no, c.deps}; }

struct Faces {
  FaceMask bits = 0;
  Deps deps = 0;
};

// ---------------------------------------------------------------------------------------------
// What a method declares and what a run records

enum class AnswerType : std::uint8_t { number, point, boolean, choice, faces };

// The work a question asks, its default weight in the sheet's points (exercises/points.h): a
// number computed by a chain of steps, or a point in the plane (its two coordinates share it),
// is worth four times a tick (a yes/no, a choice, a set of faces), which can mostly be read off
// the printed figure. A coordinate of a point in space, asked alone, is one multiply-add
// (I.x = A.x + t·u.x): half a computed number. Calibrated so that ticks stay under 15 % of every
// sheet's points (tests/exercises/sheet_points_test.cpp measures it).
inline constexpr double kComputedWork = 2;
inline constexpr double kCoordinateWork = 1;
inline constexpr double kTickWork = 0.5;
constexpr double work_of(AnswerType type) {
  return type == AnswerType::number || type == AnswerType::point ? kComputedWork : kTickWork;
}

// One question a kind can ask: its field (a point's group: "I" for I.x and I.y), its type, its
// work (by default its type's: work_of), and for a choice the contract words offered.
struct QuestionDecl {
  std::string_view field;
  AnswerType type;
  double weight = work_of(type);
  std::span<const std::string_view> choices = {};
};

// What the student answered, readable answers only (grading's view of a row).
class GivenAnswers {
 public:
  virtual ~GivenAnswers() = default;
  virtual std::optional<double> number(std::string_view field) const = 0;  // "t", "I.x"
  virtual std::optional<bool> boolean(std::string_view field) const = 0;
  virtual std::optional<std::string_view> word(std::string_view field) const = 0;
  virtual std::optional<FaceMask> faces(std::string_view field) const = 0;
};

// An answer (or a worked step) as a run records it.
template <class Num>
struct Recorded {
  Recorded(std::string_view id_, AnswerType type_, Num x_ = {}, Num y_ = {}) : id(id_), type(type_), x(x_), y(y_) {}
  std::string_view id;  // the field, or the step's name
  // A coordinate of a point in space (asked as three numbers, "I.x", "I.y", "I.z"): its point,
  // "I", of which it is one part (a slip that moves the point is one mistake, not three).
  std::string_view group;
  AnswerType type = AnswerType::number;
  Num x{}, y{};          // number: x; point: x and y
  bool boolean = false;
  std::string_view word;
  FaceMask faces = 0;
  Deps deps = 0;         // for a decision, word or face set
};

// "I" and 'x' → "I.x" without an allocation.
struct CoordinateName {
  char text[24];
  std::size_t size;
  operator std::string_view() const { return {text, size}; }
};
inline CoordinateName coordinate_name(std::string_view group, char axis) {
  CoordinateName c{};
  const std::size_t n = std::min(group.size(), sizeof c.text - 2);
  std::copy_n(group.data(), n, c.text);
  c.text[n] = '.';
  c.text[n + 1] = axis;
  c.size = n + 2;
  return c;
}

// ---------------------------------------------------------------------------------------------
// The key's narrative, recorded by the method as it runs (the key replays it: nothing walks the
// branches a second time)

// How a worked step shows a recorded value.
enum class Shown : std::uint8_t {
  value,   // a number: its exact form when short, with its decimal value (kind_support's step_value)
  equals,  // a number after its formula: "= 1/4 = 0.25", "≈ 2.17" (equals_value)
  point,   // a point or vector, each coordinate as `value` (step_point; in space three coordinates)
  shown,   // a point or vector, each coordinate exact when short, else rounded (shown_point)
  data,    // a point or vector of the data's own numbers, as the statement writes them
  datum,   // a number of the data, as the statement writes it
  face,    // the face or side named by `id` ("-x"), as printed ("−x")
  faces,   // the face set recorded under `id`, as printed ("+x, −y")
  text,    // `id` itself ("x")
};

// One value a worked step shows: the template's variable, the step or answer it was recorded
// under (a point in space: the group, "u_hat" for u_hat.x, u_hat.y, u_hat.z), and how.
struct Shows {
  std::string_view var;
  std::string_view id;
  Shown how = Shown::value;
};

// One worked step: the kind's text `step.<text>` and the values it shows.
struct Told {
  std::string_view text;
  std::vector<Shows> shows;
};

// True when x is written exactly with `decimals` decimals: a student's rounding leaves it as is.
inline bool on_decimal_grid(double x, int decimals) {
  const double scaled = x * std::pow(10.0, decimals);
  return is_whole(scaled);
}

// What the sheet tells a student: write each answer rounded to `decimals` decimals, but carry on
// with every value (answers and intermediate results alike) to kCarriedDigits significant
// digits. Two decimals alone would not do: û ≈ (0,12 ; 0,99) is 4 % off in its first
// coordinate, and a long chain (the ellipse's normal) then lands anywhere within 70 % of the
// value; four significant digits keep every carried value within 0,05 %.
inline constexpr int kCarriedDigits = 4;

// Half a unit in the last of `decimals` decimals: how far writing an answer rounded moves it.
inline double written_half_step(int decimals) { return 0.5 * std::pow(10.0, -decimals); }

// The power of ten of x's first significant digit (x finite, not 0): floor(log10 |x|), mended
// where log10 rounds across a power of ten (0,001 must give −3, 999,9999999 must give 2).
inline int decimal_exponent(double x) {
  const double a = std::abs(x);
  int e = static_cast<int>(std::floor(std::log10(a)));
  if (std::pow(10.0, e) > a) --e;
  else if (std::pow(10.0, e + 1) <= a) ++e;
  return e;
}

// Half a unit in the last place of x carried to kCarriedDigits significant digits: how far a
// student's rounding moves it (0 for x = 0, which is written as it is).
inline double carried_half_step(double x) {
  if (x == 0 || !std::isfinite(x)) return 0;
  return 0.5 * std::pow(10.0, decimal_exponent(x) - (kCarriedDigits - 1));
}

// x as a student carries it: rounded half away from zero to kCarriedDigits significant digits.
// The step 10^k is taken as a power of ten by division when negative, so that 0,1234 stays
// 1234/10000 rather than 1234·0,0001 (one rounding less).
inline double carried(double x) {
  if (x == 0 || !std::isfinite(x)) return x;
  const int k = decimal_exponent(x) - (kCarriedDigits - 1);
  if (k >= 0) {
    const double step = std::pow(10.0, k);
    return std::round(x / step) * step;
  }
  const double scale = std::pow(10.0, -k);
  return std::round(x * scale) / scale;
}

// How many decimals show x carried as the sheet says: kCarriedDigits significant digits, and
// never fewer decimals than the answers are written with (123,46, not 123,5). The key's worked
// steps show their values so, that a student can follow them as told.
inline int carried_decimals(double x, int decimals) {
  if (x == 0 || !std::isfinite(x)) return decimals;
  return std::clamp(kCarriedDigits - 1 - decimal_exponent(x), decimals, 12);
}

// What one run of a method switches on: a named mistake, another right road (Run::road), both
// (the mistake made on that road: û left unnormalised, then d² by the cross product), or
// neither.
struct Switches {
  Switches() = default;
  Switches(std::string_view mistake_, std::string_view road_ = {}) : mistake(mistake_), road(road_) {}
  Switches(const char* mistake_) : mistake(mistake_) {}
  std::string_view mistake, road;
};

struct RunOptions {
  RunOptions(std::span<const QuestionDecl> questions_, int decimals_, Switches switches = {},
             const GivenAnswers* given_ = nullptr)
      : questions(questions_), decimals(decimals_), mistake(switches.mistake), road(switches.road), given(given_) {}
  std::span<const QuestionDecl> questions;  // the kind's declared questions (for deps bits)
  int decimals = 2;                          // what the student rounds answers to
  std::string_view mistake;                  // the named mistake switched on, or none
  std::string_view road;                     // the other right road taken, or the usual one
  const GivenAnswers* given = nullptr;       // the student's answers (Traced)
  // Traced: each rounded step carried as the sheet says (`carried`), as a student computes;
  // what the tolerances must accept (tests/exercises/tolerance_property_test.cpp)
  bool carry_rounded = false;
};

// One evaluation of a method. Answers and steps are recorded in the order the method meets them.
template <class Num>
class Run {
 public:
  using Number = Num;
  using Vec = V2<Num>;

  explicit Run(RunOptions options) : o_(options) {}

  // ---- data
  Num in(double x) const {
    if constexpr (std::is_same_v<Num, Exact>) {
      return {x, rational(x)};
    } else {
      return Num{x};
    }
  }
  Vec in(geo::Point2 p) const { return {in(p.x), in(p.y)}; }
  Vec in(geo::Vec2 v) const { return {in(v.x), in(v.y)}; }
  V3<Num> in(geo::Point3 p) const { return {in(p.x), in(p.y), in(p.z)}; }
  V3<Num> in(geo::Vec3 v) const { return {in(v.x), in(v.y), in(v.z)}; }

  // ---- steps: an intermediate the student writes down rounded (the tolerances follow its
  // rounding), or one the key shows as it is
  Num round(std::string_view id, Num x) {
    x = rounded(x, bit(id) != 0);
    note(id, x);
    return x;
  }
  Vec round(std::string_view id, Vec p) {
    const bool written = bit(id) != 0;
    p = {rounded(p.x, written), rounded(p.y, written)};
    note(id, p);
    return p;
  }
  V3<Num> round(const Names3& ids, V3<Num> p) { return {round(ids[0], p.x), round(ids[1], p.y), round(ids[2], p.z)}; }
  V3<Num> note(const Names3& ids, V3<Num> p) { return {note(ids[0], p.x), note(ids[1], p.y), note(ids[2], p.z)}; }
  Num note(std::string_view id, Num x) {
    steps_.push_back(Recorded<Num>(id, AnswerType::number, x));
    return x;
  }
  Faces note(std::string_view id, Faces f) {
    Recorded<Num> r(id, AnswerType::faces);
    r.faces = f.bits;
    r.deps = f.deps;
    steps_.push_back(r);
    return f;
  }
  Vec note(std::string_view id, Vec p) {
    steps_.push_back(Recorded<Num>(id, AnswerType::point, p.x, p.y));
    return p;
  }

  // ---- answers: recorded; under Traced the student's own answer (when readable) is what the
  // method goes on with, tagged as coming from that answer
  Num number(std::string_view field, Num x) {
    answers_.push_back(Recorded<Num>(field, AnswerType::number, x));
    if constexpr (std::is_same_v<Num, Traced>) {
      if (o_.given)
        if (auto g = o_.given->number(field)) return {*g, bit(field)};
    }
    return x;
  }
  Vec point(std::string_view field, Vec p) {
    answers_.push_back(Recorded<Num>(field, AnswerType::point, p.x, p.y));
    if constexpr (std::is_same_v<Num, Traced>) {
      if (o_.given) {
        const auto gx = o_.given->number(coordinate_name(field, 'x'));
        const auto gy = o_.given->number(coordinate_name(field, 'y'));
        if (gx && gy) return {{*gx, bit(field)}, {*gy, bit(field)}};
      }
    }
    return p;
  }
  // a point in space: three numeric answers
  V3<Num> point(const Names3& fields, V3<Num> p) {
    const V3<Num> given{number(fields[0], p.x), number(fields[1], p.y), number(fields[2], p.z)};
    const std::string_view group = fields[0].substr(0, fields[0].rfind('.'));
    for (std::size_t k = answers_.size() - 3; k < answers_.size(); ++k) answers_[k].group = group;
    return given;
  }
  Cond boolean(std::string_view field, Cond c) {
    Recorded<Num> r(field, AnswerType::boolean);
    r.boolean = c.v;
    r.deps = c.deps;
    answers_.push_back(r);
    if (o_.given)
      if (auto g = o_.given->boolean(field)) return {*g, bit(field)};
    return c;
  }
  Word choice(std::string_view field, Word w) {
    Recorded<Num> r(field, AnswerType::choice);
    r.word = w.w;
    r.deps = w.deps;
    answers_.push_back(r);
    if (o_.given)
      if (auto g = o_.given->word(field)) return {*g, bit(field)};
    return w;
  }
  Faces faces(std::string_view field, Faces f) {
    Recorded<Num> r(field, AnswerType::faces);
    r.faces = f.bits;
    r.deps = f.deps;
    answers_.push_back(r);
    if (o_.given)
      if (auto g = o_.given->faces(field)) return {*g, bit(field)};
    return f;
  }

  // ---- another right road to the same answer (d² = CP² or AC² − t_proj²): taken only when
  // switched on by its name, so that grading credits a student who took it from their own
  // earlier answers. Not a mistake: the key shows the first road.
  template <class T>
  T road(std::string_view name, T usual, T other) {
    return name == o_.road ? other : usual;
  }

  // ---- named mistakes: the wrong road, taken only when that mistake is switched on
  template <class T>
  T mistake(std::string_view code, T right, T wrong) {
    if (std::find(codes_.begin(), codes_.end(), code) == codes_.end()) codes_.push_back(code);
    return code == o_.mistake ? wrong : right;
  }

  // ---- the same value by another road, for its exact form only: `road` is the student's
  // computation (what every evaluator goes on with), `exact_road` an equal expression whose
  // exact form stays within one radicand where the student's does not (I = P ± √(h²/u·u)·u
  // rather than A + (t_proj ± h)·û). Under Exact, the two must agree.
  Num either(Num road, Num exact_road) {
    if constexpr (std::is_same_v<Num, Exact>) {
      if (!agrees(exact_road.v, road.v))
        throw std::logic_error("method: two roads to one value disagree");
      if (!road.e) road.e = exact_road.e;
    }
    return road;
  }
  Vec either(Vec road, Vec exact_road) { return {either(road.x, exact_road.x), either(road.y, exact_road.y)}; }
  V3<Num> either(V3<Num> road, V3<Num> exact_road) {
    return {either(road.x, exact_road.x), either(road.y, exact_road.y), either(road.z, exact_road.z)};
  }

  // ---- the key's narrative: a worked step, recorded by the exact run (the key's) as the method
  // reaches it; the other evaluators pass
  void tell(std::string_view text, std::initializer_list<Shows> shows = {}) {
    if constexpr (std::is_same_v<Num, Exact>) told_.push_back({text, std::vector<Shows>(shows)});
  }

  // ---- what was recorded
  const std::vector<Told>& told() const { return told_; }
  const std::vector<Recorded<Num>>& answers() const { return answers_; }
  const std::vector<Recorded<Num>>& steps() const { return steps_; }
  // The mistakes the method met on this road.
  const std::vector<std::string_view>& mistakes_met() const { return codes_; }
  int rounded_count() const { return next_slot_; }
  // How far the student's rounding of slot k moves it (Dual).
  double slot_half_step(int k) const { return slot_half_step_.at(static_cast<std::size_t>(k)); }
  // Whether slot k is also an answer the student writes (to `decimals` decimals).
  bool slot_written(int k) const { return slot_written_.at(static_cast<std::size_t>(k)); }
  const RunOptions& options() const { return o_; }

  const Recorded<Num>* answer(std::string_view field) const { return find(answers_, field); }
  const Recorded<Num>* step(std::string_view id) const {
    if (const auto* s = find(steps_, id)) return s;
    return find(answers_, id);
  }

 private:
  static const Recorded<Num>* find(const std::vector<Recorded<Num>>& v, std::string_view id) {
    for (const auto& r : v)
      if (r.id == id) return &r;
    return nullptr;
  }
  Deps bit(std::string_view field) const {
    for (std::size_t i = 0; i < o_.questions.size(); ++i)
      if (o_.questions[i].field == field) return Deps(1u << i);
    return 0;
  }
  static std::optional<exact::Surd> rational(double x);
  // A step as the student carries it: under Dual a new slot (its derivative, how far its
  // rounding moves it, and whether it is also an answer the student writes), under Traced with
  // carry_rounded the carried value itself.
  Num rounded(Num x, bool written) {
    if constexpr (std::is_same_v<Num, Dual>) {
      // a value already on the decimal grid is written as it is: rounding does not move it
      if (on_decimal_grid(x.v, o_.decimals)) return x;
      if (next_slot_ >= kMaxRounded) throw std::logic_error("method: too many rounded intermediates");
      slot_half_step_[static_cast<std::size_t>(next_slot_)] = carried_half_step(x.v);
      slot_written_[static_cast<std::size_t>(next_slot_)] = written;
      x.d[next_slot_++] += 1;
    } else if constexpr (std::is_same_v<Num, Traced>) {
      if (o_.carry_rounded && !on_decimal_grid(x.v, o_.decimals)) x.v = carried(x.v);
    }
    return x;
  }

  RunOptions o_;
  std::vector<Recorded<Num>> answers_, steps_;
  std::vector<Told> told_;
  std::vector<std::string_view> codes_;
  int next_slot_ = 0;
  std::array<double, kMaxRounded> slot_half_step_{};
  std::array<bool, kMaxRounded> slot_written_{};
};

// The exact rational a datum denotes, when it has at most 6 decimals (data on a grid always do).
std::optional<exact::Rational> rational_of(double x);

template <class Num>
std::optional<exact::Surd> Run<Num>::rational(double x) {
  if (auto r = rational_of(x)) return exact::Surd(*r);
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------

// Each numeric answer coordinate's value, in the order of answers() (a point gives x then y).
inline std::vector<double> coordinate_values(const Run<Dual>& run) {
  std::vector<double> out;
  for (const auto& a : run.answers()) {
    if (a.type == AnswerType::number) out.push_back(a.x.v);
    if (a.type == AnswerType::point) out.insert(out.end(), {a.x.v, a.y.v});
  }
  return out;
}

// The part of each tolerance the carried steps make: 1.5·Σ_k |∂a/∂q_k|·δ_k, per coordinate in
// the order of coordinate_values.
inline std::vector<double> carried_errors(const Run<Dual>& run, bool as_written) {
  const double delta = written_half_step(run.options().decimals);
  std::vector<double> out;
  auto one = [&](const Dual& x) {
    double sum = 0;
    for (int k = 0; k < run.rounded_count(); ++k) {
      const double step = as_written && run.slot_written(k) ? std::max(delta, run.slot_half_step(k)) : run.slot_half_step(k);
      sum += std::abs(x.d[k]) * step;
    }
    out.push_back(1.5 * sum);
  };
  for (const auto& a : run.answers()) {
    if (a.type == AnswerType::number) one(a.x);
    if (a.type == AnswerType::point) {
      one(a.x);
      one(a.y);
    }
  }
  return out;
}

// Tolerances from a Dual run: for each numeric answer coordinate, in the order of answers(),
// δ + 1.5·Σ_k |∂a/∂q_k|·δ_k, with δ = ½·10^−decimals the answer's own rounding as written and
// δ_k how far carrying q_k to kCarriedDigits significant digits moves it. The factor 1.5 covers
// the second-order terms the derivatives leave out and a student who rounds a step twice; it is
// not applied to δ (only a relative 10⁻⁹, so that 0,13 for 0,125 is not lost to binary
// rounding), so that an answer of 0,1 written to two decimals keeps its 5 %.
//
// With `as_written`, the steps that are answers count at their written rounding δ instead: the
// tolerance of follow-through, where grading goes on from the answers as the student wrote them
// while the student went on with more digits.
inline std::vector<double> tolerances(const Run<Dual>& run, bool as_written = false) {
  const double delta = written_half_step(run.options().decimals);
  std::vector<double> out = carried_errors(run, as_written);
  for (double& t : out) t += delta * (1 + 1e-9);
  return out;
}

// Whether the steps a student carries move no answer of |v| ≥ 0.1 by more than kMaxCarriedShare
// of it (beyond the answer's own rounding, which at 0.1 is itself 5 %). A figure where they do is
// ill-conditioned (a ray nearly tangent, a normal from a nearly flat ellipse): its tolerance
// would not tell a right answer from a slip, so the draws reject it.
inline constexpr double kMaxCarriedShare = 0.05;
inline bool carried_within(const Run<Dual>& run) {
  const std::vector<double> values = coordinate_values(run), carried = carried_errors(run, false);
  for (std::size_t k = 0; k < values.size(); ++k)
    if (std::abs(values[k]) >= 0.1 && carried[k] > kMaxCarriedShare * std::abs(values[k])) return false;
  return true;
}

}  // namespace epure::method
