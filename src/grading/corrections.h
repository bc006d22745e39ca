#pragma once
// The teacher's corrections of answers that could not be read (marked "to check"), or were read
// wrong: a JSON file, written by hand or by `epure scan`'s review page (review.html), that
// `epure grade --corrections FILE` (and `epure scan --corrections FILE`) apply before marking:
//
//   {"format": "epure-corrections", "version": 1,
//    "corrections": [{"sheet": "1000-0005-001Q", "question": "3.t_proj", "value": "−17",
//                     "note": "read from the scan"},
//                    {"sheet": "1000-0005-002N", "question": "student_number", "value": "21804512"}]}
//
// `sheet` is a sheet id (any case, with or without dashes), `question` a question id of that
// sheet or "student_number", `value` the text as a student would type it (a number "4,75", a
// point's coordinate, "oui", "avant A", "+x −y"; "" for an answer left empty), `note` optional.
// Keys this version does not know are ignored, so that a later writer may add some. A file that
// is not this format stops the reading with its reason; an entry that is wrong (a missing
// field, a value that is not a string) is reported with its number and skipped, the rest applied.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "exercises/texts.h"

namespace epure::grading {

inline constexpr std::string_view kCorrectionsFormat = "epure-corrections";
inline constexpr int kCorrectionsVersion = 1;
// Limits (README, "Limits"): a file is read whole; the review page of a class writes a few kB.
inline constexpr std::size_t kMaxCorrectionsBytes = std::size_t(64) << 20;  // 64 MiB
inline constexpr int kMaxCorrectionsDepth = 16;
inline constexpr std::size_t kMaxCorrectionValueBytes = 4096;

struct Correction {
  int entry = 0;  // 1-based place in "corrections", for messages
  std::string sheet;     // as written
  std::string question;  // a question id, or "student_number"
  std::string value;
  std::string note;
};

// A problem as a code and its values: the teacher reads it in the set's language
// (templates/text/<lang>/grading.toml, [grading.corrections]: "entry 3: 'value' must be …").
struct CorrectionsProblem {
  int entry = 0;     // 0: the file as a whole
  std::string code;  // "not_json", "format", "missing", "not_string", …
  TextVars vars;     // "entry", "field", "type" (a code: string, number, boolean, null, list, object), …
};

// The problem in words, for a message that names the file: "entry 3: 'value' is missing".
std::string describe(const CorrectionsProblem& p, const Texts& texts);

struct Corrections {
  std::string source;  // the file's name, for messages
  std::vector<Correction> entries;
  std::vector<CorrectionsProblem> problems;
  // Whether the file as a whole could be read (its format, version and list); entries are
  // applied only then.
  bool readable = false;
};

// Reads a corrections file's text. Never throws for bad content: every problem is in `problems`.
Corrections read_corrections(std::string_view text, std::string_view source);
// The same from a file, named by its path in messages; a file past kMaxCorrectionsBytes is refused
// before it is read (a problem). Throws std::runtime_error naming it when it cannot be opened.
Corrections read_corrections_file(const std::filesystem::path& path);

// The entries as a corrections file, in the canonical shape (2-space indented, keys in the
// format's order, UTF-8 as is): what review pages and tests write. Reads back to the same entries.
std::string corrections_json(std::span<const Correction> entries);

}  // namespace epure::grading
