#pragma once
// --feedback DIR: a marked sheet for each student, as SVG pages and as a PDF: per exercise the key's construction diagram with the student's wrong points and
// vectors drawn beside the right ones, then every question with their answer, the expected
// one, the points, and why (the named mistake, the follow-through it earned). A row that
// could not be marked still gets a page saying why. Also class.svg, the score histogram.
// Files are named by sheet id (a sheet submitted twice: "-line<N>" after the id), written
// atomically.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include "grading/feedback_text.h"
#include "grading/key_diagrams.h"
#include "grading/mark_scale.h"
#include "grading/scanned_crops.h"
#include "grading/submission.h"
#include "render/document.h"

namespace epure::grading {

// The marked sheet of one submission, as a document (separate from the files, for tests).
// `crops`: the scanned fields (epure scan --crops), each drawn under its question's prompt.
render::Document feedback_document(const Submission& s, const AnswerKey& key, const FeedbackText& text,
                                   KeyDiagrams* diagrams, const MarkScale& scale, const ScannedCrops* crops = nullptr);

// Grows a panel's view to hold p (a student's point) when it is near enough to be drawn in the
// same frame (within twice the view's size); false, and the view unchanged, when it is not.
bool make_room(render::Panel& panel, render::P2 p);

// A scene with the student's wrong points and vectors of one exercise added to `scene`.
void overlay_answers(render::Scene& scene, const ExerciseKey& ex, const ExerciseMarks& marks,
                     const FeedbackText& text);

class FeedbackSheets final : public SubmissionSink {
 public:
  FeedbackSheets(std::filesystem::path dir, const AnswerKey& key, const FeedbackText& text, MarkScale scale,
                 ScannedCrops crops = ScannedCrops({}));
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;
  int written() const { return written_; }

 private:
  std::filesystem::path dir_;
  const AnswerKey& key_;
  const FeedbackText& text_;
  MarkScale scale_;
  KeyDiagrams diagrams_;
  ScannedCrops crops_;
  std::optional<std::int64_t> pdf_date_;  // SOURCE_DATE_EPOCH, read once
  int written_ = 0;
};

}  // namespace epure::grading
