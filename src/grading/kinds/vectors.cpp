// The preamble: dot and cross products, norms, cos, sin and the signed angle from u to v.
// Dependencies: cos from dot and the norms, sin from cross and the norms, the angle from cos
// and sin. Mistakes: the cross product's sign (x_u·y_v − y_u·x_v taken the other way round),
// a norm without its square root, the angle without its sign or in radians.
#include <cmath>
#include <numbers>

#include "geometry/vectors.h"
#include "grading/kind_grader.h"
#include "grading/kinds/instance.h"
#include "grading/kinds/registry.h"
#include "grading/review.h"

namespace epure::grading::kinds {

namespace {

struct Data {
  geo::Vec2 u, v;
  geo::VectorPair r;
};

class VectorsGrader final : public KindGrader {
 public:
  std::string_view kind() const override { return "vectors"; }

  std::any prepare(const nlohmann::json& instance) const override {
    Data d;
    d.u = instance_vec(instance, "u");
    d.v = instance_vec(instance, "v");
    d.r = geo::compare_vectors(d.u, d.v);
    return d;
  }

  std::vector<std::string_view> mistakes() const override {
    return {"cross_sign", "norm_not_rooted", "angle_unsigned", "angle_radians"};
  }

  void review(const std::any& prepared, ExerciseReview& r) const override {
    const Data& d = std::any_cast<const Data&>(prepared);
    r.mistake("cross", -d.r.cross, "cross_sign");
    r.mistake("norm_u", geo::norm2(d.u), "norm_not_rooted");
    r.mistake("norm_v", geo::norm2(d.v), "norm_not_rooted");

    const double dot = r.number("dot").value_or(d.r.dot);
    const double cross = r.number("cross").value_or(d.r.cross);
    const double nn = r.number("norm_u").value_or(d.r.norm_u) * r.number("norm_v").value_or(d.r.norm_v);
    if (nn != 0) {  // guards the divisions
      r.follow("cos", dot / nn, "dot norm_u norm_v");
      r.follow("sin", cross / nn, "cross norm_u norm_v");
    }
    r.mistake("sin", -d.r.sin, "cross_sign");

    const auto their_sin = r.number("sin");
    const double c = r.number("cos").value_or(d.r.cos), s = their_sin.value_or(d.r.sin);
    if (c != 0 || s != 0) r.follow("angle_deg", geo::angle_degrees(c, s), "cos sin");
    // a sine of the wrong sign carries its sign into the angle, whatever the rounding
    if (their_sin && std::signbit(*their_sin) != std::signbit(d.r.sin)) r.follow("angle_deg", -d.r.angle_deg, "sin");
    // |angle| with a right sine is acos without the sign; with a wrong or missing one, the
    // cross product's sign error is the likelier story
    if (!their_sin || r.right("sin")) r.mistake("angle_deg", std::abs(d.r.angle_deg), "angle_unsigned");
    r.mistake("angle_deg", -d.r.angle_deg, "cross_sign");
    r.mistake("angle_deg", d.r.angle_deg * std::numbers::pi / 180, "angle_radians");
  }
};

}  // namespace

const KindGrader& vectors_grader() {
  static const VectorsGrader grader;
  return grader;
}

}  // namespace epure::grading::kinds
