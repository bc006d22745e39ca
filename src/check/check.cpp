#include "check/check.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "check/cases.h"
#include "check/classify.h"
#include "check/feedback_page.h"
#include "check/judge.h"
#include "check/marks_csv.h"
#include "check/report_json.h"
#include "check/sandbox_error.h"
#include "check/seccomp_filter.h"
#include "check/sheet_tag.h"
#include "check/summary_text.h"
#include "exercises/texts.h"

namespace epure::check {

std::string_view verdict_name(Verdict v) {
  switch (v) {
    case Verdict::passed: return "passed";
    case Verdict::wrong: return "wrong";
    case Verdict::crashed: return "crashed";
    case Verdict::timeout: return "timeout";
    case Verdict::compile_error: return "compile_error";
    case Verdict::refused: return "refused";
  }
  return "?";
}

namespace {

Verdict verdict_of(RunEnd end) {
  switch (end) {
    case RunEnd::crashed: return Verdict::crashed;
    case RunEnd::timeout: return Verdict::timeout;
    case RunEnd::refused: return Verdict::refused;
    default: return Verdict::passed;
  }
}

// The same verdict for every function a file mentions (it did not build, or did not start).
void every_function(FileReport& file, const std::vector<Fn>& functions, Verdict verdict, const std::string& code,
                    const std::string& reason, const std::vector<std::vector<Case>>& cases) {
  for (Fn fn : functions) {
    FunctionReport f;
    f.fn = fn;
    f.verdict = verdict;
    f.cases = cases[static_cast<std::size_t>(fn)].size();
    f.failed = f.cases;
    f.reason_code = code;
    f.reason = reason;
    file.functions.push_back(std::move(f));
  }
}

std::string read_submission(const std::filesystem::path& path, bool& too_large) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read", path.string()));
  std::string text(kMaxSubmissionBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  too_large = text.size() > kMaxSubmissionBytes;
  return text;
}

// A file name for the feedback page: letters, digits, - _ . only.
std::string safe_name(std::string_view name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  return out.empty() ? std::string("submission") : out;
}

}  // namespace

struct Checker::Impl {
  CheckOptions options;
  std::filesystem::path work;
  SandboxReport sandbox;
  std::optional<SandboxUser> user;
  SeccompProgram seccomp;
  std::optional<Toolchain> toolchain;
  std::vector<std::vector<Case>> standard;  // per function
  WorksheetSpec spec;

  Impl(const CheckOptions& o, std::filesystem::path w)
      : options(o), work(std::move(w)), sandbox(probe_sandbox()), seccomp(prepare()) {
    if (sandbox.root) {
      user = sandbox.user;
      // the sandbox user compiles and runs in `work`: every directory above it must let it pass
      for (std::filesystem::path p = work.parent_path(); !p.empty(); p = p.parent_path()) {
        struct stat st {};
        if (stat(p.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH))
          throw SandboxError(fmt::format("{} is closed to the sandbox user (uid {}): set TMPDIR to a directory "
                                         "others may pass through (chmod o+x), such as /tmp",
                                         p.string(), user->uid));
        if (p == p.root_path()) break;
      }
    }
    toolchain.emplace(work, user);
    for (const FunctionInfo& f : all_functions()) standard.push_back(standard_cases(f.fn, options.seed));
    spec = options.spec ? *options.spec : builtin_spec();
  }

  SeccompProgram prepare() {
    if (!sandbox.refusal.empty()) throw SandboxError(sandbox.refusal);
    return SeccompProgram::harness();
  }

  RunConfig run_config() const {
    RunConfig config;
    config.user = user;
    config.seccomp = &seccomp;
    config.function_time = options.function_time;
    config.limits.cpu_seconds = std::chrono::duration<double>(options.function_time).count() * kFunctionCount + 1;
    config.limits.address_space = 256ULL << 20;
    config.limits.file_size = 0;
    config.limits.open_files = 8;
    config.limits.stack = 16ULL << 20;
    return config;
  }

  // Why a run ended, in the report's language.
  std::string reason_text(const FunctionRun& run) const {
    const Texts& T = Texts::builtin(options.language);
    TextVars vars = run.reason_vars;
    for (auto& [name, value] : vars)
      if (name == "kind") value = T.get("check.call." + value), name = "what";
    return T.format("check.reason." + run.reason_key, vars);
  }

  FunctionReport judge_run(const FunctionRun& run, const std::vector<Case>& cases) const {
    FunctionReport f;
    f.fn = run.fn;
    f.cases = cases.size();
    f.output = run.output;
    f.output_bytes = run.output_bytes;
    std::vector<bool> right(cases.size(), false);
    std::map<Category, std::size_t> by_category;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (!run.outcomes[i]) {
        ++by_category[cases[i].category];
        continue;
      }
      const Judgement j = judge(cases[i], *run.outcomes[i]);
      right[i] = j.right;
      if (j.right) {
        ++f.passed;
        continue;
      }
      ++by_category[cases[i].category];
      if (f.failures.size() < kMaxFailures) f.failures.push_back({i, cases[i].category, cases[i].in, j.expected, run.outcomes[i]});
    }
    f.failed = f.cases - f.passed;
    for (const auto& [c, n] : by_category) f.failed_by_category.emplace_back(c, n);
    if (run.stopped_at && *run.stopped_at < cases.size()) {
      const std::size_t i = *run.stopped_at;
      const auto e = expected(cases[i]);
      FailedCase stuck{i, cases[i].category, cases[i].in, e.value_or(Outcome{}), std::nullopt};
      // the case it stopped on first: it is what the student must look at
      f.failures.insert(f.failures.begin(), stuck);
      if (f.failures.size() > kMaxFailures) f.failures.pop_back();
    }
    if (run.end == RunEnd::completed) {
      f.verdict = f.failed == 0 ? Verdict::passed : Verdict::wrong;
    } else {
      f.verdict = verdict_of(run.end);
      f.reason = reason_text(run);
      f.reason_code = run.reason_code;
    }
    if (f.passed < f.cases) {
      const Classification c = classify(run.fn, cases, run.outcomes, right);
      f.bugs = c.bugs;
    }
    const double share = f.cases ? double(f.passed) / double(f.cases) : 0;
    f.mark = options.points * (options.all_or_nothing ? (f.verdict == Verdict::passed ? 1 : 0) : share);
    return f;
  }

  FileReport check(const std::filesystem::path& path, std::string_view source, int index) const {
    FileReport file;
    file.path = path;
    file.name = path.filename().string();
    const SubmissionTags tags = read_tags(source);
    file.student = tags.student.empty() ? path.stem().string() : tags.student;
    file.feedback = safe_name(path.stem().string());
    std::vector<std::vector<Case>> cases = standard;
    if (tags.sheet_problem)
      file.notes.push_back(fmt::format("line {}: sheet id '{}' not taken: {}", tags.sheet_line, tags.sheet_text, *tags.sheet_problem));
    if (tags.sheet) {
      file.sheet = tags.sheet->str();
      try {
        for (const Case& c : sheet_cases(spec, *tags.sheet)) {
          auto& list = cases[static_cast<std::size_t>(c.fn)];
          list.insert(std::find_if(list.begin(), list.end(), [](const Case& k) { return k.category != Category::sheet; }), c);
        }
      } catch (const std::exception& e) {
        file.notes.push_back(fmt::format("sheet {}: its instances are left out: {}", file.sheet, e.what()));
      }
    }

    const SubmissionScan scan = scan_submission(source);
    if (scan.refusal) {
      file.status = Verdict::refused;
      file.refusal = scan.refusal;
      every_function(file, scan.mentioned, Verdict::refused, scan.refusal->code,
                     Texts::builtin(options.language)
                         .format("check.reason.refused_before", {{"line", std::to_string(scan.refusal->line)},
                                                                  {"detail", scan.refusal->detail}}),
                     cases);
      compute_total(file);
      return file;
    }
    const std::filesystem::path dir = work / fmt::format("{:04}", index);
    const CompileResult compiled = toolchain->build(dir, source, file.name);
    file.compiler = compiled.messages;
    if (!compiled.ok) {
      file.status = Verdict::compile_error;
      std::string first;
      for (const auto& m : compiled.messages)
        if (m.severity == "error") {
          first = m.text;
          break;
        }
      every_function(file, scan.mentioned, Verdict::compile_error, compiled.timed_out ? "compiler_limit" : "compile", first, cases);
      cleanup(dir);
      compute_total(file);
      return file;
    }
    const FileRun run = run_program(compiled.program, cases, run_config());
    if (run.startup) {
      every_function(file, scan.mentioned, verdict_of(run.startup->end), run.startup->reason_code,
                     Texts::builtin(options.language).format("check.reason.before_start", {{"why", reason_text(*run.startup)}}),
                     cases);
      if (!file.functions.empty()) {
        file.functions.front().output = run.startup->output;
        file.functions.front().output_bytes = run.startup->output_bytes;
      }
    }
    for (const FunctionRun& r : run.functions) {
      if (r.end == RunEnd::not_written) {
        file.not_written.push_back(r.fn);
        continue;
      }
      file.functions.push_back(judge_run(r, cases[static_cast<std::size_t>(r.fn)]));
    }
    cleanup(dir);
    compute_total(file);
    return file;
  }

  void compute_total(FileReport& file) const {
    file.total = 0;
    for (const auto& f : file.functions) file.total += f.mark;
  }

  void cleanup(const std::filesystem::path& dir) const {
    if (options.keep_work) return;
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
};

Checker::Checker(const CheckOptions& options, const std::filesystem::path& work)
    : impl_(std::make_unique<Impl>(options, work)) {}
Checker::~Checker() = default;

FileReport Checker::check(const std::filesystem::path& path, std::string_view source, int index) const {
  return impl_->check(path, source, index);
}

std::string Checker::sandbox_description() const {
  const Impl& i = *impl_;
  return fmt::format("{}; Landlock ABI {}; seccomp filter of {} instructions; limits: {} s of CPU, {} MiB of memory, "
                     "no file, no process, {} ms per function",
                     i.user ? fmt::format("as uid {} gid {} (from root)", i.user->uid, i.user->gid) : "as the calling user",
                     i.sandbox.landlock_abi, i.seccomp.instructions(),
                     std::chrono::duration<double>(i.options.function_time).count() * kFunctionCount + 1, 256,
                     i.options.function_time.count());
}

namespace {

std::vector<std::filesystem::path> expand(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::filesystem::path> files;
  for (const auto& p : inputs) {
    if (std::filesystem::is_directory(p)) {
      std::vector<std::filesystem::path> found;
      for (const auto& e : std::filesystem::directory_iterator(p))
        if (e.is_regular_file() && e.path().extension() == ".c") found.push_back(e.path());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(p);
    }
  }
  return files;
}

// A private directory for the compiled programs: readable by the sandbox user, listable by no one.
std::filesystem::path make_work_dir() {
  const auto base = std::filesystem::temp_directory_path() / "epure-check-XXXXXX";
  std::string templ = base.string();
  if (!mkdtemp(templ.data())) throw std::runtime_error(fmt::format("{}: cannot make a temporary directory", templ));
  chmod(templ.c_str(), 0711);
  return templ;
}

}  // namespace

CheckResult run_check(const CheckOptions& options, const std::function<void(const FileReport&)>& progress) {
  const std::vector<std::filesystem::path> files = expand(options.submissions);
  const std::filesystem::path work = make_work_dir();
  CheckResult result;
  try {
    Checker checker(options, work);
    result.sandbox = checker.sandbox_description();
    result.files.resize(files.size());
    std::atomic<std::size_t> next{0};
    std::mutex report_mutex;
    std::exception_ptr failure;
    auto worker = [&] {
      for (;;) {
        const std::size_t i = next++;
        if (i >= files.size()) return;
        FileReport report;
        try {
          bool too_large = false;
          const std::string source = read_submission(files[i], too_large);
          if (too_large) {
            report.path = files[i];
            report.name = files[i].filename().string();
            report.student = files[i].stem().string();
            report.feedback = safe_name(files[i].stem().string());
            report.status = Verdict::refused;
            report.refusal = Refusal{0, "size", fmt::format("larger than {} bytes", kMaxSubmissionBytes)};
          } else {
            report = checker.check(files[i], source, static_cast<int>(i));
          }
        } catch (const SandboxError&) {
          std::lock_guard lock(report_mutex);
          if (!failure) failure = std::current_exception();
          next = files.size();
          return;
        } catch (const std::exception& e) {
          report.path = files[i];
          report.name = files[i].filename().string();
          report.student = files[i].stem().string();
          report.feedback = safe_name(files[i].stem().string());
          report.status = Verdict::refused;
          report.refusal = Refusal{0, "unreadable", e.what()};
        }
        std::lock_guard lock(report_mutex);
        result.files[i] = std::move(report);
        if (progress) progress(result.files[i]);
      }
    };
    std::vector<std::thread> threads;
    for (int t = 0; t < std::max(1, options.jobs); ++t) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
  } catch (...) {
    if (!options.keep_work) {
      std::error_code ignored;
      std::filesystem::remove_all(work, ignored);
    }
    throw;
  }
  if (!options.keep_work) {
    std::error_code ignored;
    std::filesystem::remove_all(work, ignored);
  }

  // two files of one stem (a/x.c, b/x.c) get their feedback pages apart
  std::map<std::string, int> seen;
  for (auto& f : result.files) {
    const int n = seen[f.feedback]++;
    if (n > 0) f.feedback += fmt::format("-{}", n + 1);
  }
  result.columns = options.columns;
  if (result.columns.empty()) {
    for (const FunctionInfo& fi : all_functions()) {
      const bool any = std::any_of(result.files.begin(), result.files.end(), [&](const FileReport& f) {
        return std::any_of(f.functions.begin(), f.functions.end(), [&](const FunctionReport& r) { return r.fn == fi.fn; }) ||
               std::find(f.not_written.begin(), f.not_written.end(), fi.fn) != f.not_written.end();
      });
      if (any) result.columns.push_back(fi.fn);
    }
  }
  for (const FunctionInfo& fi : all_functions())
    result.cases_per_function.emplace_back(fi.fn, standard_cases(fi.fn, options.seed).size());

  std::filesystem::create_directories(options.out);
  write_report_json(result, options, options.out / "report.json");
  write_marks_csv(result, options, options.out / "marks.csv");
  write_summary_text(result, options, options.out / "summary.txt");
  if (options.feedback) write_feedback_pages(result, options, options.out / "feedback");
  return result;
}

}  // namespace epure::check
