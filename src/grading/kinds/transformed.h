#pragma once
// What the graders of ray_ellipse and ray_rectangle share: the ray carried into the canonical
// frame (A_c = T⁻¹(A), u_c = T⁻¹ applied to û as a vector, not renormalised), the canonical
// figure's answer, and the way back (I = A + t·û, N by the inverse transpose, normalised).
// Follow-through: inside from A_c, hit and t from (A_c, u_c), I from t, N from I. Mistakes:
// the rotation the wrong way, the translation forgotten, scale and rotation undone in the
// wrong order, u_c renormalised, u used without normalising it, the direction translated like
// a point, the far root, the answer left in the canonical frame, and a normal not normalised,
// pointing inward, or carried by T instead of the inverse transpose.
#include <nlohmann/json_fwd.hpp>

#include <optional>

#include "geometry/affine.h"
#include "geometry/ray.h"
#include "grading/kind_grader.h"

namespace epure::grading::kinds {

struct TransformedData {
  bool ellipse = true;  // else the rectangle
  geo::Point2 A, C;
  geo::Vec2 u, uh;
  double sx = 1, sy = 1, angle = 0;
  geo::Transform2 to_world, to_canonical;
  geo::Ray2 canonical_ray;
  bool inside = false;
  std::optional<geo::Hit2> hit, canonical_hit;
};

TransformedData read_transformed(const nlohmann::json& instance, bool ellipse);
void review_transformed(const TransformedData& d, ExerciseReview& r);
std::vector<std::string_view> transformed_mistakes();
std::vector<DrawnField> transformed_drawn();

}  // namespace epure::grading::kinds
