#pragma once
// --report FILE.csv: one row per submission (every row read, marked or not): sheet, student,
// score, max, the mark out of the spec's scale when it has one ("mark/20"), then the points of each question id of the key (empty where the sheet does not
// ask it), then the row's line in the answers file and its flags. Written in the answers'
// own dialect, so that it opens in the teacher's spreadsheet as their export did: the same
// delimiter, a decimal comma with semicolons (the French export convention), a BOM if theirs
// had one. Streamed and written atomically.
#include <filesystem>
#include <memory>
#include <string>

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
  CsvReport(const std::filesystem::path& path, const AnswerKey& key, CsvDialect dialect);
  ~CsvReport() override;
  void submission(const Submission& s) override;
  // Writes the last bytes and renames the file into place.
  void finish(const ClassStatistics& stats, const Outcome& outcome) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epure::grading
