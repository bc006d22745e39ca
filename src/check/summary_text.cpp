#include "check/summary_text.h"

#include <map>

#include <fmt/format.h>

#include "exercises/texts.h"
#include "output/atomic_file.h"

namespace epure::check {

std::string summary_text(const CheckResult& result, const CheckOptions& options) {
  const Texts& T = Texts::builtin(options.language);
  std::size_t functions = 0;
  for (const auto& f : result.files) functions += f.functions.size();
  std::string out = T.format("check.summary.title", {{"files", std::to_string(result.files.size())},
                                                     {"functions", std::to_string(functions)}}) + "\n";
  out += T.format("check.summary.sandbox", {{"sandbox", result.sandbox}}) + "\n\n";
  std::map<Fn, std::size_t> passed;
  std::map<std::string, std::size_t> bugs;
  for (const FileReport& f : result.files) {
    std::string line = fmt::format("{} ({})", f.student, f.path.filename().string());
    if (f.status == Verdict::refused && f.refusal)
      line += fmt::format(": {} (line {}: {})", T.get("check.verdict.refused"), f.refusal->line, f.refusal->detail);
    else if (f.status == Verdict::compile_error)
      line += ": " + T.get("check.verdict.compile_error");
    out += line + "\n";
    for (const FunctionReport& r : f.functions) {
      std::string l = fmt::format("  {:<30} {:<18} {:>4}/{:<4}", info(r.fn).name,
                                  T.get("check.verdict." + std::string(verdict_name(r.verdict))), r.passed, r.cases);
      if (!r.bugs.empty()) {
        l += "  ";
        for (std::size_t i = 0; i < r.bugs.size(); ++i) l += (i ? "+" : "") + std::string(bug_code(r.bugs[i]));
        ++bugs[std::string(bug_code(r.bugs.front()))];
      } else if (!r.reason.empty() && r.verdict != Verdict::passed && r.verdict != Verdict::wrong) {
        l += "  " + r.reason_code;
      }
      if (r.verdict == Verdict::passed) ++passed[r.fn];
      out += l + "\n";
    }
    for (Fn fn : f.not_written)
      out += fmt::format("  {:<30} {}\n", info(fn).name, T.get("check.verdict.not_written"));
  }
  out += "\n";
  for (Fn fn : result.columns)
    out += T.format("check.summary.per_function", {{"name", std::string(info(fn).name)},
                                                   {"passed", std::to_string(passed[fn])},
                                                   {"files", std::to_string(result.files.size())}}) + "\n";
  if (!bugs.empty()) {
    std::string list;
    for (const auto& [code, n] : bugs) list += (list.empty() ? "" : ", ") + fmt::format("{} ×{}", code, n);
    out += T.format("check.summary.bugs", {{"list", list}}) + "\n";
  }
  return out;
}

void write_summary_text(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& path) {
  output::write_file_atomically(path, summary_text(result, options));
}

}  // namespace epure::check
