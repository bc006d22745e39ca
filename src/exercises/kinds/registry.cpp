#include "exercises/kinds/registry.h"

namespace epure {

std::vector<const ExerciseKind*> all_kinds() {
  // the course's order
  return {
      &kinds::vectors_kind(),
      &kinds::projection_kind(),
      &kinds::segments_kind(),
      &kinds::ray_circle_kind(),
      &kinds::ray_square_kind(),
      &kinds::ray_ellipse_kind(),
      &kinds::ray_rectangle_kind(),
  };
}

const ExerciseKind* find_kind(std::string_view name) {
  for (const auto* kind : all_kinds())
    if (kind->name() == name) return kind;
  return nullptr;
}

}  // namespace epure
