#pragma once
// The grader of every kind written as one method (exercises/kind_method.h): follow-through and
// named mistakes come from running the kind's method on the student's own answers, once as the
// course teaches it and once per named mistake, never from a hand-written copy of the method.
#include "exercises/exercise.h"
#include "grading/kind_grader.h"

namespace epure::grading {

// The grader of a kind written as a method, or null for one that is not.
const KindGrader* method_grader(const ExerciseKind& kind);

}  // namespace epure::grading
