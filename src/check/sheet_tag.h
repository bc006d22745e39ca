#pragma once
// Who a submission is from, as its comments say: a line "sheet: 2000-0G2R-0048" (or "feuille :",
// "sheet id", "id") ties the file to that student's worksheet, whose instances are then among
// the cases; "student: Zoé Lefèvre" (or "étudiant :", "etudiant", "name", "nom", "élève") names
// the student. Keys in any case, with or without accents, the colon with or without spaces; the
// first of each counts; the starter's placeholders count as nothing. The id is read as a person
// types it (parse_sheet_id: any case, O for 0, …) and refused with the reason when it does not
// check (tests/fuzz/sheet_tag_fuzz.cpp).
#include <optional>
#include <string>
#include <string_view>

#include "exercises/sheet_id.h"

namespace epure::check {

struct SubmissionTags {
  std::optional<SheetId> sheet;
  std::string sheet_text;       // as written, when there is a sheet line
  std::optional<std::string> sheet_problem;  // why the written id was not taken
  int sheet_line = 0;
  std::string student;          // empty when the file names nobody
};

// Values longer than this are cut (a name is not a paragraph).
inline constexpr std::size_t kMaxTagValue = 120;

SubmissionTags read_tags(std::string_view source);

}  // namespace epure::check
