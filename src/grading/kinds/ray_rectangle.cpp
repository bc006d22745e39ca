// The course's open question on rectangles: the canonical square under a transform. What the
// grader knows is shared with the ellipse (transformed.h).
#include "grading/kinds/registry.h"
#include "grading/kinds/transformed.h"

namespace epure::grading::kinds {

namespace {

class RayRectangleGrader final : public KindGrader {
 public:
  std::string_view kind() const override { return "ray_rectangle"; }
  std::any prepare(const nlohmann::json& instance) const override { return read_transformed(instance, false); }
  void review(const std::any& prepared, ExerciseReview& r) const override {
    review_transformed(std::any_cast<const TransformedData&>(prepared), r);
  }
  std::vector<std::string_view> mistakes() const override { return transformed_mistakes(); }
  std::vector<DrawnField> drawn() const override { return transformed_drawn(); }
};

}  // namespace

const KindGrader& ray_rectangle_grader() {
  static const RayRectangleGrader grader;
  return grader;
}

}  // namespace epure::grading::kinds
