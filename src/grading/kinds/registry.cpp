#include "grading/kinds/registry.h"

namespace epure::grading {

std::vector<const KindGrader*> all_graders() {
  return {&kinds::vectors_grader(),    &kinds::projection_grader(), &kinds::segments_grader(),
          &kinds::ray_circle_grader(), &kinds::ray_square_grader(), &kinds::ray_ellipse_grader(),
          &kinds::ray_rectangle_grader()};
}

const KindGrader* find_grader(std::string_view kind) {
  for (const auto* g : all_graders())
    if (g->kind() == kind) return g;
  return nullptr;
}

}  // namespace epure::grading
