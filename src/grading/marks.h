#pragma once
// What marking says of one answer: what was read, the verdict, the points, and why (a named
// mistake, or the earlier answers a follow-through credit came from). The sentence for a
// student is written from these only when an output needs it (feedback_text.h): marking a
// class set into a CSV report formats no sentence at all.
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "grading/faces.h"

namespace epure::grading {

// What the student wrote in one cell, read for the question's type.
struct Given {
  enum class State : unsigned char { blank, value, unreadable } state = State::blank;
  double number = 0;
  bool boolean = false;
  FaceBits faces = 0;
  std::string_view word;  // a contract word ("before", "miss"), static storage
  std::string_view raw;   // the cell as written: valid while its row is
  std::string_view why;   // unreadable: the reason's code ("number", "division_by_zero", …)

  bool readable() const { return state == State::value; }
};

enum class Verdict : unsigned char {
  right,           // by the key's rule
  follow_through,  // wrong by the key, right from the student's own earlier answers: credited
  wrong,
  unanswered,
  // A cell that could not be read for its question (corrections.h): its points are held, neither
  // given nor refused, and the row is listed for the teacher until a corrections file settles it.
  to_check,
};

std::string_view to_string(Verdict v);

struct QuestionMark {
  Given given;
  Verdict verdict = Verdict::unanswered;
  double points = 0;
  std::string_view mistake;  // a named mistake's code ("far_intersection"), static storage
  std::string_view from;     // follow-through: the fields it followed from ("t", "t_proj d2")
  std::string detail;        // those earlier answers as the student gave them ("t = 0.31")
  double value = NAN;        // what the named mistake or the student's own values give
  // How the answer was read when it was not typed where or as asked, static storage:
  // "swapped_cells" (read from the neighbouring cell, whose answer it is), "point_in_one_cell".
  std::string_view note;
  std::string_view note_field;  // swapped_cells: the question id whose cell it was read from
  bool corrected = false;       // the cell's text came from the teacher's corrections file

  bool credited() const { return points > 0; }
};

// The marks of one exercise, in the order of its key's questions.
using ExerciseMarks = std::vector<QuestionMark>;

// Whether the q-th mark names a mistake no earlier mark of its exercise names: a mistake is
// counted once per exercise (a slip that moves a point's three coordinates, or that the later
// answers carry on, is one mistake, made once).
inline bool first_naming(const ExerciseMarks& marks, std::size_t q) {
  if (marks[q].mistake.empty()) return false;
  for (std::size_t p = 0; p < q; ++p)
    if (marks[p].mistake == marks[q].mistake) return false;
  return true;
}

}  // namespace epure::grading
