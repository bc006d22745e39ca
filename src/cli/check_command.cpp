// `epure check SUBMISSIONS... --out DIR`: students' C functions run confined against the core
// (check/check.h). Exit status: 0 when every file was checked (whatever its verdicts), 1 when a
// file could not be read, 2 when nothing ran (the sandbox is missing, a bad option).
#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "check/check.h"
#include "check/sandbox.h"
#include "check/sandbox_error.h"
#include "check/summary_text.h"
#include "cli/commands.h"
#include "grading/answer_key.h"

namespace epure::cli {

namespace {

struct CheckCliOptions {
  std::vector<std::string> submissions;
  std::string out;
  std::string spec;
  std::string key;
  std::string language = "fr";
  int jobs = 0;
  std::uint64_t seed = 1;
  int timeout_ms = 2000;
  std::string functions;
  double points = 1;
  bool all_or_nothing = false;
  bool no_feedback = false;
  bool keep_work = false;
  bool quiet = false;
  bool sandbox_info = false;
};

int print_sandbox() {
  const check::SandboxReport r = check::probe_sandbox();
  fmt::print("seccomp filters: {}\n", r.seccomp ? "yes" : "NO");
  fmt::print("Landlock: {}\n", r.landlock_abi > 0 ? fmt::format("ABI {}", r.landlock_abi) : std::string("NO"));
  fmt::print("running as root: {}{}\n", r.root ? "yes" : "no",
             r.root ? fmt::format(" (children drop to uid {} gid {})", r.user.uid, r.user.gid) : std::string());
  if (!r.refusal.empty()) {
    fmt::print("epure check would refuse to run: {}\n", r.refusal);
    return 2;
  }
  fmt::print("epure check can run here\n");
  return 0;
}

int run_check_command(const CheckCliOptions& o) {
  if (o.sandbox_info) return print_sandbox();
  if (o.submissions.empty() || o.out.empty()) {
    fmt::print(stderr, "epure check: give the submissions (C files or directories) and --out DIR\n");
    return 2;
  }
  check::CheckOptions options;
  for (const auto& s : o.submissions) options.submissions.emplace_back(s);
  options.out = o.out;
  options.language = o.language;
  options.jobs = o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  options.seed = o.seed;
  options.function_time = std::chrono::milliseconds(o.timeout_ms);
  options.points = o.points;
  options.all_or_nothing = o.all_or_nothing;
  options.feedback = !o.no_feedback;
  options.keep_work = o.keep_work;
  if (!o.spec.empty()) {
    options.spec = builtin_spec(o.spec) ? *builtin_spec(o.spec) : parse_spec(read_text(o.spec), o.spec);
  } else if (!o.key.empty()) {
    const grading::AnswerKey key = grading::read_key_json(read_text(o.key), o.key);
    if (!key.info.spec_text.empty()) options.spec = parse_spec(key.info.spec_text, o.key + " (spec)");
  }
  std::stringstream names(o.functions);
  std::string name;
  while (std::getline(names, name, ',')) {
    if (name.empty()) continue;
    const auto fn = check::function_named(name);
    if (!fn) {
      fmt::print(stderr, "epure check: --functions: no function '{}'\n", name);
      return 2;
    }
    options.columns.push_back(*fn);
  }
  std::size_t unreadable = 0, done = 0;
  const std::size_t total = [&] {
    std::size_t n = 0;
    for (const auto& p : options.submissions) {
      if (std::filesystem::is_directory(p)) {
        for (const auto& e : std::filesystem::directory_iterator(p))
          if (e.is_regular_file() && e.path().extension() == ".c") ++n;
      } else {
        ++n;
      }
    }
    return n;
  }();
  check::CheckResult result;
  try {
  result = check::run_check(options, [&](const check::FileReport& f) {
    ++done;
    if (f.refusal && f.refusal->code == "unreadable") ++unreadable;
    if (!o.quiet) {
      std::size_t passed = 0;
      for (const auto& r : f.functions) passed += r.verdict == check::Verdict::passed;
      fmt::print(stderr, "[{}/{}] {}: {}\n", done, total, f.name,
                 f.status != check::Verdict::passed ? std::string(check::verdict_name(f.status))
                                                    : fmt::format("{} of {} functions passed", passed, f.functions.size()));
    }
  });
  } catch (const check::SandboxError& e) {
    fmt::print(stderr, "epure check: {}\n", e.what());
    return 2;
  }
  if (!o.quiet) fmt::print("{}", check::summary_text(result, options));
  return unreadable > 0 ? 1 : 0;
}

}  // namespace

void add_check_command(CLI::App& app, int& status) {
  auto o = std::make_shared<CheckCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check", "Run students' C functions, confined, against the geometry core: report, marks, feedback pages");
  cmd->add_option("submissions", o->submissions, "C files (one per student), or directories of them");
  cmd->add_option("--out,-o", o->out, "Directory for report.json, summary.txt, marks.csv and feedback/");
  auto* spec = cmd->add_option("--spec", o->spec,
                               "The spec the students' sheets were drawn from (TOML, 'builtin' or 'builtin:3d'; default: the course)")
                   ->check(spec_check());
  auto* key = cmd->add_option("--key", o->key, "Instead of --spec: the set's key.json (it carries its spec)")->check(CLI::ExistingFile);
  spec->excludes(key);
  cmd->add_option("--lang", o->language, "Language of the feedback pages and the summary (default: fr)")
      ->check(CLI::IsMember({"en", "fr"}));
  cmd->add_option("--jobs,-j", o->jobs, "Files checked at once (0, the default: one per core)");
  cmd->add_option("--seed", o->seed, "Seed of the random and hard cases (the same for every student)");
  cmd->add_option("--timeout", o->timeout_ms, "Milliseconds a function gets for all its cases (default 2000)")
      ->check(CLI::Range(100, 600000));
  cmd->add_option("--functions", o->functions, "marks.csv's columns, comma-separated (default: every function some file defines)");
  cmd->add_option("--points", o->points, "Points per function (default 1)")->check(CLI::PositiveNumber);
  cmd->add_flag("--all-or-nothing", o->all_or_nothing, "A function's mark is all its points when every case passes, else 0");
  cmd->add_flag("--no-feedback", o->no_feedback, "Write no feedback pages");
  cmd->add_flag("--keep-work", o->keep_work, "Keep the temporary directory with the compiled programs");
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors");
  cmd->add_flag("--sandbox-info", o->sandbox_info, "Say what the sandbox relies on and whether this machine has it, then stop");
  cmd->callback([o, &status] {
    try {
      status = run_reporting("epure check", [&] { return run_check_command(*o); });
    } catch (...) {
      status = 2;
    }
  });
}

}  // namespace epure::cli
