#pragma once
// The graders of the exercise kinds, one file each under kinds/; registry.cpp lists them.
#include "grading/kind_grader.h"

namespace epure::grading::kinds {

const KindGrader& ray_ellipse_grader();
const KindGrader& ray_rectangle_grader();

}  // namespace epure::grading::kinds
