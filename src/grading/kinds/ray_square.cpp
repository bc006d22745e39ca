// Exercise 4: ray/canonical square. The candidate sides are those whose outer half-plane holds
// A; on a candidate side n the ray is met at t = (1 − A·n)/(û·n), I = A + t·û, and N is the
// side's normal. hit and t follow from the student's own candidates, I from their t, N from
// the side their I lies on. Mistakes: the candidates taken from the wrong half-planes (the
// opposite sides, or the sides whose inner half-plane holds A), the candidates read from the
// direction instead of A, u used without normalising it, and a normal pointing inward.
#include <cmath>

#include "geometry/ray_square.h"
#include "grading/kind_grader.h"
#include "grading/kinds/instance.h"
#include "grading/kinds/registry.h"
#include "grading/review.h"

namespace epure::grading::kinds {

namespace {

using geo::Point2;
using geo::Vec2;

struct Data {
  Point2 A;
  Vec2 u, uh;
  geo::RaySquare rs;
  FaceBits candidates = 0;
  FaceBits inner = 0;      // sides whose inner half-plane holds A
  FaceBits towards = 0;    // sides the direction points at (û·n < 0)
};

// The first crossing of the ray with one of `sides` that lies on the side, as the course's
// method finds it from those candidates.
std::optional<double> hit_from(const Data& d, FaceBits sides) {
  std::optional<double> best;
  for (int bit : kSquareSides) {
    if (!(sides & (1u << bit))) continue;
    const Vec2 n = side_normal(bit);
    const double un = geo::dot(d.uh, n);
    if (!(un < 0)) continue;
    const double t = (1 - geo::dot(geo::to_vec(d.A), n)) / un;
    const Point2 J = d.A + t * d.uh;
    const double other = n.x != 0 ? J.y : J.x;
    if (t >= 0 && std::abs(other) <= 1 && (!best || t < *best)) best = t;
  }
  return best;
}

class RaySquareGrader final : public KindGrader {
 public:
  std::string_view kind() const override { return "ray_square"; }

  std::any prepare(const nlohmann::json& instance) const override {
    Data d;
    d.A = instance_point(instance, "A");
    d.u = instance_vec(instance, "u");
    d.uh = unit_direction(d.u);
    d.rs = geo::intersect_canonical_square(geo::Ray2{d.A, d.uh});
    d.rs.faces.for_each([&](geo::Face f) { d.candidates |= face_bit(geo::face_name(f)); });
    for (int bit : kSquareSides) {
      const Vec2 n = side_normal(bit);
      if (geo::dot(geo::to_vec(d.A), n) <= 1) d.inner |= FaceBits(1u << bit);
      if (geo::dot(d.uh, n) < 0) d.towards |= FaceBits(1u << bit);
    }
    return d;
  }

  std::vector<std::string_view> mistakes() const override {
    return {"faces_wrong_half_planes", "faces_from_direction", "direction_not_unit", "normal_inward"};
  }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}, {"N", 0, "I"}}; }

  void review(const std::any& prepared, ExerciseReview& r) const override {
    const Data& d = std::any_cast<const Data&>(prepared);
    if (!d.rs.inside) {
      r.mistake_faces("faces", opposite_faces(d.candidates), "faces_wrong_half_planes");
      r.mistake_faces("faces", d.inner, "faces_wrong_half_planes");
    }
    r.mistake_faces("faces", d.towards, "faces_from_direction");

    const FaceBits sides = r.faces("faces").value_or(d.candidates);
    if (sides != 0) {
      const auto t_sides = hit_from(d, sides);
      r.follow_boolean("hit", t_sides.has_value(), "faces");
      for (int bit : kSquareSides) {
        if (!(sides & (1u << bit))) continue;
        const Vec2 n = side_normal(bit);
        const double un = geo::dot(d.uh, n);
        if (un == 0) continue;  // guards the division: the ray runs along the side
        const double t = (1 - geo::dot(geo::to_vec(d.A), n)) / un;
        if (t >= 0) r.follow("t", t, "faces");
      }
    }
    if (!d.rs.hit) return;
    const Vec2 n = d.rs.hit->N;
    const double un = geo::dot(d.u, n);
    if (un != 0) r.mistake("t", (1 - geo::dot(geo::to_vec(d.A), n)) / un, "direction_not_unit");

    const double t = r.number("t").value_or(d.rs.hit->t);
    r.follow_point("I", d.A + t * d.uh, "t");
    r.mistake_point("I", d.A + d.rs.hit->t * d.u, "direction_not_unit");

    r.mistake_point("N", geo::to_point(-n), "normal_inward");
    if (const auto I = r.point("I")) {
      // the side their I lies on: its larger coordinate, in absolute value
      const Vec2 side = std::abs(I->x) >= std::abs(I->y) ? Vec2{I->x < 0 ? -1.0 : 1.0, 0}
                                                         : Vec2{0, I->y < 0 ? -1.0 : 1.0};
      r.follow_point("N", geo::to_point(side), "I");
    }
  }
};

}  // namespace

const KindGrader& ray_square_grader() {
  static const RaySquareGrader grader;
  return grader;
}

}  // namespace epure::grading::kinds
