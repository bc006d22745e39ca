#pragma once
// An exercise's points, the same on every sheet of a set whatever branch was drawn: the spec
// (or the kind) sets the exercise's total, and the questions its branch asks share it in
// proportion to their weights (a spec's per-question `points`). Each question gets a multiple
// of kPointStep and the shares add up to the total exactly.
#include <string_view>
#include <vector>

#include "exercises/exercise.h"

namespace epure {

// Shares are quarter points: fine enough to follow the weights, round enough to read.
inline constexpr double kPointStep = 0.25;

// Whether `points` is a whole number of kPointStep (what a spec's exercise total must be).
bool on_point_step(double points);

// Replaces each question's weight (Question::points) by its share of `total`: largest
// remainder over kPointStep units, ties to the question asked first. A point's coordinates
// (same point_group) share as one question, and each gets half, so the share is a multiple of
// 2 units whenever the total allows it. Weights that add up to zero count as equal weights.
// `total` is rounded to kPointStep; no questions: nothing to do.
void spread_points(std::vector<Question>& questions, double total);

}  // namespace epure
