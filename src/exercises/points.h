#pragma once
// A sheet's points: the same total on every sheet of a set, each question's share following the
// work it asks. A question's weight is its work (method.h: a computed number 2, a point in the
// plane 2, a tick 0.5), or the spec's per-question `points`. An exercise whose spec sets
// `points` is worth exactly that on every sheet, its questions sharing it by weight (as before
// sheets were work-fair); the questions of the other exercises share the rest of the sheet's
// total — what their kinds' default points add up to — by weight across the whole sheet, so a
// short branch earns little and a long one much, and the draw (balance.h) gives every sheet of
// a set about the same work. Each question gets a multiple of kPointStep and the shares add up
// to the total exactly.
#include <optional>
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

// Whether a question is answered by a tick (a yes/no, a choice, a set of faces): what can mostly
// be read off the printed figure, so it weighs little (method.h's kTickWork).
bool ticked(const Question& q);

// Replaces the weights of a sheet's questions by their points: exercise e with fixed[e] (the
// spec's `points`) shares that among its own questions; the questions of every other exercise
// share `pool` together, across the sheet (a point group stays within its exercise).
// `fixed` has one entry per exercise.
void spread_sheet_points(std::vector<ExerciseInstance>& exercises, const std::vector<std::optional<double>>& fixed,
                         double pool);

}  // namespace epure
