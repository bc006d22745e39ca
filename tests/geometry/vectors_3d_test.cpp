// The preamble in space (geometry/vectors.h: compare_vectors_3d), against values worked by hand.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/degenerate.h"
#include "geometry/vectors.h"

using namespace epure::geo;

TEST_CASE("vectors in space: products, norms, unsigned angle") {
  // u = (1, 2, 3), v = (−2, 0, 1): u·v = 1, u∧v = (2, −7, 4), ‖u‖ = √14, ‖v‖ = √5, ‖u∧v‖ = √69
  const VectorPair3 p = compare_vectors_3d({1, 2, 3}, {-2, 0, 1});
  CHECK(p.dot == 1);
  CHECK(p.cross.x == 2);
  CHECK(p.cross.y == -7);
  CHECK(p.cross.z == 4);
  CHECK(p.norm_u == doctest::Approx(std::sqrt(14.0)).epsilon(1e-15));
  CHECK(p.norm_v == doctest::Approx(std::sqrt(5.0)).epsilon(1e-15));
  CHECK(p.cos == doctest::Approx(1 / std::sqrt(70.0)).epsilon(1e-15));
  CHECK(p.sin == doctest::Approx(std::sqrt(69.0 / 70.0)).epsilon(1e-15));
  CHECK(p.cos * p.cos + p.sin * p.sin == doctest::Approx(1).epsilon(1e-15));
  CHECK(p.angle_deg == doctest::Approx(std::acos(1 / std::sqrt(70.0)) * 180 / M_PI).epsilon(1e-13));
  CHECK_FALSE(p.collinear);
  CHECK_FALSE(p.orthogonal);
  // swapping u and v turns u∧v round, and leaves the (unsigned) angle
  const VectorPair3 q = compare_vectors_3d({-2, 0, 1}, {1, 2, 3});
  CHECK(q.cross.y == 7);
  CHECK(q.angle_deg == doctest::Approx(p.angle_deg).epsilon(1e-15));
}

TEST_CASE("vectors in space: collinear, orthogonal, degenerate") {
  const VectorPair3 opposite = compare_vectors_3d({1, 2, 2}, {-2, -4, -4});
  CHECK(opposite.collinear);
  CHECK(opposite.angle_deg == 180);
  // collinear as written, whatever the rounding in binary; their doubles as such are not
  const VectorPair3 same = compare_decimal_vectors_3d(written_point(Vec3{0.3, 0.6, 0.9}), written_point(Vec3{0.1, 0.2, 0.3}));
  CHECK(same.collinear);
  CHECK(same.angle_deg < 1e-9);
  CHECK_FALSE(compare_vectors_3d({0.3, 0.6, 0.9}, {0.1, 0.2, 0.3}).collinear);
  // a hair off collinear or orthogonal as written is neither (no tolerance)
  const Decimal hair = read_decimal("0.30000000000000000001", 0.3);
  CHECK_FALSE(compare_decimal_vectors_3d({hair, written(0.6), written(0.9)}, written_point(Vec3{0.1, 0.2, 0.3})).collinear);
  const Decimal off = read_decimal("0.50000000000000000001", 0.5);
  CHECK_FALSE(compare_decimal_vectors_3d({written(2), written(-1), off}, written_point(Vec3{1, 3, 2})).orthogonal);
  CHECK(compare_decimal_vectors_3d(written_point(Vec3{2, -1, 0.5}), written_point(Vec3{1, 3, 2})).orthogonal);
  const VectorPair3 right = compare_vectors_3d({2, -1, 0.5}, {1, 3, 2});
  CHECK(right.orthogonal);
  CHECK(right.angle_deg == doctest::Approx(90).epsilon(1e-15));
  CHECK_THROWS_AS(compare_vectors_3d({0, 0, 0}, {1, 2, 3}), DegenerateFigure);
  CHECK_THROWS_AS(compare_vectors_3d({1, 2, 3}, {0, 0, 0}), DegenerateFigure);
}
