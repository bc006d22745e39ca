#pragma once
// A grading run: the answers' rows come in one by one (answer_source.h), each is matched to its
// sheet of the key, marked exercise by exercise (marking.h), flagged where something is off,
// counted in the class statistics and handed to the outputs; nothing is kept per row, so a
// run's memory does not grow with the number of rows.
//
// Nothing is silently lost: every row read is a row reported (marked, or flagged with why
// not), and every problem is logged with the file and line: an unknown or mistyped sheet id
// (with the nearest id of the key), a sheet submitted twice (both marked and flagged), a
// column that is not a question (warned once), an unreadable value (marked wrong as
// "unreadable: …"), a ragged row, a malformed quote, an answer to a question the sheet does
// not ask. Errors (data that could not be read) make the exit status 1; warnings do not.
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "exercises/numbers.h"
#include "exercises/texts.h"
#include "grading/answer_key.h"
#include "grading/answer_source.h"
#include "grading/corrections.h"
#include "grading/marking.h"
#include "grading/statistics.h"
#include "grading/submission.h"

namespace epure::grading {

struct Problem {
  int line = 0;  // 0: about the file or the key as a whole
  std::string message;
  bool error = true;
  std::string file;  // the file it is about when not the answers file (the corrections file)
};

// How the run went, for the outputs' closing sections and the exit status.
struct Outcome {
  std::string answers;   // the answers file's name
  SourceInfo source;
  bool follow_through = true;
  std::string language;  // of the feedback
  int rows = 0;          // rows read = rows reported
  int marked = 0;
  int empty_rows = 0;    // rows whose every cell is empty: not submissions, skipped
  int to_check_rows = 0; // marked rows with answers to check (points held)
  int to_check = 0;      // answers to check, in all
  int corrections_applied = 0;  // cells whose text came from the corrections file
  int errors = 0, warnings = 0;
  std::vector<Problem> problems;  // the first kKeptProblems
  int problems_not_kept = 0;
  std::vector<std::pair<std::string, std::vector<int>>> duplicates;  // sheet → its first lines

  int exit_status() const { return errors > 0 ? 1 : 0; }
};

inline constexpr std::size_t kKeptProblems = 10000;
// Problems of one kind printed before the rest of that kind is only counted.
inline constexpr int kPrintedPerKind = 50;

struct SessionOptions {
  std::string answers_name;  // for messages: "answers.csv"
  std::optional<bool> follow_through;  // overrides the key's spec
  std::string language;      // "" for the key's
  std::FILE* log = stderr;   // where problems are printed as they occur (null: not printed)
  // How many rows carry each sheet (canonical id), from a first pass: a sheet submitted twice
  // is flagged on both rows. Without it, only the later rows are flagged.
  std::unordered_map<std::string, int> sheet_counts;
  // The teacher's corrections (corrections.h), applied to the cells before marking; null: none.
  const Corrections* corrections = nullptr;
};

class GradingSession final : public RowHandler {
 public:
  GradingSession(const AnswerKey& key, SessionOptions options);

  void add_sink(SubmissionSink& sink) { sinks_.push_back(&sink); }
  // A problem of the run found outside the rows (the key's version, …).
  void problem(int line, std::string message, bool error, std::string_view kind = "other", std::string_view file = {});

  void header(const std::vector<std::string>& names, int line) override;
  void row(const AnswerRow& row) override;
  // Closes the run: duplicates and reading notes logged, every sink's finish() called.
  const Outcome& finish(const SourceInfo& source);

  const ClassStatistics& statistics() const { return stats_; }
  const Outcome& outcome() const { return outcome_; }
  bool follow_through() const { return marking_.follow_through; }
  const Texts& texts() const { return texts_; }

 private:
  struct SheetColumns {
    std::vector<std::vector<int>> column;        // [exercise][question] → answers column or −1
    std::vector<std::vector<int>> report_index;  // [exercise][question] → question id index
    std::vector<char> asked;                     // by answers column: a question of this sheet
  };
  const SheetColumns& columns_for(const SheetKey& sheet);
  void flag(Submission& s, std::string_view code, std::string message, bool error);
  void take_corrections(const Corrections& corrections);

  // A correction of one sheet's cell, resolved against the key: the question's index in
  // key.question_ids(), or kStudentNumber.
  struct SheetCorrection {
    int question = 0;
    std::string_view value;  // in options_.corrections
    int entry = 0;
  };
  static constexpr int kStudentNumber = -1;

  const AnswerKey& key_;
  SessionOptions options_;
  const Texts& texts_;  // the set's language (or --lang): every message a teacher or student reads
  MarkingOptions marking_;
  Outcome outcome_;
  ClassStatistics stats_;
  std::vector<SubmissionSink*> sinks_;
  std::map<std::string, int, std::less<>> printed_;  // per kind of problem

  // the header
  std::vector<std::string> names_;
  int header_line_ = 0;
  int sheet_column_ = -1, student_column_ = -1, student_number_column_ = -1;
  // A point typed whole under its own name ("2.P" beside, or instead of, "2.P.x" and "2.P.y"):
  // by question id index of its first coordinate → that column, or −1.
  std::vector<int> point_column_;
  // by sheet index: the corrections of its cells (empty for most)
  std::unordered_map<std::size_t, std::vector<SheetCorrection>> corrections_;
  std::vector<char> correction_used_;  // by entry − 1
  std::vector<int> question_column_;  // by question id index → answers column or −1
  std::vector<int> column_question_;  // by answers column → question id index or −1
  std::map<std::string, bool, std::less<>> warned_columns_;
  std::vector<const SheetColumns*> columns_;  // by sheet index, found on first use
  // One SheetColumns per layout of questions (sheets of one branch ask the same ids), shared by
  // every sheet of that layout: a few of them stay in cache while rows visit a thousand sheets.
  std::map<std::vector<std::vector<int>>, std::unique_ptr<SheetColumns>> layouts_;

  // per row, reused
  Submission current_;
  std::vector<ExerciseMarks> marks_;
  std::vector<std::string_view> cells_;
  std::vector<std::string> transcoded_;
  std::vector<std::string_view> transcoded_views_;
  std::vector<int> counts_;      // by sheet index: rows carrying it (first pass)
  std::vector<int> first_line_;  // by sheet index: where it was first seen, 0 not yet
  // sheet → the first lines it is on, and how many more
  std::map<std::string, std::pair<std::vector<int>, int>> duplicate_lines_;
  static constexpr std::size_t kNamedLines = 10;
  bool transcoded_warned_ = false;
};

}  // namespace epure::grading
