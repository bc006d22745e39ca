// Exercise 3: ray/circle by projection and Pythagoras, with û = u/‖u‖: t_proj = û·AC,
// d² = ‖AC‖² − t_proj², the ray hits when A is inside or when t_proj ≥ 0 and d² ≤ r², then
// t = t_proj ∓ √(r² − d²), I = A + t·û and N = (I − C)/r. Each follows from the student's own
// earlier values. Mistakes: u used without normalising it, the far intersection J (t_proj +
// √(r² − d²)) instead of I, the root behind A when A is inside, and a normal not divided by r
// or pointing inward.
#include <cmath>

#include "geometry/ray_circle.h"
#include "grading/kind_grader.h"
#include "grading/kinds/instance.h"
#include "grading/kinds/registry.h"
#include "grading/review.h"

namespace epure::grading::kinds {

namespace {

using geo::Point2;
using geo::Vec2;

struct Data {
  Point2 A, C;
  Vec2 u, uh;
  double r = 1;
  geo::RayCircle rc;
};

class RayCircleGrader final : public KindGrader {
 public:
  std::string_view kind() const override { return "ray_circle"; }

  std::any prepare(const nlohmann::json& instance) const override {
    Data d;
    d.A = instance_point(instance, "A");
    d.u = instance_vec(instance, "u");
    d.C = instance_point(instance, "C");
    d.r = instance_number(instance, "r");
    d.uh = unit_direction(d.u);
    d.rc = geo::intersect(geo::Ray2{d.A, d.uh}, geo::Circle{d.C, d.r});
    return d;
  }

  std::vector<std::string_view> mistakes() const override {
    return {"direction_not_unit", "far_intersection", "near_root_inside", "normal_not_unit", "normal_inward"};
  }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}, {"N", 0, "I"}}; }

  void review(const std::any& prepared, ExerciseReview& r) const override {
    const Data& d = std::any_cast<const Data&>(prepared);
    const auto& rc = d.rc;
    const Vec2 AC = d.C - d.A;
    const double r2 = d.r * d.r;

    r.mistake("t_proj", geo::dot(d.u, AC), "direction_not_unit");
    const double tp = r.number("t_proj").value_or(rc.t_proj);
    r.follow("d2", geo::norm2(AC) - tp * tp, "t_proj");
    const double d2 = r.number("d2").value_or(rc.d2);

    const bool inside = r.boolean("inside").value_or(rc.inside);
    const bool hit = inside || (tp >= 0 && d2 <= r2);
    r.follow_boolean("hit", hit, "t_proj d2");
    if (!hit) r.follow_word("reason", tp < 0 ? "behind" : "miss", "t_proj d2");
    if (!rc.hit) return;

    const double h = *rc.half_chord;
    if (rc.inside) r.mistake("t", rc.t_proj - h, "near_root_inside");
    else r.mistake("t", rc.t_proj + h, "far_intersection");
    if (d2 <= r2) {
      const double their_h = std::sqrt(r2 - d2);
      r.follow("t", rc.inside ? tp + their_h : tp - their_h, "t_proj d2");
      if (!rc.inside) r.follow("t", tp + their_h, "t_proj d2", "far_intersection");
    }
    const double t = r.number("t").value_or(rc.hit->t);
    r.follow_point("I", d.A + t * d.uh, "t");
    if (!rc.inside) r.mistake_point("I", d.A + (rc.t_proj + h) * d.uh, "far_intersection");
    r.mistake_point("I", d.A + rc.hit->t * d.u, "direction_not_unit");

    const Point2 I = r.point("I").value_or(rc.hit->I);
    const Vec2 N = rc.hit->N;
    r.mistake_point("N", geo::to_point(-N), "normal_inward");
    r.mistake_point("N", geo::to_point(d.C - I), "normal_inward");
    r.mistake_point("N", geo::to_point(d.C - rc.hit->I), "normal_inward");
    r.mistake_point("N", geo::to_point(I - d.C), "normal_not_unit");
    r.mistake_point("N", geo::to_point(rc.hit->I - d.C), "normal_not_unit");
    r.follow_point("N", geo::to_point((I - d.C) / d.r), "I");
  }
};

}  // namespace

const KindGrader& ray_circle_grader() {
  static const RayCircleGrader grader;
  return grader;
}

}  // namespace epure::grading::kinds
