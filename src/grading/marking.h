#pragma once
// Marks one exercise of one submission: every cell read for its question's type, compared by
// the key's rule (isclose for numbers, distance for a point marked as a whole, equality for
// yes/no, words and face sets in any order); a cell that cannot be read is to check (its
// points held). Then, if some answer is not right, answers typed where or as not asked
// (typed_cells.h: a point in one cell, two neighbouring cells swapped) are read as meant, and if
// some answer is still wrong, the mistakes every kind shares (a point's coordinates swapped:
// "swapped_coordinates") and the kind's second look (review.h) for follow-through credit and its
// own named mistakes.
#include <span>
#include <string_view>

#include "exercises/numbers.h"
#include "grading/answer_key.h"
#include "grading/marks.h"

namespace epure::grading {

struct MarkingOptions {
  bool follow_through = true;
  NumberStyle numbers;  // for the earlier answers a follow-through sentence quotes
  int decimals = 2;
};

// `cells[i]` is the student's cell for key.questions[i] (empty: not answered). `out` is
// resized and overwritten; its buffers are reused from call to call.
void mark_exercise(const ExerciseKey& key, std::span<const std::string_view> cells,
                   const MarkingOptions& options, ExerciseMarks& out);

}  // namespace epure::grading
