#include "check/marks_csv.h"

#include <cmath>

#include <fmt/format.h>

#include "output/atomic_file.h"

namespace epure::check {

namespace {

void cell(std::string& out, std::string_view s, bool first = false) {
  if (!first) out += ',';
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) {
    out += s;
    return;
  }
  out += '"';
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

// Points to two decimals, without trailing zeros ("0.75", "1", "0.5").
std::string points(double x) {
  std::string s = fmt::format("{:.2f}", std::round(x * 100) / 100);
  while (s.find('.') != std::string::npos && (s.back() == '0' || s.back() == '.')) {
    const bool dot = s.back() == '.';
    s.pop_back();
    if (dot) break;
  }
  return s;
}

}  // namespace

std::string marks_csv(const CheckResult& result, const CheckOptions&) {
  std::string out;
  cell(out, "sheet", true);
  cell(out, "file");
  cell(out, "student");
  for (Fn fn : result.columns) cell(out, info(fn).name);
  cell(out, "total");
  out += "\r\n";
  for (const FileReport& f : result.files) {
    cell(out, f.sheet, true);
    cell(out, f.path.filename().string());
    cell(out, f.student);
    double total = 0;
    for (Fn fn : result.columns) {
      double mark = 0;
      for (const auto& r : f.functions)
        if (r.fn == fn) mark = r.mark;
      total += mark;
      cell(out, points(mark));
    }
    cell(out, points(total));
    out += "\r\n";
  }
  return out;
}

void write_marks_csv(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& path) {
  output::write_file_atomically(path, marks_csv(result, options));
}

}  // namespace epure::check
