#pragma once
// --json FILE.json: everything the run found, for other tools. One object: the answers file,
// the key's seed and versions, the marking settings (follow-through, the mark's scale and
// rounding), "submissions" (every row read: line, sheet, student, student number, score, max,
// mark, points held to check, flags, its exercises with their branch and points, and per
// question its id, expected, given, verdict, points, feedback, mistake code, how it was read
// and the answers a follow-through came from), then "statistics" (with "items": the item
// analysis, item_analysis.h), "problems" and the exit status. Codes (verdicts, mistakes, flags,
// branches) are codes here; their names in the set's language sit beside them where a reader
// shows them. Streamed and written atomically.
#include <filesystem>
#include <memory>

#include "grading/feedback_text.h"
#include "grading/mark_scale.h"
#include "grading/submission.h"

namespace epure::grading {

class JsonReport final : public SubmissionSink {
 public:
  JsonReport(const std::filesystem::path& path, const AnswerKey& key, const FeedbackText& text,
             std::string_view answers_name, bool follow_through, MarkScale scale);
  ~JsonReport() override;
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epure::grading
