#pragma once
// `epure check`: every submission read, scanned, compiled, run confined on its cases, judged
// against the core, its classic bugs named; then report.json, summary.txt, marks.csv and a
// feedback page per student (feedback_page.h). Files are checked in parallel (`jobs` at once),
// each compiled once and run in one child per function run (runner.h).
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "check/bug_models.h"
#include "check/compile.h"
#include "check/functions.h"
#include "check/runner.h"
#include "check/submission.h"
#include "exercises/sheet_id.h"
#include "exercises/spec.h"

namespace epure::check {

enum class Verdict { passed, wrong, crashed, timeout, compile_error, refused };
std::string_view verdict_name(Verdict v);

struct FailedCase {
  std::size_t index = 0;  // among the function's cases
  Category category = Category::random;
  Inputs in{};
  Outcome expected;
  std::optional<Outcome> got;  // nothing: the case during which it crashed or hung
};

struct FunctionReport {
  Fn fn;
  Verdict verdict = Verdict::passed;
  std::size_t cases = 0, passed = 0, failed = 0;
  std::vector<Bug> bugs;  // the named classic bugs (none, one, or two together)
  std::string reason, reason_code;  // for crashed, timeout, refused, compile_error
  std::vector<FailedCase> failures;  // the first failing cases (kMaxFailures)
  std::vector<std::pair<Category, std::size_t>> failed_by_category;  // how many per category
  std::string output;       // what it printed (the start)
  std::size_t output_bytes = 0;
  double mark = 0;          // in points
  // The function ran and its run ended early (a crash, a timeout, a call the sandbox forbids),
  // as opposed to a file that did not build or was refused before it did.
  bool stopped_running() const {
    return verdict == Verdict::crashed || verdict == Verdict::timeout ||
           (verdict == Verdict::refused && reason_code != "include" && reason_code != "directive" &&
            reason_code != "pragma" && reason_code != "identifier" && reason_code != "size" && reason_code != "nul");
  }
};

inline constexpr std::size_t kMaxFailures = 5;

struct FileReport {
  std::filesystem::path path;
  std::string name;      // the file's name, as reports show it
  std::string student;   // from its comment, else the file's stem
  std::string sheet;     // the sheet id (canonical), when tied to a sheet
  std::vector<std::string> notes;  // a sheet id that did not check, a sheet that could not be rebuilt
  Verdict status = Verdict::passed;  // compile_error or refused for the file as a whole; else passed
  std::optional<Refusal> refusal;
  std::vector<CompileMessage> compiler;
  std::vector<FunctionReport> functions;  // the functions it defines (or mentions, when it did not build)
  std::vector<Fn> not_written;
  std::string feedback;  // the feedback page's base name (feedback/<name>.html, .pdf)
  double total = 0;
};

struct CheckOptions {
  std::vector<std::filesystem::path> submissions;  // files; directories give their *.c
  std::filesystem::path out;
  std::optional<WorksheetSpec> spec;  // rebuilds the sheets a file names (default: the course)
  std::string language = "en";        // of the feedback pages and the summary
  int jobs = 2;
  std::uint64_t seed = 1;             // of the random and hard cases
  std::chrono::milliseconds function_time{2000};
  std::vector<Fn> columns;            // marks.csv's columns; empty: every function some file defines
  bool all_or_nothing = false;        // a function's mark: all its points or none
  double points = 1;                  // per function
  bool feedback = true;               // write the feedback pages
  bool keep_work = false;             // keep the temporary directory (the compiled programs)
};

struct CheckResult {
  std::vector<FileReport> files;
  std::vector<Fn> columns;
  std::string sandbox;  // what the sandbox was, for the summary
  std::vector<std::pair<Fn, std::size_t>> cases_per_function;  // standard cases
};

// Throws SandboxError when the sandbox is not there (nothing is run then), std::runtime_error
// for an output that cannot be written. `progress` is told of each file done.
CheckResult run_check(const CheckOptions& options, const std::function<void(const FileReport&)>& progress = {});

// The check of one submission's text (tests; run_check does this for each file).
class Checker {
 public:
  Checker(const CheckOptions& options, const std::filesystem::path& work);
  ~Checker();
  FileReport check(const std::filesystem::path& path, std::string_view source, int index) const;
  std::string sandbox_description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epure::check
