#pragma once
// Answers typed where or as the sheet did not ask, read as the student meant them, the way a
// teacher reads a paper copy: a whole point written in one of its coordinates' cells ("(3 ; 5)"
// in P.x, P.y left empty) is read coordinate by coordinate, and two neighbouring answers typed in
// each other's cell (t_proj's value under d², d²'s under t_proj) are each read in its own place.
// Both run only on an exercise with something not right: the point after the first reading of
// its cells, the swap after the kind's review, so that a mistake the kind names (t_ab and t_cd
// swapped is the segments' "t_swapped") is never read as a slip of the pen.
#include <span>
#include <string_view>

#include "grading/answer_key.h"
#include "grading/marks.h"

namespace epure::grading {

// Whether a readable given answer is right by the question's rule (points marked as a whole
// are decided with their partner, in marking.cpp).
bool equal_by_rule(const HotQuestion& q, const Given& g);

// For every point (group of coordinate questions) with exactly one non-empty cell holding the
// whole point, each coordinate is read from its part and marked ("point_in_one_cell"). A cell
// that may be a point or a number ("(3,5)" on a French sheet) puts every coordinate of the point
// to check (why "ambiguous_point"). Coordinates of a point marked as a whole are left `wrong`,
// for their partner's pass to decide.
void read_points_in_one_cell(const ExerciseKey& key, std::span<const std::string_view> cells, bool decimal_comma,
                             ExerciseMarks& out);

// Two neighbouring questions (in the sheet's order) whose answers are neither right nor blank
// nor explained by a named mistake, each right when its cell is read as the other's: both marked right with their points, the
// given answers exchanged, noted "swapped_cells". Never for two coordinates of one point (that
// is the named mistake "swapped_coordinates": a point is written (x ; y)) nor for two yes/no
// answers (swapping two of them is also answering both wrong).
void read_swapped_cells(const ExerciseKey& key, std::span<const std::string_view> cells, ExerciseMarks& out);

}  // namespace epure::grading
