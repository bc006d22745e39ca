// Pins geometry/affine.h: Transform2 keeps its inverse; a point moves with the translation, a
// direction without it, a normal by the inverse transpose (so it stays perpendicular to the
// mapped tangents); (T ∘ S) applies S first; T ∘ T⁻¹ is the identity and T⁻¹⁻¹ is T itself;
// singular matrices and zero scales are refused. cos_sin_degrees: exact at quarter turns, the
// long double values elsewhere, cos² + sin² = 1, any angle reduced exactly, NaN for no angle.
#include "geometry/affine.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "geometry/degenerate.h"
#include "support/approx.h"
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

template <class F>
void check_refused(F&& call, const std::string& field) {
  try {
    call();
    FAIL("no exception");
  } catch (const DegenerateFigure& e) {
    CHECK(e.field() == field);
  }
}

// The linear part within `tolerance`, the translation within `shift_tolerance`.
void check_matrix(const Affine2Matrix& m, const Affine2Matrix& expected, double tolerance,
                  double shift_tolerance) {
  CHECK(m.a == T::within(expected.a, tolerance, tolerance));
  CHECK(m.b == T::within(expected.b, tolerance, tolerance));
  CHECK(m.c == T::within(expected.c, tolerance, tolerance));
  CHECK(m.d == T::within(expected.d, tolerance, tolerance));
  CHECK(m.e == T::within(expected.e, shift_tolerance, shift_tolerance));
  CHECK(m.f == T::within(expected.f, shift_tolerance, shift_tolerance));
}

// A random invertible transform: translate ∘ rotate ∘ scale (the shape of every figure's
// placement), sometimes mirrored, sometimes a general matrix.
Transform2 draw_transform(Rng& rng) {
  if (rng.chance(0.3)) {
    for (;;) {
      const Affine2Matrix m{rng.uniform(-3, 3), rng.uniform(-3, 3),     rng.uniform(-3, 3),
                            rng.uniform(-3, 3), rng.uniform(-100, 100), rng.uniform(-100, 100)};
      if (std::abs(m.a * m.d - m.b * m.c) > 0.1) return Transform2(m);
    }
  }
  const double sx = T::decades(rng, -3, 3) * T::sign(rng), sy = T::decades(rng, -3, 3);
  return Transform2::translate({rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3)}) *
         Transform2::rotate_degrees(rng.uniform(-720, 720)) * Transform2::scale(sx, sy);
}

// The size of a matrix, for tolerances: its largest entry.
double size_of(const Affine2Matrix& m) {
  return std::max({std::abs(m.a), std::abs(m.b), std::abs(m.c), std::abs(m.d)});
}

}  // namespace

TEST_SUITE_BEGIN("geometry");

TEST_CASE("geometry/affine: points, directions and normals") {
  SUBCASE("1. the identity changes nothing") {
    const Transform2 id;
    CHECK(exactly(id.apply(Point2{3, -4}).x, 3));
    CHECK(exactly(id.apply(Vec2{3, -4}).y, -4));
    CHECK(exactly(id.apply_normal(Vec2{0.6, 0.8}).x, 0.6));
    check_matrix(id.inverse_matrix(), {}, 0, 0);
  }
  SUBCASE("2. a translation moves points, not directions or normals") {
    const Transform2 t = Transform2::translate({2, -1});
    const Point2 p = t.apply(Point2{1, 1});
    CHECK(exactly(p.x, 3));
    CHECK(exactly(p.y, 0));
    CHECK(exactly(t.apply(Vec2{1, 1}).x, 1));
    CHECK(exactly(t.apply_normal(Vec2{0, 1}).y, 1));
    CHECK(exactly(t.inverse().apply(p).x, 1));
  }
  SUBCASE("3. a scale stretches directions and shrinks normals") {
    const Transform2 s = Transform2::scale(2, 0.5);
    CHECK(exactly(s.apply(Vec2{1, 1}).x, 2));
    CHECK(exactly(s.apply(Vec2{1, 1}).y, 0.5));
    // the line x + y = c maps to x/2 + 2y = c: its normal (1, 1) to (1/2, 2)
    const Vec2 n = s.apply_normal(Vec2{1, 1});
    CHECK(exactly(n.x, 0.5));
    CHECK(exactly(n.y, 2));
    CHECK(exactly(dot(n, s.apply(Vec2{1, -1})), 0));
    // a mirror is a scale too
    CHECK(exactly(Transform2::scale(-1, 1).apply(Point2{3, 4}).x, -3));
  }
  SUBCASE("4. composition applies the inner transform first") {
    const Transform2 ts = Transform2::translate({10, 0}) * Transform2::scale(2, 2);
    CHECK(exactly(ts.apply(Point2{1, 1}).x, 12));  // scaled to (2, 2), then moved
    const Transform2 st = Transform2::scale(2, 2) * Transform2::translate({10, 0});
    CHECK(exactly(st.apply(Point2{1, 1}).x, 22));  // moved to (11, 1), then scaled
    CHECK(exactly(ts.inverse().apply(Point2{12, 2}).x, 1));
  }
  SUBCASE("5. singular matrices and zero scales are refused") {
    check_refused([] { Transform2(Affine2Matrix{1, 2, 2, 4, 0, 0}); }, "transform");
    check_refused([] { Transform2(Affine2Matrix{0, 0, 0, 0, 1, 1}); }, "transform");
    // parallel columns to the last bits are singular too
    check_refused(
        [] {
          Transform2(Affine2Matrix{0.1, 0.3, 0.2, 0.6000000000000001, 0, 0});
        },
        "transform");
    check_refused([] { Transform2::scale(0, 1); }, "scale");
    check_refused([] { Transform2::scale(1, -0.0); }, "scale");
    check_refused([] { Transform2::scale(1e-320, 1); }, "scale");  // 1/s overflows
    // nearly singular but genuinely invertible: kept
    const Transform2 thin(Affine2Matrix{1, 1, 0, 1e-9, 0, 0});
    CHECK(thin.inverse_matrix().d == doctest::Approx(1e9).epsilon(4 * kEps));
  }
  SUBCASE("6. the inverse of the inverse is the transform itself, bit for bit") {
    const Transform2 t = Transform2::translate({1.5, -2}) * Transform2::rotate_degrees(33) *
                         Transform2::scale(3, 0.25);
    const Transform2 back = t.inverse().inverse();
    CHECK(exactly(back.matrix().a, t.matrix().a));
    CHECK(exactly(back.matrix().f, t.matrix().f));
    CHECK(exactly(back.inverse_matrix().b, t.inverse_matrix().b));
  }
}

TEST_CASE("geometry/affine: rotations in degrees") {
  SUBCASE("1. quarter turns are exact") {
    struct Case {
      double degrees, cos, sin;
    };
    for (Case q : {Case{0, 1, 0}, Case{90, 0, 1}, Case{180, -1, 0}, Case{270, 0, -1},
                   Case{-90, 0, -1}, Case{360, 1, 0}, Case{450, 0, 1}, Case{-270, 0, 1},
                   Case{-180, -1, 0}, Case{720, 1, 0}, Case{1e6 * 360, 1, 0}}) {
      CAPTURE(q.degrees);
      const CosSin cs = cos_sin_degrees(q.degrees);
      CHECK(cs.cos == T::within(q.cos, 0, 0));
      CHECK(cs.sin == T::within(q.sin, 0, 0));
      const Point2 p = Transform2::rotate_degrees(q.degrees).apply(Point2{3, 4});
      CHECK(p.x == T::within(3 * q.cos - 4 * q.sin, 0, 0));
      CHECK(p.y == T::within(3 * q.sin + 4 * q.cos, 0, 0));
    }
  }
  SUBCASE("2. 30°, 45°, 60° and their negatives and turns") {
    const double half_root3 = std::sqrt(3.0) / 2, half_root2 = std::sqrt(0.5);
    CHECK(cos_sin_degrees(30).cos == doctest::Approx(half_root3).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(30).sin == doctest::Approx(0.5).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(60).cos == doctest::Approx(0.5).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(-30).sin == doctest::Approx(-0.5).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(390).sin == doctest::Approx(0.5).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(-330).sin == doctest::Approx(0.5).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(45).cos == doctest::Approx(half_root2).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(45).sin == doctest::Approx(half_root2).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(135).cos == doctest::Approx(-half_root2).epsilon(2 * kEps));
    CHECK(cos_sin_degrees(1e6 + 30).sin ==
          doctest::Approx(std::sin(310 * std::numbers::pi / 180)).epsilon(4 * kEps));
  }
  SUBCASE("3. no angle, no rotation: NaN, not undefined behaviour") {
    for (double x :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()}) {
      const CosSin cs = cos_sin_degrees(x);
      CHECK(std::isnan(cs.cos));
      CHECK(std::isnan(cs.sin));
    }
  }
  SUBCASE("4. random angles: the long double values, cos² + sin² = 1") {
    for (std::uint64_t seed = 0; seed < 5000; ++seed) {
      Rng rng(seed);
      CAPTURE(seed);
      const double degrees = seed % 2 ? rng.uniform(-400, 400) : rng.uniform(-1e7, 1e7);
      const CosSin cs = cos_sin_degrees(degrees);
      const T::RealCosSin e = T::cos_sin_degrees(degrees);
      CHECK(cs.cos == T::within(d(e.cos), 0, 2 * kEps));
      CHECK(cs.sin == T::within(d(e.sin), 0, 2 * kEps));
      CHECK(cs.cos * cs.cos + cs.sin * cs.sin == doctest::Approx(1).epsilon(4 * kEps));
      // whole turns change no bit (on angles in 1/64 of a degree, so that adding them is exact)
      const double base = static_cast<double>(rng.integer(-25600, 25600)) / 64;
      const CosSin a = cos_sin_degrees(base),
                   b = cos_sin_degrees(base + 360 * static_cast<double>(rng.integer(-5, 5)));
      CHECK(exactly(a.cos, b.cos));
      CHECK(exactly(a.sin, b.sin));
    }
  }
}

TEST_CASE("geometry/affine: random transforms") {
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    Rng rng(seed, 1);
    CAPTURE(seed);
    const Transform2 t = draw_transform(rng), s = draw_transform(rng);
    const Point2 p = T::point2(rng, 100);
    const Vec2 v = T::direction2(rng);
    const Affine2Matrix& m = t.matrix();
    const double size = size_of(m), inverse_size = size_of(t.inverse_matrix());
    const double cond = size * inverse_size;

    // T ∘ T⁻¹ and T⁻¹ ∘ T are the identity, to the condition number
    const Transform2 one = t * t.inverse(), other = t.inverse() * t;
    const double shift = 8 * kEps * cond * (std::abs(m.e) + std::abs(m.f) + 1);
    check_matrix(one.matrix(), {}, 8 * kEps * cond, shift);
    check_matrix(other.matrix(), {}, 8 * kEps * cond, shift * inverse_size);

    // points go there and back
    const Point2 q = t.inverse().apply(t.apply(p));
    const double reach = 100 + (std::abs(m.e) + std::abs(m.f)) * inverse_size;
    CHECK(q.x == T::within(p.x, 0, 16 * kEps * cond * reach));
    CHECK(q.y == T::within(p.y, 0, 16 * kEps * cond * reach));

    // the matrix does what it says, checked in quadruple precision
    const Point2 tp = t.apply(p);
    const Real x = Real(m.a) * p.x + Real(m.b) * p.y + m.e,
               y = Real(m.c) * p.x + Real(m.d) * p.y + m.f;
    CHECK(tp.x == T::within(d(x), 0, 4 * kEps * (size * 200 + std::abs(m.e))));
    CHECK(tp.y == T::within(d(y), 0, 4 * kEps * (size * 200 + std::abs(m.f))));

    // composition applies s first
    const Point2 ts = (t * s).apply(p), t_of_s = t.apply(s.apply(p));
    const double extent =
        size * (size_of(s.matrix()) * 100 + std::abs(s.matrix().e) + std::abs(s.matrix().f)) +
        std::abs(m.e) + std::abs(m.f);
    CHECK(ts.x == T::within(t_of_s.x, 0, 16 * kEps * extent));
    CHECK(ts.y == T::within(t_of_s.y, 0, 16 * kEps * extent));

    // directions ignore the translation: T(p + v) − T(p) = T(v)
    const Vec2 tv = t.apply(v), diff = t.apply(p + v) - t.apply(p);
    CHECK(diff.x ==
          T::within(tv.x, 0, 16 * kEps * size * (200 + norm(v)) + 16 * kEps * std::abs(m.e)));
    CHECK(diff.y ==
          T::within(tv.y, 0, 16 * kEps * size * (200 + norm(v)) + 16 * kEps * std::abs(m.f)));

    // a normal n ⟂ v maps to (M⁻¹)ᵀn, still perpendicular to the mapped tangent M·v
    const Vec2 n = perp(v);
    const Vec2 mn = t.apply_normal(n);
    CHECK(std::abs(dot(mn, tv)) <= 16 * kEps * cond * norm(mn) * norm(tv));
    // and a general pair keeps its dot product: (M⁻ᵀn)·(Mw) = n·w
    const Vec2 w = T::direction2(rng);
    CHECK(dot(t.apply_normal(v), t.apply(w)) ==
          T::within(dot(v, w), 0, 16 * kEps * cond * norm(v) * norm(w)));
  }
}

TEST_SUITE_END();
