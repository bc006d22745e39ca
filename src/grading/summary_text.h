#pragma once
// The readable summary on stdout, in the set's language: one line per submission (line, sheet,
// student, score and mark, what was not right and why in a few words: the named mistake, the
// follow-through, what is to check), then the class: scores and marks, what is still to check,
// the item analysis (facility and discrimination per question, Cronbach's α, branches
// significantly harder than the others, named mistakes, follow-through credit) and the
// problems counted. With `rows` false (a report file holds the rows) only the class part is
// printed. Codes (mistakes, flags) are the JSON report's; here every word is the language's.
#include <cstdio>

#include "grading/class_words.h"
#include "grading/feedback_text.h"
#include "grading/mark_scale.h"
#include "grading/submission.h"

namespace epure::grading {

class TextSummary final : public SubmissionSink {
 public:
  TextSummary(std::FILE* out, const AnswerKey& key, const FeedbackText& text, MarkScale scale, bool rows);
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

 private:
  std::string score(double x) const;    // points as the language writes them, to hundredths
  std::string percent(double x) const;  // "62.5%", "62,5 %"

  std::FILE* out_;
  const AnswerKey& key_;
  const FeedbackText& text_;
  ClassWords words_;
  MarkScale scale_;
  bool rows_;
  bool header_done_ = false;
};

}  // namespace epure::grading
