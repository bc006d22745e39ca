// The ray_rectangle kind: instances per difficulty and branch, their constraints, questions,
// exact forms, tolerances and texts; and literal cases of the frame change worked by hand.
#include <doctest/doctest.h>

#include "exercises/transformed_checks.h"

namespace {

using epure::kinds::transformed::Data;
using epure::kinds::transformed::Limits;
namespace tf = epure::kinds::transformed;
namespace geo = epure::geo;

geo::Rectangle rectangle_of(const Data& d) { return {d.C, d.sx, d.sy, d.angle_deg}; }

// Whether the half-line A + t·u (t ≥ 0) meets the box [−e, e]², by the slab method: another
// computation than the course's candidate sides.
bool slab_meets(geo::Point2 A, geo::Vec2 u, double e) {
  double lo = 0, hi = 1e300;
  for (int k = 0; k < 2; ++k) {
    const double a = k == 0 ? A.x : A.y, v = k == 0 ? u.x : u.y;
    if (std::abs(v) < 1e-300) {
      if (std::abs(a) > e) return false;
      continue;
    }
    double t0 = (-e - a) / v, t1 = (e - a) / v;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  return lo <= hi;
}

// A clear hit lands at least `margin` from the corners and meets its side steeply; a clear miss
// stays out of the square grown by margin/√2 (inside the points within `margin` of it).
void check_clear(const Data& d, const std::string& branch, const Limits& lim) {
  const auto r = geo::intersect(tf::world_ray(d), rectangle_of(d));
  const geo::Point2 Ac = r.canonical_ray.origin;
  const geo::Vec2 uc = r.canonical_ray.direction;
  const double reach = std::max(std::abs(Ac.x), std::abs(Ac.y));
  if (branch == "inside")
    CHECK(reach <= 1 - lim.margin + 1e-12);
  else
    CHECK(reach >= 1 + lim.margin - 1e-12);
  if (r.hit) {
    const geo::Point2 Ic = r.canonical.hit->I;
    const geo::Vec2 Nc = r.canonical.hit->N;
    const double across = std::abs(Nc.x) > 0.5 ? Ic.y : Ic.x;
    CHECK(std::abs(across) <= 1 - lim.margin + 1e-12);
    CHECK(std::abs(geo::dot(uc, Nc)) / geo::norm(uc) >= lim.min_incidence - 1e-12);
  }
  if (branch == "miss") CHECK_FALSE(slab_meets(Ac, uc, 1 + lim.margin / std::sqrt(2.0) - 1e-9));
}

// The kind's method on the data, unrounded: {Ac.x, Ac.y, uc.x, uc.y} and with a hit {t, I.x,
// I.y, N.x, N.y}.
std::vector<double> hand(const Data& d) {
  return epure::test::hand_answers(epure::test::instance_of("ray_rectangle", d));
}

// The key's solution of the data, at the standard level in English.
epure::kinds::KeySolution key_of(const Data& d) {
  // the context (and the spec it names) outlive every call: a key's questions keep a view of it
  static const auto spec = epure::test::spec_for("ray_rectangle", epure::Difficulty::standard);
  static const auto ctx = epure::test::context_for(spec, "en", "hit");
  return tf::rectangle_key(d, ctx);
}
std::string machine(const std::optional<epure::exact::Surd>& e) {
  REQUIRE(e.has_value());
  return e->machine();
}

}  // namespace

TEST_CASE("ray_rectangle: every difficulty and branch, over many seeds") {
  const epure::test::KindCheck check{(*epure::find_kind("ray_rectangle")), tf::Shape::rectangle, check_clear};
  epure::test::check_kind(check, 300, rectangle_of);
}

TEST_CASE("ray_rectangle: the kind's name, branches, constraints and fields") {
  const auto& kind = (*epure::find_kind("ray_rectangle"));
  CHECK(kind.name() == "ray_rectangle");
  CHECK(epure::find_kind("ray_rectangle") == &kind);
  CHECK(kind.default_branches().size() == 3);
  CHECK(kind.default_constraints().count("min_incidence") == 1);
  CHECK(kind.fields() == std::vector<std::string>{"Ac", "uc", "inside", "hit", "t", "I", "N"});
}

TEST_CASE("ray_rectangle: the key names the candidate sides and the side hit") {
  const auto& kind = (*epure::find_kind("ray_rectangle"));
  const auto spec = epure::test::spec_for("ray_rectangle", epure::Difficulty::easy);
  for (int seed = 0; seed < 20; ++seed) {
    CAPTURE(seed);
    epure::Rng rng(static_cast<std::uint64_t>(seed));
    const auto inst = kind.make(rng, epure::test::context_for(spec, "en", "hit"));
    const auto texts = epure::test::texts_of(inst.key);
    bool enters = false;
    for (const auto& text : texts) enters = enters || text.find("enters the square through side") != std::string::npos;
    CHECK(enters);
  }
}

TEST_CASE("ray_rectangle: the frame change worked by hand") {
  SUBCASE("1. angle 90: the w-axis is vertical") {
    // C(6, 5), w = 2, h = 1, θ = 90°; A(6, 0), u = (0, 2): rotated by −90°, A − C = (0, −5)
    // becomes (−5, 0), A_c = (−5/2, 0), u_c = (1/2, 0); side −x at t = (−1 + 5/2)/(1/2) = 3,
    // I = (6, 3), N_c = (−1, 0) → N = (0, −1)
    const Data d{{6, 0}, {0, 2}, {6, 5}, 2, 1, 90};
    const auto answers = hand(d);
    const std::vector<double> want{-2.5, 0, 0.5, 0, 3, 6, 3, 0, -1};
    REQUIRE(answers.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) CHECK(answers[i] == doctest::Approx(want[i]).epsilon(1e-12).scale(1));
    const auto r = geo::intersect(tf::world_ray(d), rectangle_of(d));
    REQUIRE(r.hit.has_value());
    CHECK(geo::face_name(*r.canonical.face) == "-x");
  }
  SUBCASE("2. angle 30: exact surds") {
    // C(6, 5), w = 2, h = 1, θ = 30°; A(6, 3), u = (0, 1): rotated by −30°, A − C = (0, −2)
    // becomes (−1, −√3), so A_c = (−1/2, −√3); û = (0, 1) becomes (1/2, √3/2), u_c = (1/4, √3/2);
    // side −y at t = (−1 + √3)/(√3/2) = 2 − 2√3/3, where x = −1/2 + t/4 lies in [−1, 1]
    const Data d{{6, 3}, {0, 1}, {6, 5}, 2, 1, 30};
    const auto key = key_of(d);
    CHECK(machine(key.exact_x("Ac")) == "-1/2");
    CHECK(machine(key.exact_y("Ac")) == "-sqrt(3)");
    CHECK(machine(key.exact_x("uc")) == "1/4");
    CHECK(machine(key.exact_y("uc")) == "sqrt(3)/2");
    CHECK(machine(key.exact("t")) == "(6-2*sqrt(3))/3");
    const auto r = geo::intersect(tf::world_ray(d), rectangle_of(d));
    REQUIRE(r.hit.has_value());
    CHECK(geo::face_name(*r.canonical.face) == "-y");
    CHECK(r.hit->t == doctest::Approx(2 - 2 * std::sqrt(3.0) / 3).epsilon(1e-12));
    // the normal of side −y, rotated by 30°: (sin 30°, −cos 30°)
    CHECK(r.hit->N.x == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(r.hit->N.y == doctest::Approx(-std::sqrt(3.0) / 2).epsilon(1e-12));
    const auto answers = hand(d);
    REQUIRE(answers.size() == 9);
    CHECK(answers[4] == doctest::Approx(r.hit->t).epsilon(1e-12));
  }
}
