// The one list of the exercise kinds, in the course's order. Each kind is one file beside this
// one (its schema, branches, questions, method, mistakes and diagrams) that defines its accessor;
// nothing else names a kind.
#include "exercises/exercise.h"

namespace epure::kinds {

const ExerciseKind& vectors_kind();
const ExerciseKind& projection_kind();
const ExerciseKind& segments_kind();
const ExerciseKind& ray_circle_kind();
const ExerciseKind& ray_square_kind();
const ExerciseKind& ray_ellipse_kind();
const ExerciseKind& ray_rectangle_kind();
const ExerciseKind& vectors_3d_kind();
const ExerciseKind& ray_sphere_kind();
const ExerciseKind& ray_cube_kind();

}  // namespace epure::kinds

namespace epure {

std::vector<const ExerciseKind*> all_kinds() {
  return {
      &kinds::vectors_kind(),    &kinds::projection_kind(),  &kinds::segments_kind(),
      &kinds::ray_circle_kind(), &kinds::ray_square_kind(),  &kinds::ray_ellipse_kind(),
      &kinds::ray_rectangle_kind(),
      // in space
      &kinds::vectors_3d_kind(), &kinds::ray_sphere_kind(), &kinds::ray_cube_kind(),
  };
}

const ExerciseKind* find_kind(std::string_view name) {
  for (const auto* kind : all_kinds())
    if (kind->name() == name) return kind;
  return nullptr;
}

}  // namespace epure
