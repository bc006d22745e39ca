#pragma once
// The words students answer with, in every language the binary has texts for: yes/no
// (oui/non, true/false, 1/0), positions and reasons ("before A", "avant", "à l’extérieur"),
// "none" for an empty set of faces, and the names of the sheet, student and student number
// columns. The lists live in templates/text/<lang>/grading.toml ([grading.read]) together with
// the sheets' own choice texts ([choice]): no word is written in C++. Matching ignores case,
// accents, apostrophes and extra spaces, and the words around an answer that do not change it
// ([grading.read] lead and tail: "le rayon passe à côté du cercle" reads as "passe à côté").
#include <optional>
#include <string>
#include <string_view>

namespace epure::grading {

// Lower case, accents folded (é → e, ç → c, œ → oe), apostrophes and runs of spaces as one
// space, surrounding spaces, quotes and a final full stop removed.
std::string fold_word(std::string_view text);

// The contract word a student's word means ("avant A" → "before", "oui" → "true", "∅" →
// "none", "hors segment" → "outside", "Feuille" → "sheet", "N° étudiant" → "student_number"),
// or nothing. Static storage.
std::optional<std::string_view> read_word(std::string_view text);

}  // namespace epure::grading
