#pragma once
// From the sheet id a student typed to the key's sheet, or a sentence saying why not: a
// mistyped character (the check character fails), a sheet of another set or generator version,
// an index past the key's sheets. Whatever the reason, the nearest id of the key (by edit
// distance, a swap of two neighbours counting as one edit) is suggested.
#include <string>
#include <string_view>

#include "exercises/texts.h"
#include "grading/answer_key.h"

namespace epure::grading {

struct SheetLookup {
  const SheetKey* sheet = nullptr;
  std::string why;      // when not found: why, in the language of `texts` (a message for the teacher)
  std::string nearest;  // the key's nearest id, when not found
  int distance = 0;     // its edit distance
};

// `texts` (grading.lookup.*) words the reason; by default the key's language.
SheetLookup find_sheet(const AnswerKey& key, std::string_view typed, const Texts& texts);
SheetLookup find_sheet(const AnswerKey& key, std::string_view typed);

// Edit distance of two ids as typed (case, dashes and spaces ignored, O read as 0, I and L as
// 1), with adjacent transpositions (optimal string alignment).
int id_distance(std::string_view a, std::string_view b);

}  // namespace epure::grading
