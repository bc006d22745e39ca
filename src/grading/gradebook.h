#pragma once
// --gradebook moodle|csv FILE: the marks, one per student, for the school's gradebook.
//
// moodle: what Moodle's grade import (Grades → Import → CSV file) takes: a header row, then one
//   row per student with their ID number, e-mail address (where known), name and mark, comma
//   separated, decimal point (Moodle reads it whatever the site's language), UTF-8. Moodle's
//   importer keeps the previous row's student when a row's identifier is empty and aborts the
//   whole import on a student it does not know (grade/import/csv/classes/load_data.php), so a
//   row is written only for a student identified by a student number: from the roster
//   (`--roster`) when there is one, else from the answers' student number column; a sheet with
//   answers still to check is left out (its mark is not final), and so is a student who has no
//   sheet (Moodle keeps their grade as it is).
// csv: every student and every row, in the set's language and dialect (a French set: ';' and
//   decimal commas, a BOM for Excel): student number, name, e-mail, sheet, points, maximum,
//   mark, status (marked, to check, absent, not marked, not in the roster).
//
// Students are found by the answers' student number, else by their name (words in any order,
// without case or accents; a name two students share is never matched), else by an e-mail typed
// as the name. Two marked sheets for one student: the later row is kept, and said. Each
// student left out is said once, with the line of their row.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "grading/class_words.h"
#include "grading/mark_scale.h"
#include "grading/roster.h"
#include "grading/submission.h"

namespace epure::grading {

enum class GradebookFormat { moodle, csv };

class Gradebook final : public SubmissionSink {
 public:
  using Report = std::function<void(int line, std::string message, bool error)>;
  Gradebook(std::filesystem::path path, GradebookFormat format, const AnswerKey& key, const Texts& texts,
            MarkScale scale, const Roster* roster, Report report);
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;
  int written() const { return written_; }

 private:
  struct Row {
    int line = 0;
    std::string sheet, student, number;
    bool marked = false;
    int to_check = 0;
    double score = 0, max = 0, mark = 0;
  };
  std::filesystem::path path_;
  GradebookFormat format_;
  const AnswerKey& key_;
  ClassWords words_;
  MarkScale scale_;
  const Roster* roster_;
  Report report_;
  std::vector<Row> rows_;
  int written_ = 0;
};

}  // namespace epure::grading
