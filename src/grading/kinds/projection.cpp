// Exercise 1: t = AB·AC / ‖AB‖², P = A + t·AB, and where P falls. P and the position follow
// from t. Mistakes: t = AB·AC / ‖AB‖ (the square forgotten), t = AB·AC (no division), and a
// position read from a wrong t (credited as follow-through, and named).
#include "geometry/projection.h"
#include "grading/kind_grader.h"
#include "grading/kinds/instance.h"
#include "grading/kinds/registry.h"
#include "grading/review.h"

namespace epure::grading::kinds {

namespace {

struct Data {
  geo::Point2 A, B, C;
  geo::Projection p;
};

std::string_view position_of(double t) {
  if (t < 0) return "before";
  return t <= 1 ? "between" : "after";
}

class ProjectionGrader final : public KindGrader {
 public:
  std::string_view kind() const override { return "projection"; }

  std::any prepare(const nlohmann::json& instance) const override {
    Data d;
    d.A = instance_point(instance, "A");
    d.B = instance_point(instance, "B");
    d.C = instance_point(instance, "C");
    d.p = geo::project(d.A, d.B, d.C);
    return d;
  }

  std::vector<std::string_view> mistakes() const override {
    return {"t_unsquared_norm", "t_not_divided", "position_from_wrong_t"};
  }
  std::vector<DrawnField> drawn() const override { return {{"P", 0, {}}}; }

  void review(const std::any& prepared, ExerciseReview& r) const override {
    const Data& d = std::any_cast<const Data&>(prepared);
    const double length = geo::norm(d.p.AB);
    r.mistake("t", d.p.ab_dot_ac / length, "t_unsquared_norm");
    r.mistake("t", d.p.ab_dot_ac, "t_not_divided");

    const double t = r.number("t").value_or(d.p.t);
    r.follow_point("P", d.A + t * d.p.AB, "t");
    r.follow_word("position", position_of(t), "t", "position_from_wrong_t");
  }
};

}  // namespace

const KindGrader& projection_grader() {
  static const ProjectionGrader grader;
  return grader;
}

}  // namespace epure::grading::kinds
