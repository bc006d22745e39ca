// The ray_ellipse kind: instances per difficulty and branch, their constraints, questions, exact
// forms, tolerances and texts; and literal cases of the frame change worked by hand.
#include <doctest/doctest.h>

#include "exercises/transformed_checks.h"

namespace {

using epure::kinds::transformed::Data;
using epure::kinds::transformed::Limits;
namespace tf = epure::kinds::transformed;
namespace geo = epure::geo;

geo::Ellipse ellipse_of(const Data& d) { return {d.C, d.sx, d.sy, d.angle_deg}; }

// The kind's method on the data, unrounded: {Ac.x, Ac.y, uc.x, uc.y} and with a hit {t, I.x,
// I.y, N.x, N.y}.
std::vector<double> hand(const Data& d) {
  return epure::test::hand_answers(epure::test::instance_of("ray_ellipse", d));
}

// The key's solution of the data, at the standard level in English.
epure::kinds::KeySolution key_of(const Data& d) {
  // the context (and the spec it names) outlive every call: a key's questions keep a view of it
  static const auto spec = epure::test::spec_for("ray_ellipse", epure::Difficulty::standard);
  static const auto ctx = epure::test::context_for(spec, "en", "hit");
  return tf::ellipse_key(d, ctx);
}
std::string machine(const std::optional<epure::exact::Surd>& e) {
  REQUIRE(e.has_value());
  return e->machine();
}

// The clearances, checked with the quadratic formula rather than the course's method: a clear
// hit's line passes within 1 − margin of O, a clear miss's half-line stays out of the circle of
// radius 1 + margin.
void check_clear(const Data& d, const std::string& branch, const Limits& lim) {
  const auto r = geo::intersect(tf::world_ray(d), ellipse_of(d));
  const geo::Vec2 Ac = geo::to_vec(r.canonical_ray.origin);
  const geo::Vec2 uc = r.canonical_ray.direction;
  const double from_centre = geo::norm(Ac);
  if (branch == "inside")
    CHECK(from_centre <= 1 - lim.margin + 1e-12);
  else
    CHECK(from_centre >= 1 + lim.margin - 1e-12);
  // |Ac + t·uc|² = ρ²  <=>  (uc·uc)t² + 2(Ac·uc)t + Ac·Ac − ρ² = 0
  auto roots = [&](double rho) -> std::optional<std::pair<double, double>> {
    const double a = geo::dot(uc, uc), b = geo::dot(Ac, uc), c = geo::dot(Ac, Ac) - rho * rho;
    const double disc = b * b - a * c;
    if (disc < 0) return std::nullopt;
    return std::pair{(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a};
  };
  if (branch == "hit") {
    const auto inner = roots(1 - lim.margin);
    REQUIRE(inner.has_value());
    CHECK(inner->first > 0);
  }
  if (branch == "miss") {
    const auto outer = roots(1 + lim.margin - 1e-9);
    if (outer) CHECK(outer->second < 0);
  }
}

}  // namespace

TEST_CASE("ray_ellipse: every difficulty and branch, over many seeds") {
  const epure::test::KindCheck check{(*epure::find_kind("ray_ellipse")), tf::Shape::ellipse, check_clear};
  epure::test::check_kind(check, 300, ellipse_of);
}

TEST_CASE("ray_ellipse: the kind's name, branches, constraints and fields") {
  const auto& kind = (*epure::find_kind("ray_ellipse"));
  CHECK(kind.name() == "ray_ellipse");
  CHECK(epure::find_kind("ray_ellipse") == &kind);
  CHECK(kind.default_branches().size() == 3);
  CHECK(kind.default_constraints().count("margin") == 1);
  CHECK(kind.fields() == std::vector<std::string>{"Ac", "uc", "inside", "hit", "t", "I", "N"});
}

TEST_CASE("ray_ellipse: an unmeetable constraint is refused by name") {
  const auto& kind = (*epure::find_kind("ray_ellipse"));
  auto spec = epure::test::spec_for("ray_ellipse", epure::Difficulty::easy);
  spec.constraints["max_aspect"] = 1.1;  // below min_aspect: no ellipse qualifies
  epure::Rng rng(1);
  CHECK_THROWS_WITH_AS(kind.make(rng, epure::test::context_for(spec, "en", "hit")),
                       doctest::Contains("ray_ellipse"), std::runtime_error);
}

TEST_CASE("ray_ellipse: the frame change worked by hand") {
  SUBCASE("1. angle 0: the ray along the a-axis meets the vertex") {
    // C(5, 4), a = 2, b = 1; A(0, 4), u = (1, 0): A_c = (−5/2, 0), u_c = (1/2, 0), t = 3
    const Data d{{0, 4}, {1, 0}, {5, 4}, 2, 1, 0};
    const auto answers = hand(d);
    const std::vector<double> want{-2.5, 0, 0.5, 0, 3, 3, 4, -1, 0};
    REQUIRE(answers.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) CHECK(answers[i] == doctest::Approx(want[i]).epsilon(1e-12).scale(1));
    const auto key = key_of(d);
    CHECK(machine(key.exact_x("Ac")) == "-5/2");
    CHECK(machine(key.exact_x("uc")) == "1/2");
  }
  SUBCASE("2. angle 90: the a-axis is vertical") {
    // C(5, 5), a = 2, b = 1, θ = 90°; A(5, 0), u = (0, 1): rotated by −90°, A − C = (0, −5)
    // becomes (−5, 0), so A_c = (−5/2, 0) and u_c = (1/2, 0); the hit is the vertex (5, 3)
    const Data d{{5, 0}, {0, 1}, {5, 5}, 2, 1, 90};
    const auto r = geo::intersect(tf::world_ray(d), ellipse_of(d));
    REQUIRE(r.hit.has_value());
    CHECK(r.hit->t == doctest::Approx(3).epsilon(1e-12));
    const auto answers = hand(d);
    const std::vector<double> want{-2.5, 0, 0.5, 0, 3, 5, 3, 0, -1};
    REQUIRE(answers.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) CHECK(answers[i] == doctest::Approx(want[i]).epsilon(1e-12).scale(1));
  }
  SUBCASE("3. angle 45: exact surds") {
    // C(5, 5), a = 2, b = 1, θ = 45°; A(1, 1), u = (1, 1): û = (√2/2, √2/2), A_c = (−2√2, 0),
    // u_c = (1/2, 0); t = (−1 + 2√2)/(1/2) = 4√2 − 2, I = (5 − √2, 5 − √2), N = −(√2/2, √2/2)
    const Data d{{1, 1}, {1, 1}, {5, 5}, 2, 1, 45};
    const auto key = key_of(d);
    CHECK(machine(key.exact_x("u_hat")) == "sqrt(2)/2");
    CHECK(machine(key.exact_x("Ac")) == "-2*sqrt(2)");
    CHECK(machine(key.exact_y("Ac")) == "0");
    CHECK(machine(key.exact_x("uc")) == "1/2");
    CHECK(machine(key.exact_y("uc")) == "0");
    CHECK(machine(key.exact("t")) == "-2+4*sqrt(2)");
    CHECK(machine(key.exact_x("Nc")) == "-1");
    CHECK(machine(key.exact_y("Nc")) == "0");
    CHECK(machine(key.exact_x("I")) == "5-sqrt(2)");
    CHECK(machine(key.exact_y("N")) == "-sqrt(2)/2");
    const auto r = geo::intersect(tf::world_ray(d), ellipse_of(d));
    REQUIRE(r.hit.has_value());
    CHECK(r.hit->t == doctest::Approx(4 * std::sqrt(2.0) - 2).epsilon(1e-12));
    CHECK(r.hit->I.x == doctest::Approx(5 - std::sqrt(2.0)).epsilon(1e-12));
    CHECK(r.hit->N.x == doctest::Approx(-std::sqrt(0.5)).epsilon(1e-12));
  }
  SUBCASE("4. exact cos and sin only where they are quadratic surds") {
    CHECK(machine(tf::exact_cos_sin(150).cos) == "-sqrt(3)/2");
    CHECK(machine(tf::exact_cos_sin(150).sin) == "1/2");
    CHECK(machine(tf::exact_cos_sin(270).sin) == "-1");
    CHECK_FALSE(tf::exact_cos_sin(20).cos.has_value());
    CHECK_FALSE(tf::exact_cos_sin(22.5).cos.has_value());
  }
}
