#pragma once
// One cell read for its question's type: a number (expression.h), a yes/no, a word (a position
// or a reason), or a set of faces. An empty cell is "not answered"; a cell that cannot be read
// as the type is "unreadable", with the reason's code (templates: grading.unreadable.<code>).
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

Given read_answer(std::string_view cell, AnswerType type);
// The same written into `out` (marking's own mark): a Given returned by value was put together
// on the stack and copied, and the copy's wide loads stalled on the narrow stores just before.
void read_answer(std::string_view cell, AnswerType type, Given& out);

}  // namespace epure::grading
