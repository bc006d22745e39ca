#pragma once
// --class-report DIR: the class at a glance for the teacher, in the set's language, as one HTML
// page (DIR/class-report.html: self-contained, its plots inline SVG) and its PDF
// (DIR/class-report.pdf, laid out and drawn like the sheets: render/layout.h, the cairo
// backend). Both show the same plots (class_plots.h: the marks' distribution, each exercise's
// questions by facility and discrimination, its branches compared and its named mistakes), the
// figures the summary gives (marks, Cronbach's α, follow-through, branches significantly harder),
// the answers still to check, every student's mark, and how each figure is computed. The HTML
// page adds the full tables (every question, branch and mistake with its numbers).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "grading/class_words.h"
#include "grading/feedback_text.h"
#include "grading/mark_scale.h"
#include "grading/submission.h"
#include "render/document.h"

namespace epure::grading {

class ClassReport final : public SubmissionSink {
 public:
  ClassReport(std::filesystem::path dir, const AnswerKey& key, const FeedbackText& text, MarkScale scale);
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

  // The PDF's document (for tests); valid after finish().
  const render::Document& document() const { return doc_; }
  const std::string& html() const { return html_; }

 private:
  struct Row {
    int line = 0;
    std::string sheet, student;
    bool marked = false;
    double score = 0, max = 0, mark = 0, held = 0;
    std::vector<std::string> to_check;  // "2.t “2,5??” is not a number"
    std::vector<std::string> flags;     // names
  };
  void build(const ClassStatistics& stats, const Outcome& outcome);

  std::filesystem::path dir_;
  const AnswerKey& key_;
  const FeedbackText& text_;
  ClassWords words_;
  MarkScale scale_;
  std::vector<Row> rows_;
  render::Document doc_;
  std::string html_;
};

}  // namespace epure::grading
