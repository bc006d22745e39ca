#pragma once
// One cell read for its question's type: a number (expression.h), a yes/no, a word (a position
// or a reason), or a set of faces. An empty cell is "not answered"; a cell that cannot be read
// as the type is "unreadable", with the reason's code (templates: grading.unreadable.<code>).
#include <array>
#include <string_view>

#include "grading/answer_key.h"
#include "grading/marks.h"

namespace epure::grading {

// Surrounding spaces (ASCII and no-break) removed.
std::string_view trim_cell_spaces(std::string_view cell);
inline std::string_view trim_cell(std::string_view cell) {
  // most cells begin and end with a printable ASCII byte, which no space (nor any byte of a
  // no-break space) is: nothing to trim, decided inline
  const auto plain = [](char c) { return static_cast<unsigned char>(c) > ' ' && static_cast<unsigned char>(c) < 0x80; };
  if (cell.empty() || (plain(cell.front()) && plain(cell.back()))) return cell;
  return trim_cell_spaces(cell);
}

// Faces as students list them: "+x -y", "-y;+x", "+x,+y", "x=1 y=-1", "none" / "aucune" / "∅".
// Every face needs its sign. Returns false for anything else.
bool read_faces(std::string_view text, FaceBits& out);

// A whole point typed in one coordinate's cell: "(3 ; 5)", "3;5", "(3, 5)", "[1,5 ; −2]",
// "P = (2 ; 1 ; 0)". The coordinates are split at ';', else at a comma followed by a blank
// ("(3, 5)"), else, in brackets and in a language that writes decimal points, at a comma
// ("(3,5)"); each part must read as a number. "3,5" without brackets is a number (a decimal
// comma is read in every language); in a language that writes decimal commas, "(3,5)" is the
// point (3 ; 5) or the number 3,5: `ambiguous`, for the teacher to check.
enum class PointCell { not_a_point, point, ambiguous };
PointCell read_point_cell(std::string_view cell, int dims, bool decimal_comma, std::array<std::string_view, 3>& parts);

Given read_answer(std::string_view cell, AnswerType type);
// The same written into `out` (marking's own mark): a Given returned by value was put together
// on the stack and copied, and the copy's wide loads stalled on the narrow stores just before.
void read_answer(std::string_view cell, AnswerType type, Given& out);

}  // namespace epure::grading
