// `epure generate`: the course's worksheet set (or a spec's) into a directory.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "cli/commands.h"
#include "exercises/spec.h"
#include "exercises/texts.h"
#include "grading/roster.h"
#include "exercises/worksheet.h"
#include "output/explore_page.h"
#include "output/generate.h"
#include "render/pdf_document.h"

namespace epure::cli {

namespace {

struct GenerateCliOptions {
  int sheets = 30;
  std::uint64_t seed = 1;
  std::string spec_file;
  std::string language;
  std::string difficulty;
  std::string out = "out";
  std::vector<std::string> formats = {"svg", "pdf"};  // --format svg,pdf: a list, each checked
  std::string paper;
  bool split = false;
  bool duplex = false;
  bool quiet = false;
  int jobs = 0;  // 0: every core
  std::string roster;
  bool sheets_given = false;
};

// The roster's students, one sheet each. A problem that would leave a student without a sheet
// or two with one number (a duplicate number, a row without a number, no number column, an
// empty or unreadable file) stops the run before anything is written: sheets printed for a
// class that cannot be told apart are paper wasted. A missing name or a bad e-mail is said and
// the sheets are made. Every problem is said with the file and its line. Nothing when the
// roster is refused.
std::optional<std::vector<SheetStudent>> read_students(const std::string& path, const Texts& texts) {
  const grading::Roster roster = grading::read_roster(path);
  bool refused = false;
  for (const auto& p : roster.problems) {
    const std::string where = p.line > 0 ? fmt::format("{}:{}", path, p.line) : path;
    fmt::print(stderr, "epure generate: {}: {}: {}\n", where, p.error ? "error" : "warning", describe(p, texts));
    refused = refused || p.error;
  }
  if (roster.students.empty() && !refused) {
    fmt::print(stderr, "epure generate: {}: error: no student in the roster\n", path);
    refused = true;
  }
  if (refused) {
    fmt::print(stderr, "epure generate: {}: the roster has errors: no sheet written\n", path);
    return std::nullopt;
  }
  std::vector<SheetStudent> students;
  for (const auto& e : roster.students) students.push_back({e.number, e.name, e.email});
  return students;
}

// A bar on stderr when it is a terminal and the run has lasted more than a second.
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled && ::isatty(STDERR_FILENO)) {}
  void operator()(int done, int total) {
    if (!enabled_) return;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    if (elapsed < std::chrono::seconds(1) && done < total) return;
    if (elapsed < std::chrono::seconds(1) && !shown_) return;
    shown_ = true;
    const int width = 30, filled = total ? width * done / total : width;
    fmt::print(stderr, "\r[{:=<{}}{: <{}}] {}/{} sheets", "", filled, "", width - filled, done, total);
    if (done == total) fmt::print(stderr, "\n");
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string written_files(const output::GenerateOptions& o) {
  std::string files;
  if (o.svg) files += "sheets/*.svg, keys/*.svg, ";
  if (o.pdf) files += o.split ? "sheets/*.pdf, keys/*.pdf, " : "sheets.pdf, keys.pdf, ";
  files += "key.json";
  if (o.svg || o.pdf) files += ", layout.json";
  if (o.svg) files += ", index.html";
  if (o.svg && output::explore_available()) files += ", explore.html";
  return files;
}

int run_generate(const GenerateCliOptions& o) {
  WorksheetSpec spec;
  if (o.spec_file.empty()) {
    spec = builtin_spec();
  } else if (auto builtin = builtin_spec(o.spec_file)) {
    spec = *std::move(builtin);
  } else {
    std::ifstream in(o.spec_file, std::ios::binary);
    if (!in) {
      fmt::print(stderr, "epure generate: cannot read spec '{}'\n", o.spec_file);
      return 2;
    }
    std::stringstream text;
    text << in.rdbuf();
    spec = parse_spec(text.str(), o.spec_file);
  }
  SetOptions set_options;
  if (!o.language.empty()) set_options.language = o.language;
  if (!o.difficulty.empty()) set_options.difficulty = parse_difficulty(o.difficulty);
  if (!o.paper.empty()) set_options.page = o.paper == "letter" ? "letter" : "A4";
  WorksheetSet set(std::move(spec), o.seed, set_options);

  output::GenerateOptions options;
  options.sheets = o.sheets;
  if (!o.roster.empty()) {
    auto students = read_students(o.roster, Texts::builtin(set.language()));
    if (!students) return 2;
    if (o.sheets_given && o.sheets != static_cast<int>(students->size())) {
      fmt::print(stderr, "epure generate: --sheets {} with a roster of {} students: a roster makes one sheet per student (leave --sheets out)\n",
                 o.sheets, students->size());
      return 2;
    }
    if (students->size() > static_cast<std::size_t>(kMaxSheets)) {
      fmt::print(stderr, "epure generate: {}: {} students: a set holds at most {} sheets\n", o.roster, students->size(), kMaxSheets);
      return 2;
    }
    options.sheets = static_cast<int>(students->size());
    options.students = std::move(*students);
  }
  options.out = o.out;
  options.svg = std::find(o.formats.begin(), o.formats.end(), "svg") != o.formats.end();
  options.pdf = std::find(o.formats.begin(), o.formats.end(), "pdf") != o.formats.end();
  options.split = o.split;
  options.duplex = o.duplex;
  if (options.pdf) options.pdf_date = render::source_date_epoch();
  options.jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  options.epure_version = EPURE_VERSION;
  Progress progress(!o.quiet);
  options.progress = [&](int done, int total) { progress(done, total); };
  const auto report = output::generate_set(set, options);
  if (!o.quiet)
    fmt::print("epure generate: {} sheets ({} … {}) into {}/ ({})\n", report.sheets, report.first_id,
               report.last_id, o.out, written_files(options));
  return 0;
}

}  // namespace

void add_generate_command(CLI::App& app, int& status) {
  auto o = std::make_shared<GenerateCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "generate", "Write a randomised worksheet set and its answer keys (default: the course's worksheet)");
  cmd->add_option("--sheets,-n", o->sheets, "Number of sheets")->check(CLI::Range(1, 32768))->capture_default_str()
      ->each([o](const std::string&) { o->sheets_given = true; });
  cmd->add_option("--roster", o->roster,
                  "Class roster (CSV: student number; name; optional e-mail): one sheet per student, their name and number printed on it")
      ->check(CLI::ExistingFile);
  cmd->add_option("--seed,-s", o->seed, "Seed of the set (0 to 2^35-1); same spec + seed = same files")
      ->check(CLI::Range(std::uint64_t{0}, (std::uint64_t{1} << 35) - 1))
      ->capture_default_str();
  cmd->add_option("--spec", o->spec_file, "Worksheet spec (TOML), or builtin (the course) or builtin:3d (the course in space); default: builtin")
      ->check(spec_check());
  cmd->add_option("--lang", o->language, "Language of the texts (overrides the spec)")
      ->check(CLI::IsMember({"en", "fr"}));
  cmd->add_option("--difficulty", o->difficulty, "Difficulty of every exercise (overrides the spec)")
      ->check(CLI::IsMember({"easy", "standard", "hard"}));
  cmd->add_option("--out,-o", o->out, "Output directory")->capture_default_str();
  cmd->add_option("--format", o->formats, "Output formats: svg, pdf, or both (svg,pdf)")
      ->delimiter(',')
      ->check(CLI::IsMember({"svg", "pdf"}))
      ->capture_default_str();
  cmd->add_flag("--split", o->split, "PDF: one file per sheet and per key (sheets/<id>.pdf, keys/<id>.pdf) instead of sheets.pdf and keys.pdf");
  cmd->add_flag("--duplex", o->duplex, "PDF: start every sheet on an odd page (a blank page where needed), for double-sided printing");
  cmd->add_option("--paper", o->paper, "Paper size (overrides the spec): a4 or letter")
      ->transform(CLI::IsMember({"a4", "letter"}, CLI::ignore_case));
  cmd->add_option("--jobs,-j", o->jobs, "Parallel jobs, 0 for every core (output is the same for any number)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  cmd->add_flag("--quiet,-q", o->quiet, "No progress bar nor summary");
  cmd->callback([o, &status] { status = run_reporting("epure generate", [&] { return run_generate(*o); }); });
}

}  // namespace epure::cli
