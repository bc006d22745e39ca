#pragma once
// A worksheet spec: the hand-edited TOML file a teacher writes (templates/course.toml is the
// built-in one). Parsing validates everything against the exercise kinds, and an error names the
// file, the line and the key, so that a typo never silently becomes a default.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace epure {

enum class Difficulty { easy, standard, hard };
std::string_view to_string(Difficulty d);
std::optional<Difficulty> parse_difficulty(std::string_view s);

// Per-question settings, by the question's field ("t", "P" for both P.x and P.y, "faces").
struct QuestionSpec {
  std::optional<double> points;  // the question's weight (default: its work, method.h's work_of)
  std::optional<double> rel;  // overrides the derived relative tolerance
  std::optional<double> abs;  // overrides the derived absolute tolerance (a floor)
  bool whole_point = false;   // mark a point by its distance to the expected point, as a whole
};

struct ExerciseSpec {
  std::string kind;
  Difficulty difficulty = Difficulty::standard;
  std::vector<std::pair<std::string, double>> branches;  // empty: the kind's defaults
  std::map<std::string, QuestionSpec> questions;
  std::map<std::string, double> constraints;  // overrides of the kind's defaults
  // What the exercise is worth on every sheet, shared by the questions its branch asks in
  // proportion to their weights; unset: it adds the kind's default_points() to the sheet's total,
  // which the questions of every such exercise share by weight across the sheet (points.h).
  std::optional<double> points;
  // What the sheet calls it instead of "Exercise n" ("Preamble", "Open question 1"), in the
  // spec's language and per language as given; empty: numbered. Exercises without a heading of
  // their own are numbered 1, 2, … in order, as the course numbers its exercises.
  std::string heading;
  std::map<std::string, std::string> heading_by_language;
  std::string heading_in(std::string_view language) const;
  // The exercise's number in every place that names it: its questions' ids ("3.3" gives
  // 3.3.t, printed beside the field, the answers CSV's column, key.json), and "Exercise n" when
  // it has no heading. Letters, digits and inner dots ("P", "3.3"). Empty as written: see
  // exercise_id, which parse_spec fills in.
  std::string number;
};

// The spec's own words, printed on every page and in the PDF's metadata.
struct SpecWords {
  std::string title;
  std::string course;
  std::string author;
  std::string subject;
};

// At most this many [[exercise]] tables in a spec (README, "Limits"): the course has 8, a long
// exam 20; more is a mistake, refused before any sheet is drawn (20,000 ran out of memory).
inline constexpr std::size_t kMaxExercises = 100;
// The student number's comb: from 4 cells to 12, what the first page's header row holds beside
// the name's writing line.
inline constexpr int kMinStudentNumberDigits = 4;
inline constexpr int kMaxStudentNumberDigits = 12;

struct WorksheetSpec {
  std::string source;  // where it was read from, for messages
  // In the spec's language. Each may also be written per language, `title = { en = "…",
  // fr = "…" }`, so that one spec serves `--lang en` and `--lang fr`: see words_in.
  std::string title;
  std::string course;
  std::string author;
  std::string subject;
  std::map<std::string, SpecWords> words_by_language;  // only the languages the file names

  // The words to print in `language`: those the file gives for it, the spec language's for the
  // rest (a teacher who translates only the title still gets a course line).
  SpecWords words_in(std::string_view language) const;
  std::string language = "en";
  std::string page = "A4";  // "A4" or "letter"
  int decimals = 2;         // students round data-derived answers to this many decimals
  // The cells of the student number's comb on a sheet made without a roster (a university's
  // numbers are 8 digits in France, up to 10 or 12 elsewhere).
  int student_number_digits = 8;
  bool follow_through = true;
  // Reports also give the mark out of this (20 for the French "note sur 20"); unset: points only.
  std::optional<double> scale;
  std::vector<ExerciseSpec> exercises;
  std::string text;  // the spec's own text, as read (travels in key.json)
};

class SpecError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The number the sheet gives the exercise in `slot` when it has no heading of its own: 1 + the
// unheaded exercises before it.
int exercise_number(const WorksheetSpec& spec, std::size_t slot);
// The exercise's number as its ids and heading use it: the spec's `number`, else for an
// exercise without a heading its exercise_number ("Exercise 2" asks 2.t), else its place on the
// sheet (1-based) — or "s" and that place when another exercise already has that number (a
// spec written before `number` existed, with a "Preamble" first, still reads). parse_spec checks
// that no two exercises share one.
std::string exercise_id(const WorksheetSpec& spec, std::size_t slot);

// Throws SpecError "<source>:<line>:<column>: key '<key>': <why>".
WorksheetSpec parse_spec(std::string_view toml_text, std::string_view source_name);
// The course's worksheet, built in (templates/course.toml).
WorksheetSpec builtin_spec();
// A built-in spec by its command-line name: "builtin" (the course, templates/course.toml) or
// "builtin:3d" (the course in space, templates/course-3d.toml); nothing for another name.
std::optional<WorksheetSpec> builtin_spec(std::string_view name);
// The built-in specs, the course's first.
std::vector<WorksheetSpec> builtin_specs();
// Their command-line names, in the same order ("builtin", "builtin:3d"): the one list the
// options' checks, the manual pages and the shell completion read.
std::vector<std::string> builtin_spec_names();

}  // namespace epure
