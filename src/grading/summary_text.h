#pragma once
// The readable summary on stdout: one line per submission (line, sheet, student, score, what
// was wrong and why in a word: the mistake codes), then the class: mean, median, range,
// per-question success rates, the most frequent mistakes, and the problems counted. With
// `rows` false (a report file holds the rows) only the class part is printed.
#include <cstdio>

#include "grading/feedback_text.h"
#include "grading/submission.h"

namespace epure::grading {

class TextSummary final : public SubmissionSink {
 public:
  TextSummary(std::FILE* out, const AnswerKey& key, const FeedbackText& text, bool rows);
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

 private:
  std::string score(double x) const;    // points as the language writes them, to hundredths
  std::string percent(double x) const;  // "62.5%", "62,5 %"

  std::FILE* out_;
  const AnswerKey& key_;
  const FeedbackText& text_;
  bool rows_;
  bool header_done_ = false;
};

}  // namespace epure::grading
