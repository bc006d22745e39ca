#pragma once
// --report FILE.csv: one row per submission (every row read, marked or not): sheet, student,
// score, max, the mark out of N when marks have a scale (mark_scale.h: "note/20"), the points
// held to check, then the points of each question id of the key (empty where the sheet does
// not ask it, "?" for an answer to check), then the row's line in the answers file and its
// flags. The header's words and the flags are in the set's language (a teacher opens this in a
// spreadsheet); the question ids are the sheet's. Written in the answers' own dialect, so that
// it opens in the teacher's spreadsheet as their export did: the same delimiter, a decimal
// comma with semicolons (the French export convention), a BOM if theirs had one. Streamed and
// written atomically.
#include <filesystem>
#include <memory>
#include <string>

#include "grading/class_words.h"
#include "grading/mark_scale.h"
#include "grading/submission.h"

namespace epure::grading {

struct CsvDialect {
  char delimiter = ',';
  bool decimal_comma = false;
  bool bom = false;
  bool crlf = false;
};

class CsvReport final : public SubmissionSink {
 public:
  CsvReport(const std::filesystem::path& path, const AnswerKey& key, CsvDialect dialect, const Texts& texts,
            MarkScale scale);
  ~CsvReport() override;
  void submission(const Submission& s) override;
  // Writes the last bytes and renames the file into place.
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epure::grading
