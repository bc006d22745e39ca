#pragma once
// The key's construction diagrams, redrawn for feedback sheets: key.json carries the spec the
// set was drawn from and its seed, so each exercise is drawn again from (sheet index, slot,
// attempt) and kept only when its instance is exactly the key's (a set settles the rare
// collision between sheets by a later attempt: the first few attempts are tried). A key from
// another generator version, or a set generated with an overridden difficulty that the key
// does not record, is tried under each difficulty before giving up; then the sheet has no
// diagram, and says why.
#include <map>
#include <optional>
#include <string>

#include "exercises/worksheet.h"
#include "grading/answer_key.h"
#include "render/document.h"

namespace epure::grading {

class KeyDiagrams {
 public:
  KeyDiagrams(const AnswerKey& key, std::string language);

  bool available() const { return spec_.has_value(); }
  const std::string& why_not() const { return why_not_; }
  // The spec the set was drawn from, when the key carries one that reads (headings come from it).
  const WorksheetSpec* spec() const { return spec_ ? &*spec_ : nullptr; }

  // The key's figure of exercise `e` of `sheet` (its scene and the width the key gives it: a
  // feedback sheet shows it as large as the key does), or nothing when it cannot be redrawn.
  std::optional<render::Figure> figure(const SheetKey& sheet, std::size_t e);
  // The whole exercise drawn again (the student's section, the key's, its questions), in this
  // object's language, or nothing when it cannot be redrawn (platform exports read the sheet's
  // statement and diagrams from it).
  std::optional<ExerciseInstance> instance(const SheetKey& sheet, std::size_t e);

 private:
  std::optional<ExerciseInstance> try_set(WorksheetSet& set, const SheetKey& sheet, std::size_t e);

  std::optional<WorksheetSpec> spec_;
  std::string language_;
  // per seed: the spec as written first, then under each difficulty
  std::map<std::uint64_t, std::vector<WorksheetSet>> sets_;
  std::size_t preferred_ = 0;  // the variant that last matched
  std::string why_not_;
};

}  // namespace epure::grading
