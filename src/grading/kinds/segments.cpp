// Exercise 2: t_ab = AC∧CD / AB∧CD, t_cd = AC∧AB / AB∧CD, I = A + t_ab·AB. I follows from t_ab
// (or from t_cd, I = C + t_cd·CD), and whether the segments intersect from both parameters.
// Mistakes: t_ab and t_cd swapped; a sign error in one cross product (the parameter's sign
// flips).
#include "geometry/segments.h"
#include "grading/kind_grader.h"
#include "grading/kinds/instance.h"
#include "grading/kinds/registry.h"
#include "grading/review.h"

namespace epure::grading::kinds {

namespace {

struct Data {
  geo::Point2 A, B, C, D;
  geo::SegmentIntersection s;
};

bool on_segment(double t) { return t >= 0 && t <= 1; }

class SegmentsGrader final : public KindGrader {
 public:
  std::string_view kind() const override { return "segments"; }

  std::any prepare(const nlohmann::json& instance) const override {
    Data d;
    d.A = instance_point(instance, "A");
    d.B = instance_point(instance, "B");
    d.C = instance_point(instance, "C");
    d.D = instance_point(instance, "D");
    d.s = geo::intersect_segments(d.A, d.B, d.C, d.D);
    return d;
  }

  std::vector<std::string_view> mistakes() const override { return {"t_swapped", "cross_sign"}; }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}}; }

  void review(const std::any& prepared, ExerciseReview& r) const override {
    const Data& d = std::any_cast<const Data&>(prepared);
    if (!d.s.t_ab || !d.s.t_cd) return;  // parallel or collinear: nothing is computed from t
    const double t_ab = *d.s.t_ab, t_cd = *d.s.t_cd;
    r.mistake("t_ab", t_cd, "t_swapped");
    r.mistake("t_cd", t_ab, "t_swapped");
    r.mistake("t_ab", -t_ab, "cross_sign");
    r.mistake("t_cd", -t_cd, "cross_sign");

    const double ab = r.number("t_ab").value_or(t_ab), cd = r.number("t_cd").value_or(t_cd);
    r.follow_point("I", d.A + ab * d.s.AB, "t_ab");
    r.follow_point("I", d.C + cd * d.s.CD, "t_cd");
    const bool crossing = on_segment(ab) && on_segment(cd);
    r.follow_boolean("intersects", crossing, "t_ab t_cd");
    if (!crossing) r.follow_word("reason", "outside", "t_ab t_cd");
  }
};

}  // namespace

const KindGrader& segments_grader() {
  static const SegmentsGrader grader;
  return grader;
}

}  // namespace epure::grading::kinds
