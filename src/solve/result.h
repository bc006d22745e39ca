#pragma once
// Writing one result of the solve contract, and what the kinds' solvers share: the ray as given
// (its direction rescaled by a power of two only) and the round figures' fields.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

#include "geometry/box_faces.h"
#include "geometry/vec.h"
#include "solve/fields.h"
#include "solve/json_out.h"

namespace epure::solve {

// Every number of a result is checked before it is written: data near the limits of double
// (1e300 squared) overflows, and the text must never say inf or nan. A refused result leaves
// the buffer as it found it.
class Result {
 public:
  Result(fmt::memory_buffer& out, std::string_view kind) : start_(out.size()), out_(out), w_(out) {
    w_.begin_object().field("kind", kind);
  }
  Result& number(std::string_view k, double x) {
    check(x, k);
    w_.field(k, x);
    return *this;
  }
  Result& boolean(std::string_view k, bool b) {
    w_.field(k, b);
    return *this;
  }
  Result& string(std::string_view k, std::string_view s) {
    w_.field(k, s);
    return *this;
  }
  template <class P>
  Result& point(std::string_view k, const P& p) {
    w_.key(k).begin_array();
    for (double c : coordinates(p)) {
      check(c, k);
      w_.number(c);
    }
    w_.end_array();
    return *this;
  }
  template <int Dim>
  Result& faces(const geo::FaceSet<Dim>& set) {
    w_.key("faces").begin_array();
    set.for_each([&](geo::Face f) { w_.string(geo::face_name(f)); });
    w_.end_array();
    return *this;
  }
  // hit; then t (times `length`: the direction's length, for a t along the ray as given), I, N
  template <class Hit>
  Result& hit(const std::optional<Hit>& h, double length = 1) {
    boolean("hit", h.has_value());
    if (h) number("t", h->t * length).point("I", h->I).point("N", h->N);
    return *this;
  }
  void end() { w_.end_object(); }

 private:
  static std::array<double, 2> coordinates(geo::Point2 p) { return {p.x, p.y}; }
  static std::array<double, 2> coordinates(geo::Vec2 v) { return {v.x, v.y}; }
  static std::array<double, 3> coordinates(geo::Point3 p) { return {p.x, p.y, p.z}; }
  static std::array<double, 3> coordinates(geo::Vec3 v) { return {v.x, v.y, v.z}; }
  void check(double x, std::string_view k) {
    if (!std::isfinite(x)) {
      out_.resize(start_);
      fail(k, "result overflows a double: the figure's coordinates are too large");
    }
  }
  std::size_t start_;
  fmt::memory_buffer& out_;
  JsonWriter w_;
};

// The ray as given, its direction only rescaled by a power of two (exact). Normalising it would
// turn it by up to ε around A, which a figure 1e8 away sees as a shift of 1e-8, and an exact
// tangent as a near one. The core's t is then in units of that direction: times its length
// gives the distance the contract asks for.
template <class Ray, class Point, class Vec>
std::pair<Ray, double> raw_ray(Point A, Vec u) {
  const Vec direction = geo::rescaled(u);
  return {Ray{A, direction}, geo::norm(direction)};
}

// A direction as written, times the power of two that brings its largest coordinate into [1, 2)
// (exact, as raw_ray), and its length.
template <std::size_t N>
std::pair<std::array<geo::Decimal, N>, double> raw_direction(std::array<geo::Decimal, N> u) {
  double m = 0;
  for (const auto& c : u) m = std::max(m, std::abs(c.hi));
  if (m > 0 && std::isfinite(m)) {
    const int k = -std::ilogb(m);
    for (auto& c : u) c = geo::times_pow2(c, k);
  }
  return {u, geo::norm(geo::hi_vec(u))};
}

// A ray and a ball (circle, sphere): t_proj, d², inside, hit; then t, I, N; else the reason.
// The same values for the keys and for `epure solve`, whichever kernel decided (geometry's
// printed_values: within 4 ulps of the figure's scale).
template <class Round, class Printed>
void write_round(const Round& c, const Printed& printed, Result& r) {
  r.number("t_proj", printed.t_proj).number("d2", c.d2).boolean("inside", c.inside);
  r.boolean("hit", c.hit.has_value());
  if (c.hit) r.number("t", printed.t).point("I", printed.I).point("N", printed.N);
  if (c.reason) r.string("reason", to_string(*c.reason));
}

}  // namespace epure::solve
