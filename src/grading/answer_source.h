#pragma once
// Where answers come from: a CSV export (csv_reader.h) or JSON (an array of objects, or JSON
// Lines: one object per line), pushed row by row to a handler, so that no file is held whole.
// A JSON object is {"sheet": …, "student": …, "1.t": …} or keeps its answers under "answers";
// a value [x, y] under "1.P" answers "1.P.x" and "1.P.y", a list of strings is a face set.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace epure::grading {

// How deep a JSON answers file may nest (README, "Limits"): a record is two levels deep (three
// with "answers"), a point or a face list one more. Deeper, the reading stops (an array) or the
// line is a row that is not an object (JSON Lines), before a file of [[[[… builds a tree of
// gigabytes (20 MB of '[' took 4 GB).
inline constexpr int kMaxJsonDepth = 64;

struct AnswerRow {
  int line = 0;       // CSV: the physical line; JSON: the line (JSON Lines) or the record number
  int last_line = 0;
  std::span<const std::string_view> cells;  // by column of the latest header
  std::string_view problem;                 // a reading problem's code, or empty
};

struct SourceInfo {
  std::string format;            // "csv", "json" or "jsonl"
  std::string_view unit = "line";  // how positions are named: "line" or "record"
  char delimiter = ',';
  bool bom = false;
  bool crlf = false;
  int blank_lines = 0;
  int rows = 0;
  std::string stopped;  // non-empty when reading stopped early (a JSON syntax error): why
};

class RowHandler {
 public:
  virtual ~RowHandler() = default;
  // The column names (CSV: the header row; JSON: every name seen so far, growing).
  virtual void header(const std::vector<std::string>& names, int line) = 0;
  virtual void row(const AnswerRow& row) = 0;
  // After header(): how many leading cells of each row it reads (a CSV row is split no further).
  virtual std::size_t cells_needed() const { return static_cast<std::size_t>(-1); }
};

// The format by the first character after blanks and a byte-order mark ('[' or '{': JSON).
// Throws std::runtime_error naming the file for a file that cannot be opened or is UTF-16.
// A file with no header (empty) calls nothing; `info.rows` is then 0.
SourceInfo read_answers(const std::filesystem::path& path, RowHandler& handler,
                        std::optional<char> delimiter = std::nullopt);

// The same from text held in memory, named `name` (tests).
SourceInfo read_answers_text(std::string text, std::string_view name, RowHandler& handler,
                             std::optional<char> delimiter = std::nullopt);

}  // namespace epure::grading
