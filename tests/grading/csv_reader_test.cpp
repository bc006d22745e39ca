// The CSV reader on what spreadsheets write: delimiters detected, BOM, CRLF, RFC 4180 quoting,
// line numbers across quoted line breaks, the lenient cases; and a round trip of random cells
// over many seeds.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "exercises/rng.h"
#include "grading/csv_reader.h"

using epure::grading::CsvReader;
using epure::grading::CsvRecord;

namespace {
std::vector<std::vector<std::string>> all(CsvReader& r, std::vector<int>* lines = nullptr) {
  std::vector<std::vector<std::string>> out;
  CsvRecord rec;
  while (r.next(rec)) {
    out.emplace_back(rec.cells.begin(), rec.cells.end());
    if (lines) lines->push_back(rec.line);
  }
  return out;
}
using Rows = std::vector<std::vector<std::string>>;
}  // namespace

TEST_CASE("the delimiter comes from the header") {
  SUBCASE("comma") { CHECK(CsvReader::from_text("sheet,1.t\na,b\n").delimiter() == ','); }
  SUBCASE("semicolon") { CHECK(CsvReader::from_text("sheet;1.t;1.P.x\n").delimiter() == ';'); }
  SUBCASE("tab") { CHECK(CsvReader::from_text("sheet\t1.t\n").delimiter() == '\t'); }
  SUBCASE("inside quotes it does not count") { CHECK(CsvReader::from_text("\"a,b,c\";x\n").delimiter() == ';'); }
  SUBCASE("one column: comma") { CHECK(CsvReader::from_text("sheet\n").delimiter() == ','); }
}

TEST_CASE("a spreadsheet export: BOM, CRLF, quotes, accents, commas in names") {
  auto r = CsvReader::from_text("\xef\xbb\xbfsheet;student;1.t\r\n"
                                "1000-0001-000X;\"Lefèvre, Zoé\";0,25\r\n"
                                "1000-0001-001V;\"O'Brien, \"\"Shane\"\"\";\r\n");
  std::vector<int> lines;
  const Rows rows = all(r, &lines);
  CHECK(r.had_bom());
  CHECK(r.crlf());
  CHECK(rows == Rows{{"sheet", "student", "1.t"},
                     {"1000-0001-000X", "Lefèvre, Zoé", "0,25"},
                     {"1000-0001-001V", "O'Brien, \"Shane\"", ""}});
  CHECK(lines == std::vector<int>{1, 2, 3});
}

TEST_CASE("a quoted line break keeps the record whole and the line count right") {
  auto r = CsvReader::from_text("a,b\n\"two\nlines\",x\nc,d\n");
  std::vector<int> lines;
  CHECK(all(r, &lines) == Rows{{"a", "b"}, {"two\nlines", "x"}, {"c", "d"}});
  CHECK(lines == std::vector<int>{1, 2, 4});
}

TEST_CASE("blank lines are skipped and counted; a missing final newline is fine") {
  auto r = CsvReader::from_text("a,b\n\n\r\nc,d");
  std::vector<int> lines;
  CHECK(all(r, &lines) == Rows{{"a", "b"}, {"c", "d"}});
  CHECK(lines == std::vector<int>{1, 4});
  CHECK(r.blank_lines() == 2);
}

TEST_CASE("lenient cases, each reported") {
  CsvRecord rec;
  SUBCASE("a quote inside an unquoted cell is a character") {
    auto r = CsvReader::from_text("a,b\n5\",x\n");
    REQUIRE(r.next(rec));
    REQUIRE(r.next(rec));
    CHECK(std::string(rec.cells[0]) == "5\"");
    CHECK(rec.problem.empty());
  }
  SUBCASE("text after a closing quote") {
    auto r = CsvReader::from_text("a,b\n\"x\"y,z\n");
    REQUIRE(r.next(rec));
    REQUIRE(r.next(rec));
    CHECK(std::string(rec.cells[0]) == "xy");
    CHECK(rec.problem == "text_after_quote");
  }
  SUBCASE("an unclosed quote runs to the end") {
    auto r = CsvReader::from_text("a,b\n\"x,y\nz,w\n");
    REQUIRE(r.next(rec));
    REQUIRE(r.next(rec));
    CHECK(rec.problem == "unclosed_quote");
    CHECK(rec.line == 2);
    CHECK(rec.last_line == 3);
    CHECK_FALSE(r.next(rec));
  }
  SUBCASE("classic Mac line ends (CR alone)") {
    auto r = CsvReader::from_text("a,b\rc,d\r");
    CHECK(all(r) == Rows{{"a", "b"}, {"c", "d"}});
  }
  SUBCASE("UTF-16 is refused") {
    CHECK_THROWS_AS(CsvReader::from_text(std::string("\xff\xfe" "a\0,\0", 6)), std::runtime_error);
  }
}

TEST_CASE("round trip: random cells written as RFC 4180, read back, over many seeds") {
  const char* alphabet[] = {"a", "Z", "0", "9", ",", ";", "\t", "\"", " ", "\n", "\r\n", "é", "√", "-", "."};
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    CAPTURE(seed);
    epure::Rng rng(seed);
    const char delimiter = seed % 3 == 0 ? ',' : seed % 3 == 1 ? ';' : '\t';
    const int columns = static_cast<int>(rng.integer(1, 6));
    Rows rows;
    // a header that detects as the delimiter
    std::vector<std::string> header;
    for (int c = 0; c < columns; ++c) header.push_back(fmt::format("h{}", c));
    rows.push_back(header);
    const int count = static_cast<int>(rng.integer(1, 30));
    for (int i = 0; i < count; ++i) {
      std::vector<std::string> row;
      for (int c = 0; c < columns; ++c) {
        std::string cell;
        const int len = static_cast<int>(rng.integer(0, 8));
        for (int k = 0; k < len; ++k) cell += alphabet[rng.integer(0, std::size(alphabet) - 1)];
        row.push_back(cell);
      }
      // a row of only empty cells with one column would be a blank line: not a record
      if (columns == 1 && row[0].empty()) row[0].push_back('x');
      rows.push_back(row);
    }
    std::string text;
    for (const auto& row : rows) {
      for (std::size_t c = 0; c < row.size(); ++c) {
        if (c) text += delimiter;
        const std::string& cell = row[c];
        const bool quote = cell.find_first_of(std::string{delimiter, '"', '\n', '\r'}) != std::string::npos ||
                           (!cell.empty() && (cell.front() == ' ' || cell.back() == ' '));
        if (!quote) {
          text += cell;
          continue;
        }
        text += '"';
        for (char ch : cell) {
          if (ch == '"') text += '"';
          text += ch;
        }
        text += '"';
      }
      text += seed % 2 ? "\r\n" : "\n";
    }
    auto reader = CsvReader::from_text(text);
    CHECK(reader.delimiter() == (columns > 1 ? delimiter : ','));
    if (columns > 1) CHECK(all(reader) == rows);
  }
}

TEST_CASE("records longer than the read buffer, from a file") {
  const auto path = std::filesystem::temp_directory_path() / "epure_csv_reader_test.csv";
  {
    std::ofstream out(path, std::ios::binary);
    out << "sheet;student\n";
    for (int i = 0; i < 3000; ++i) out << "id" << i << ";\"" << std::string(700, 'x') << "\n,;" << i << "\"\n";
  }
  CsvReader r(path);
  CsvRecord rec;
  int count = 0, last_line = 0;
  REQUIRE(r.next(rec));
  while (r.next(rec)) {
    REQUIRE(rec.cells.size() == 2);
    CHECK(std::string(rec.cells[0]) == "id" + std::to_string(count));
    CHECK(rec.cells[1].size() == 700 + 3 + std::to_string(count).size());
    last_line = rec.last_line;
    ++count;
  }
  CHECK(count == 3000);
  CHECK(last_line == 1 + 2 * 3000);
  std::filesystem::remove(path);
}

// A line of 3 MB made of stray quotes in an unquoted cell ('a"a"a"…'): each quote sends the
// reader to its slow path and back, and it once searched for the line's end again every time,
// 25 s for this line (quadratic). Now each byte is looked at a bounded number of times.
TEST_CASE("regression: stray quotes on a very long line are read in linear time") {
  std::string line = "1000-0005-002N;";
  for (int i = 0; i < 1500000; ++i) line += "a\"";
  const auto start = std::chrono::steady_clock::now();
  auto r = CsvReader::from_text("sheet;1.t\n" + line + "\nx;y\n");
  const auto rows = all(r);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(rows.size() == 3);
  CHECK(rows[1].size() == 2);
  CHECK(rows[1][1].size() == 3000000);
  CHECK(rows[2] == std::vector<std::string>{"x", "y"});
  CHECK(seconds < 5);  // linear: milliseconds; the quadratic reader took 25 s
}
