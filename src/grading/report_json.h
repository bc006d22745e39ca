#pragma once
// --json FILE.json: everything the run found, for other tools. One object: the answers file,
// the key's seed and versions, the marking settings, "submissions" (every row read: line,
// sheet, student, score, max, flags, and per question its id, expected, given, verdict,
// points, feedback, mistake code and the answers a follow-through came from), then
// "statistics", "problems" and the exit status. Streamed and written atomically.
#include <filesystem>
#include <memory>

#include "grading/feedback_text.h"
#include "grading/submission.h"

namespace epure::grading {

class JsonReport final : public SubmissionSink {
 public:
  JsonReport(const std::filesystem::path& path, const AnswerKey& key, const FeedbackText& text,
             std::string_view answers_name, bool follow_through);
  ~JsonReport() override;
  void submission(const Submission& s) override;
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epure::grading
