#pragma once
// One marked row of the answers, as every output sees it, and the interface of those outputs
// (CSV report, JSON, summary, feedback sheets): each gets the submissions one by one as they
// are marked, then the class's statistics once at the end.
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grading/answer_key.h"
#include "grading/marks.h"

namespace epure::grading {

class ClassStatistics;
struct Outcome;

// Why a row was flagged: a code for machines ("duplicate") and a sentence for people.
struct Flag {
  std::string_view code;
  std::string message;
};

struct Submission {
  int line = 0, last_line = 0;  // where the row is in the answers file
  std::string_view sheet_text;  // the sheet id as written
  std::string student;          // as written (UTF-8)
  std::string student_number;   // the student number column's, as written (or corrected)
  const SheetKey* sheet = nullptr;  // null: the row could not be marked (see flags)
  std::span<const ExerciseMarks> marks;  // one per exercise of the sheet
  // For each exercise, each question: its column in the report (index in key.question_ids()).
  std::span<const std::vector<int>> report_index;
  double score = 0;  // the points given; points held (to check) are not in it
  double max = 0;
  double held = 0;   // the points of the answers to check: neither given nor refused yet
  int to_check = 0;  // how many answers are to check
  std::vector<Flag> flags;

  bool marked() const { return sheet != nullptr; }
  // Marked, with nothing left to check: its score is final.
  bool settled() const { return marked() && to_check == 0; }
  bool flagged(std::string_view code) const {
    for (const auto& f : flags)
      if (f.code == code) return true;
    return false;
  }
};

class SubmissionSink {
 public:
  virtual ~SubmissionSink() = default;
  virtual void submission(const Submission& s) = 0;
  // After the last submission: the statistics and what went wrong, for a closing section.
  virtual void finish(const ClassStatistics& stats, const Outcome& outcome) = 0;
};

}  // namespace epure::grading
