#include <doctest/doctest.h>

#include "geometry/projection.h"

TEST_CASE("projection of the course's first example") {
  auto p = epure::geo::project({0, 0}, {4, 0}, {1, 3});
  CHECK(p.t == doctest::Approx(0.25).epsilon(1e-15));
}
