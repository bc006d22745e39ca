#pragma once
// Random data for the geometry property tests, drawn from epure::Rng (never rand() or the
// standard distributions, so that a seed names the same figure on every platform). Each property
// test loops over seeds with CAPTURE(seed): a failure prints the seed that reproduces it.
#include <cmath>
#include <cstdint>

#include "exercises/rng.h"
#include "geometry/vec.h"

namespace epure::test {

// A magnitude spread evenly over the decades [10^lo, 10^hi].
inline double decades(Rng& rng, double lo, double hi) {
  return std::pow(10.0, rng.uniform(lo, hi));
}

// A sign, + or −, with even odds.
inline double sign(Rng& rng) { return rng.chance(0.5) ? 1.0 : -1.0; }

// A point of the square [−extent, extent]² (cube in 3D), full 53-bit coordinates.
inline geo::Point2 point2(Rng& rng, double extent) {
  return {rng.uniform(-extent, extent), rng.uniform(-extent, extent)};
}
inline geo::Point3 point3(Rng& rng, double extent) {
  return {rng.uniform(-extent, extent), rng.uniform(-extent, extent), rng.uniform(-extent, extent)};
}

// A direction of random orientation whose length is spread over [10^-3, 10^3]: the functions
// must not care how long a direction is.
inline geo::Vec2 direction2(Rng& rng) {
  for (;;) {
    geo::Vec2 v{rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double n = geo::norm(v);
    if (n > 0.25 && n < 1) return decades(rng, -3, 3) / n * v;
  }
}
inline geo::Vec3 direction3(Rng& rng) {
  for (;;) {
    geo::Vec3 v{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double n = geo::norm(v);
    if (n > 0.25 && n < 1) return decades(rng, -3, 3) / n * v;
  }
}

// The unit vector at `radians` from the x-axis.
inline geo::Vec2 at_angle(double radians) { return {std::cos(radians), std::sin(radians)}; }

}  // namespace epure::test
