#pragma once
// A RowHandler that records what the answer readers hand over and checks it as it comes:
// positions that only go forward, rows as wide as they should be, known problem codes.
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "grading/answer_source.h"

namespace epure::fuzz {

struct Recorder final : grading::RowHandler {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> problems;
  std::vector<int> lines;
  int headers = 0;
  int last_line = 0;
  bool json = false;

  void header(const std::vector<std::string>& n, int line) override {
    if (json) {
      // names only grow, in the order they were seen
      check(n.size() >= names.size(), "the JSON header shrank");
      for (std::size_t i = 0; i < names.size(); ++i) check(n[i] == names[i], "a JSON column was renamed");
    } else {
      check(headers == 0, "a CSV file with two headers");
      check(line >= 1, "a header line < 1");
      last_line = line;
    }
    names = n;
    ++headers;
  }
  void row(const grading::AnswerRow& r) override {
    check(r.line >= 1 && r.last_line >= r.line, "a row's lines out of order");
    check(r.line > last_line, "rows do not come in the order of their lines");
    last_line = r.last_line;
    if (json) check(r.cells.size() == names.size(), "a JSON row is not as wide as the names seen");
    static const std::string_view known[] = {"", "unclosed_quote", "text_after_quote", "not_an_object", "too_many_names"};
    bool ok = false;
    for (auto k : known) ok = ok || r.problem == k;
    check(ok, "an unknown problem code", r.problem);
    rows.emplace_back(r.cells.begin(), r.cells.end());
    problems.emplace_back(r.problem);
    lines.push_back(r.line);
  }
};

}  // namespace epure::fuzz
