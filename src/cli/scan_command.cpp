// `epure scan SCANS... --key key.json --out DIR`: reads a class's scanned sheets (PDF, PNG,
// JPEG, TIFF) and writes the answers `epure grade` marks, pages.csv, sheets.csv and review.html
// (src/scan/scan_outputs.h). Exit status: 0 when every page was identified and every field read
// for sure, 1 when some page or field needs the teacher (each said on stderr), 2 when nothing
// could be scanned (no layout, a key of another set or version, a corrections file that is not one).
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "cli/commands.h"
#include "grading/answer_key.h"
#include "exercises/texts.h"
#include "grading/corrections.h"
#include "scan/digit_classifier.h"
#include "scan/layout_file.h"
#include "scan/scan_outputs.h"
#include "scan/scan_session.h"

namespace epure::cli {

namespace {

struct ScanCliOptions {
  std::vector<std::string> inputs;
  std::string key_file;
  std::string layout_file;
  std::string out = "scan";
  std::string corrections;
  int jobs = 0;
  int dpi = 200;
  bool crops = false;
  bool quiet = false;
};

int run_scan(const ScanCliOptions& o) {
  namespace fs = std::filesystem;
  const std::string layout_path = !o.layout_file.empty() ? o.layout_file
                                  : (fs::path(o.key_file).parent_path() / "layout.json").string();
  scan::SetLayout layout;
  try {
    layout = scan::read_layout_file(layout_path);
  } catch (const scan::LayoutError& e) {
    fmt::print(stderr, "scan: {}\n", e.what());
    return 2;
  }
  // The key must be the layout's set: the same seed and draw version, every sheet of the layout in it.
  try {
    const grading::AnswerKey key = grading::read_key_json(read_text(o.key_file), o.key_file);
    if (key.info.seed != layout.seed || key.info.draw_version != layout.draw_version) {
      fmt::print(stderr, "scan: {} is the key of another set (seed {}, draw version {}) than {} (seed {}, draw version {})\n",
                 o.key_file, key.info.seed, key.info.draw_version, layout_path, layout.seed, layout.draw_version);
      return 2;
    }
    for (const auto& [id, sheet] : layout.sheets)
      if (!key.find(id)) {
        fmt::print(stderr, "scan: sheet {} of {} is not in {}: not the same set\n", id, layout_path, o.key_file);
        return 2;
      }
  } catch (const std::exception& e) {
    fmt::print(stderr, "scan: {}\n", e.what());
    return 2;
  }
  // The teacher's corrections, read before any page (one reader and one format with `epure grade
  // --corrections`): a file that is not a corrections file stops the run, as it stops grade; a
  // bad entry is said in the set's language, as grade says it, and the others are applied.
  std::optional<grading::Corrections> corrections;
  const Texts& texts = Texts::builtin(layout.language);
  std::vector<std::string> correction_problems;
  if (!o.corrections.empty()) {
    corrections = grading::read_corrections_file(o.corrections);
    for (const auto& p : corrections->problems)
      correction_problems.push_back(fmt::format("{}: {}", corrections->source, grading::describe(p, texts)));
    if (!corrections->readable) {
      for (const auto& p : correction_problems) fmt::print(stderr, "scan: {}\n", p);
      return 2;
    }
  }
  scan::ScanOptions options;
  options.jobs = o.jobs;
  options.render_dpi = o.dpi;
  options.all_crops = o.crops;
  options.out = o.out;
  scan::ScanResult result = scan::scan_inputs(o.inputs, layout, options, scan::DigitClassifier::builtin());
  result.problems.insert(result.problems.end(), correction_problems.begin(), correction_problems.end());
  if (corrections) scan::apply_corrections(result, *corrections, texts);
  if (o.crops) scan::say_crops_not_written(result);  // said below with the others
  scan::write_scan_outputs(o.out, result, layout);

  int status = 0;
  std::size_t identified = 0;
  for (const auto& p : result.pages) {
    if (p.status == scan::PageStatus::identified) {
      ++identified;
      continue;
    }
    if (p.status != scan::PageStatus::blank) status = 1;
    fmt::print(stderr, "scan: {}: page {}: {}{}{}\n", p.file, p.page, scan::page_status_name(p.status),
               p.detail.empty() ? "" : ": ", p.detail);
  }
  for (const auto& [id, s] : result.sheets)
    for (std::size_t i = 0; i < s.seen.size(); ++i)
      if (!s.seen[i]) {
        status = 1;
        fmt::print(stderr, "scan: sheet {}: page {} of {} is missing\n", id, i + 1, s.pages);
      }
  for (const auto& p : result.problems) {
    status = 1;
    fmt::print(stderr, "scan: {}\n", p);
  }
  const std::size_t review = scan::fields_to_review(result);
  if (review > 0) status = 1;
  if (!o.quiet)
    fmt::print("scan: {} pages read, {} identified, {} sheets; {} fields to review ({}/review.html){}\n", result.pages.size(),
               identified, result.sheets.size(), review, o.out,
               review > 0 ? "; then run again with --corrections FILE" : "");
  return status;
}

}  // namespace

void add_scan_command(CLI::App& app, int& status) {
  auto opts = std::make_shared<ScanCliOptions>();
  CLI::App* cmd = app.add_subcommand("scan", "Read a class's scanned sheets into answers for `epure grade`");
  cmd->add_option("scans", opts->inputs, "Scanned pages: PDF, PNG, JPEG or TIFF files, in any order")->required();
  cmd->add_option("--key", opts->key_file, "The set's key.json (its layout.json beside it is read)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--layout", opts->layout_file, "The set's layout.json, if not beside key.json")->check(CLI::ExistingFile);
  cmd->add_option("--out", opts->out, "Output directory (answers.json, answers.csv, pages.csv, sheets.csv, review.html)");
  cmd->add_option("--corrections", opts->corrections, "A corrections file (saved from review.html; the one epure grade --corrections reads)")->check(CLI::ExistingFile);
  cmd->add_option("--jobs", opts->jobs, "Threads reading pages (0: every core)")->check(CLI::Range(0, 256));
  cmd->add_option("--dpi", opts->dpi, "Resolution at which PDF pages without one embedded image are rendered")->check(CLI::Range(72, 600));
  cmd->add_flag("--crops", opts->crops,
                "Also write every field as scanned into OUT/crops/<sheet>/<question>.png: epure grade's feedback sheets "
                "show each under its question, so a student sees what was read");
  cmd->add_flag("-q,--quiet", opts->quiet, "No summary on standard output");
  cmd->callback([opts, &status] { status = run_reporting("scan", [&] { return run_scan(*opts); }); });
}

}  // namespace epure::cli
