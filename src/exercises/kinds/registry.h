#pragma once
// The exercise kinds, one file each under kinds/. Each file defines its accessor; registry.cpp
// lists them in the course's order.
#include "exercises/exercise.h"

namespace epure::kinds {

const ExerciseKind& vectors_kind();
const ExerciseKind& projection_kind();
const ExerciseKind& segments_kind();
const ExerciseKind& ray_circle_kind();
const ExerciseKind& ray_square_kind();
const ExerciseKind& ray_ellipse_kind();
const ExerciseKind& ray_rectangle_kind();

}  // namespace epure::kinds
