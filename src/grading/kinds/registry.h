#pragma once
// The graders of the exercise kinds. Every kind is written as one method (exercises/
// kind_method.h) and graded by the method grader (grading/method_grader.h): no kind has a
// hand-written grader left under kinds/; registry.cpp lists the graders.
#include "grading/kind_grader.h"
