#pragma once
// The words a teacher reads about a class, in the set's language: what the sheet calls each
// exercise ("Préambule", "Exercice 3"), its title, the names of the branches drawn, of the named
// mistakes and of the flags (templates/text/<lang>/grading.toml: [grading.branch],
// [grading.mistake_name], [grading.flag_name]). The summary, the reports and the class report
// print these; the codes stay in --json.
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "exercises/spec.h"
#include "exercises/texts.h"
#include "grading/answer_key.h"

namespace epure::grading {

class ClassWords {
 public:
  ClassWords(const AnswerKey& key, const Texts& texts);

  const Texts& texts() const { return texts_; }
  // What the sheet calls exercise number n (1-based place on the sheet): the spec's heading, or
  // "Exercise k" counted as the sheet counts them.
  std::string exercise(int n) const;
  // The kind's title ("Projection of a point on a line").
  std::string title(std::string_view kind) const;
  // A branch ("parallel" → "parallèles"), a named mistake ("norm_not_rooted" → "‖u‖ sans la
  // racine carrée"), a flag ("not_asked" → "réponses non demandées"): the code itself only for a
  // code that has no name yet (a test pins that every one has).
  std::string branch(std::string_view code) const;
  std::string mistake(std::string_view code) const;
  std::string flag(std::string_view code) const;

 private:
  std::string name(std::string_view table, std::string_view code) const;
  const Texts& texts_;
  // flag names asked again and again (a report names each row's flags): code → name
  mutable std::map<std::string, std::string, std::less<>> flags_;
  std::optional<WorksheetSpec> spec_;
};

}  // namespace epure::grading
