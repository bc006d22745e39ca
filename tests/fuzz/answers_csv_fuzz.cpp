// The answers CSV (src/grading/answer_source.cpp, csv_reader.cpp, encoding.cpp): rows in = rows
// reported; parse → write → parse gives the same header and cells; a cell that is not UTF-8
// becomes valid UTF-8 as Windows-1252, and valid_utf8 agrees with a plain reading of RFC 3629.
#include <cstdint>
#include <optional>

#include "answers_support.h"
#include "grading/csv_reader.h"
#include "grading/encoding.h"

using namespace epure;
using namespace epure::grading;

namespace {

// RFC 3629 as written (table in its section 4): no overlong forms, no surrogates, ≤ U+10FFFF.
bool reference_utf8(std::string_view s) {
  std::size_t i = 0;
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const auto tail = [&](std::size_t k) { return k < s.size() && (at(k) & 0xc0) == 0x80; };
  while (i < s.size()) {
    const unsigned c = at(i);
    if (c < 0x80) { ++i; continue; }
    if (c >= 0xc2 && c <= 0xdf) {
      if (!tail(i + 1)) return false;
      i += 2;
    } else if (c >= 0xe0 && c <= 0xef) {
      if (!tail(i + 1) || !tail(i + 2)) return false;
      const unsigned d = at(i + 1);
      if (c == 0xe0 && d < 0xa0) return false;  // overlong
      if (c == 0xed && d > 0x9f) return false;  // a surrogate
      i += 3;
    } else if (c >= 0xf0 && c <= 0xf4) {
      if (!tail(i + 1) || !tail(i + 2) || !tail(i + 3)) return false;
      const unsigned d = at(i + 1);
      if (c == 0xf0 && d < 0x90) return false;  // overlong
      if (c == 0xf4 && d > 0x8f) return false;  // past U+10FFFF
      i += 4;
    } else {
      return false;
    }
  }
  return true;
}

std::string quote_cell(std::string_view cell) {
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // the first byte: the delimiter forced (as --delimiter) or detected
  std::optional<char> delimiter;
  switch (data[0] % 4) {
    case 1: delimiter = ','; break;
    case 2: delimiter = ';'; break;
    case 3: delimiter = '\t'; break;
  }
  std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  // the CSV reader itself, whatever the first character (read_answers sends '[' and '{' to JSON)
  fuzz::Recorder rec;
  int rows = 0;
  char used = ',';
  try {
    CsvReader reader = CsvReader::from_text(text, delimiter);
    CsvRecord r;
    bool header = true;
    while (reader.next(r)) {
      const std::vector<std::string_view> cells(r.cells.begin(), r.cells.end());
      if (header) {
        rec.header(std::vector<std::string>(cells.begin(), cells.end()), r.line);
        header = false;
      } else {
        ++rows;
        rec.row(AnswerRow{r.line, r.last_line, cells, r.problem});
      }
      bool each = true;
      for (auto c : cells) {
        const bool v = valid_utf8(c);
        fuzz::check(v == reference_utf8(c), "valid_utf8 disagrees with RFC 3629", c);
        each = each && v;
        if (!v) fuzz::check(valid_utf8(cp1252_to_utf8(c)), "Windows-1252 read as UTF-8 is not UTF-8", c);
      }
      fuzz::check(all_valid_utf8(cells) == each, "all_valid_utf8 disagrees with valid_utf8 cell by cell");
    }
    used = reader.delimiter();
  } catch (const std::runtime_error& e) {
    const std::string_view what = e.what();
    fuzz::check(what.find("UTF-16") != std::string_view::npos || what.find("line ") != std::string_view::npos,
                "a CSV error names neither the line nor the encoding", what);
    return 0;
  }
  // read_answers_text hands the same rows over (when it takes the text as CSV)
  const char first = [&] {
    std::string_view h = text;
    if (h.substr(0, 3) == "\xef\xbb\xbf") h.remove_prefix(3);
    const auto i = h.find_first_not_of(" \t\r\n");
    return i == std::string_view::npos ? '\0' : h[i];
  }();
  if (first != '[' && first != '{') {
    fuzz::Recorder via;
    const SourceInfo info = read_answers_text(text, "fuzz.csv", via, delimiter);
    fuzz::check(info.rows == static_cast<int>(via.rows.size()), "rows in ≠ rows reported");
    fuzz::check(info.rows == rows && via.rows == rec.rows && via.names == rec.names,
                "read_answers_text and CsvReader disagree");
  }
  // parse → write → parse: every cell quoted, the delimiter the reader used, one record a line
  if (rec.headers == 0) return 0;
  bool clean = true;  // a record read leniently is not written back as it was read
  for (const auto& p : rec.problems) clean = clean && p.empty();
  if (!clean) return 0;
  std::string written;
  const auto write = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) written += (i ? std::string(1, used) : "") + quote_cell(cells[i]);
    written += "\r\n";
  };
  write(rec.names);
  for (const auto& r : rec.rows) write(r);
  fuzz::Recorder back;
  CsvReader again = CsvReader::from_text(written, used);
  CsvRecord r;
  bool header = true;
  while (again.next(r)) {
    std::vector<std::string> cells(r.cells.begin(), r.cells.end());
    if (header) {
      back.names = cells;
      header = false;
    } else {
      back.rows.push_back(cells);
    }
  }
  std::vector<std::vector<std::string>> expected;
  for (const auto& row : rec.rows) expected.push_back(row);
  fuzz::check(back.names == rec.names && back.rows == expected, "CSV parse → write → parse changed the cells", written);
  return 0;
}
