// `epure grade`: marks a class's answers (a spreadsheet's CSV export, or JSON) against the key
// of their worksheet set, and writes the marks, the class statistics and a feedback sheet for
// every student. Exit status: 0 when every row and value could be read, 1 when some could not
// (each said on stderr with its file and line), 2 when nothing could be graded.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "cli/commands.h"
#include "exercises/spec.h"
#include "grading/answer_key.h"
#include "grading/answer_reading.h"
#include "grading/answer_source.h"
#include "grading/corrections.h"
#include "grading/mark_scale.h"
#include "grading/class_report.h"
#include "grading/feedback_sheet.h"
#include "grading/gradebook.h"
#include "grading/roster.h"
#include "grading/histogram.h"
#include "grading/report_csv.h"
#include "grading/report_json.h"
#include "grading/session.h"
#include "grading/summary_text.h"
#include "grading/words.h"
#include "output/atomic_file.h"

#ifndef EPURE_VERSION
#define EPURE_VERSION "0.0.0"
#endif

namespace epure::cli {

namespace {

using namespace epure::grading;

struct GradeCliOptions {
  std::string key_file;
  std::string spec_file;
  std::string answers;
  std::string report;
  std::string json;
  std::string feedback;
  std::string crops;
  std::string histogram;
  std::string language;
  std::string delimiter;
  std::string corrections;
  std::string class_report;
  std::vector<std::string> gradebook;  // format, file
  std::string roster;
  double out_of = 0;
  double round_to = 0;
  bool follow_through = false;
  bool no_follow_through = false;
  bool quiet = false;
};

// The first pass over the answers: how many rows carry each sheet (two submissions of one
// sheet are flagged on both rows), and the ids to rebuild under --spec.
class SheetCounter final : public RowHandler {
 public:
  explicit SheetCounter(const AnswerKey* key) : key_(key) {}
  void header(const std::vector<std::string>& names, int) override {
    column_ = -1;
    for (std::size_t c = 0; c < names.size(); ++c) {
      const auto w = read_word(trim_cell(names[c]));
      if (w && *w == "sheet") {
        column_ = static_cast<int>(c);
        break;
      }
    }
  }
  std::size_t cells_needed() const override { return column_ < 0 ? 0 : static_cast<std::size_t>(column_) + 1; }
  void row(const AnswerRow& r) override {
    if (column_ < 0 || static_cast<std::size_t>(column_) >= r.cells.size()) return;
    const std::string_view typed = trim_cell(r.cells[static_cast<std::size_t>(column_)]);
    if (typed.empty()) return;
    // a key's own id (nearly every row): counted by its place in the key, no string made
    if (key_) {
      if (const SheetKey* s = key_->find(typed)) {
        ++by_index_[key_->index_of(*s)];
        return;
      }
    }
    const auto parsed = parse_sheet_id(typed);
    if (!parsed.id) return;
    auto [it, fresh] = counts_.emplace(parsed.id->str(), 0);
    ++it->second;
    if (fresh) ids.push_back(*parsed.id);
  }

  // How many rows carry each sheet, by canonical id.
  std::unordered_map<std::string, int> take_counts() {
    if (key_)
      for (std::size_t i = 0; i < by_index_.size(); ++i)
        if (by_index_[i] > 0) counts_[key_->sheets()[i].id] += by_index_[i];
    return std::move(counts_);
  }

  std::vector<SheetId> ids;

 private:
  const AnswerKey* key_;
  int column_ = -1;
  std::vector<int> by_index_ = std::vector<int>(key_ ? key_->sheets().size() : 0, 0);
  std::unordered_map<std::string, int> counts_;
};

std::optional<char> delimiter_of(const std::string& name) {
  if (name.empty()) return std::nullopt;
  if (name == "tab" || name == "\\t") return '\t';
  return name[0];
}

int run_grade(const GradeCliOptions& o) {
  const auto delimiter = delimiter_of(o.delimiter);
  // the key: key.json, or rebuilt from the spec for the ids the answers name
  std::optional<AnswerKey> key;
  if (!o.key_file.empty()) {
    // refused before it is read whole (README, "Limits")
    std::error_code size_error;
    const auto bytes = std::filesystem::file_size(o.key_file, size_error);
    if (!size_error && bytes > kMaxKeyBytes)
      throw KeyError(fmt::format("{}: {} bytes: a key.json holds at most {} bytes (1 GiB)", o.key_file, bytes, kMaxKeyBytes));
    key = read_key_json(read_text(o.key_file), o.key_file);
  }
  SheetCounter counter(key ? &*key : nullptr);
  const SourceInfo dialect = read_answers(o.answers, counter, delimiter);
  if (!key) {
    const WorksheetSpec spec =
        builtin_spec(o.spec_file) ? *builtin_spec(o.spec_file) : parse_spec(read_text(o.spec_file), o.spec_file);
    key = key_from_spec(spec, counter.ids, EPURE_VERSION);
    if (key->sheets().empty()) {
      fmt::print(stderr, "epure grade: {}: no sheet id in the answers could be rebuilt from {}\n", o.answers, o.spec_file);
      for (const auto& [id, why] : key->refused()) fmt::print(stderr, "  {}: {}\n", id, why);
      return 2;
    }
  }

  // the teacher's corrections: read before anything is marked; a file that cannot be read at all
  // stops the run, a bad entry is said and the rest applied (corrections.h)
  std::optional<Corrections> corrections;
  if (!o.corrections.empty()) corrections = read_corrections_file(o.corrections);

  SessionOptions options;
  options.answers_name = o.answers;
  if (corrections) options.corrections = &*corrections;
  if (o.follow_through) options.follow_through = true;
  if (o.no_follow_through) options.follow_through = false;
  options.language = o.language;
  options.sheet_counts = counter.take_counts();
  GradingSession session(*key, std::move(options));
  const Texts& texts = session.texts();
  const TextVars versions{{"key", key->info.source},
                          {"key_epure", key->info.epure_version},
                          {"key_draw", std::to_string(key->info.draw_version)},
                          {"epure", EPURE_VERSION},
                          {"draw", std::to_string(kDrawVersion)}};
  if (key->info.draw_version != kDrawVersion)
    session.problem(0, texts.format("grading.problem.other_draw_version", versions), false, "version");
  else if (key->info.epure_version != EPURE_VERSION)
    session.problem(0, texts.format("grading.problem.other_epure_version", versions), false, "version");

  const std::string language = o.language.empty() ? key->info.language : o.language;
  const FeedbackText text(language, key->info.decimals);
  // out of 20 for a French set (the set's language, not the feedback's)
  const MarkScale scale = MarkScale::choose(key->info, key->info.language, o.out_of, o.round_to);
  std::optional<CsvReport> report;
  std::optional<JsonReport> json;
  std::optional<FeedbackSheets> sheets;
  std::optional<ClassReport> class_report;
  std::optional<Roster> roster;
  std::optional<Gradebook> gradebook;
  if (!o.roster.empty()) {
    roster = read_roster(o.roster);
    for (const auto& p : roster->problems) session.problem(p.line, describe(p, texts), p.error, "roster", o.roster);
  }
  // first among the outputs: what it finds (students left out) is in the JSON report's problems
  if (!o.gradebook.empty()) {
    const GradebookFormat format = o.gradebook[0] == "moodle" ? GradebookFormat::moodle : GradebookFormat::csv;
    gradebook.emplace(o.gradebook[1], format, *key, texts, scale, roster ? &*roster : nullptr,
                      [&session](int line, std::string message, bool error) {
                        session.problem(line, std::move(message), error, "gradebook");
                      });
    session.add_sink(*gradebook);
  }
  if (!o.report.empty()) {
    // the report in the dialect the first pass found
    const bool csv = dialect.format == "csv";
    report.emplace(o.report, *key,
                   CsvDialect{csv ? dialect.delimiter : ',', csv && dialect.delimiter == ';', dialect.bom, dialect.crlf},
                   texts, scale);
    session.add_sink(*report);
  }
  if (!o.json.empty()) {
    json.emplace(o.json, *key, text, o.answers, session.follow_through(), scale);
    session.add_sink(*json);
  }
  if (!o.feedback.empty()) {
    // scan --crops writes them beside its answers.json: found there without a flag
    std::filesystem::path crops = o.crops;
    if (crops.empty()) {
      const auto beside = std::filesystem::path(o.answers).parent_path() / "crops";
      std::error_code ec;
      if (std::filesystem::is_directory(beside, ec)) crops = beside;
    }
    sheets.emplace(o.feedback, *key, text, scale, grading::ScannedCrops(crops));
    session.add_sink(*sheets);
  }
  if (!o.class_report.empty()) {
    class_report.emplace(o.class_report, *key, text, scale);
    session.add_sink(*class_report);
  }
  const bool rows_on_stdout = o.report.empty() && o.json.empty();
  TextSummary summary(stdout, *key, text, scale, rows_on_stdout);
  if (!o.quiet || rows_on_stdout) session.add_sink(summary);

  const SourceInfo info = read_answers(o.answers, session, delimiter);
  const Outcome& outcome = session.finish(info);
  if (!o.histogram.empty()) output::write_file_atomically(o.histogram, histogram_svg(session.statistics(), text));
  if (sheets && !o.quiet)
    fmt::print("{}\n", texts.format("grading.problem.feedback_written",
                                     {{"count", std::to_string(sheets->written())}, {"dir", o.feedback}}));
  if (gradebook && !o.quiet)
    fmt::print("{}\n", texts.format("grading.roster.written", {{"file", o.gradebook[1]},
                                                                {"count", std::to_string(gradebook->written())},
                                                                {"format", o.gradebook[0]}}));
  return outcome.exit_status();
}

}  // namespace

void add_grade_command(CLI::App& app, int& status) {
  auto o = std::make_shared<GradeCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "grade", "Mark students' answers (CSV or JSON) against the key: reports, statistics, feedback sheets");
  auto* key = cmd->add_option("--key,-k", o->key_file, "The set's key.json (from epure generate)")->check(CLI::ExistingFile);
  auto* spec = cmd->add_option("--spec", o->spec_file,
                               "Instead of --key: the set's spec (TOML, or 'builtin' or 'builtin:3d'); keys rebuilt from the sheet ids")
                   ->check(spec_check());
  key->excludes(spec);
  cmd->add_option("--answers,-a", o->answers,
                  "Answers: CSV with a header row (a 'sheet' column, optional 'student', one column per question id) "
                  "or JSON (an array of objects, or one object per line)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--report,-r", o->report, "Write one CSV row per submission: sheet, student, score, max, points per question");
  cmd->add_option("--json", o->json, "Write every mark as JSON: expected, given, verdict, points, feedback, mistake code");
  cmd->add_option("--feedback", o->feedback, "Write a feedback sheet per student (<id>.svg and <id>.pdf) and class.svg into this directory");
  cmd->add_option("--crops", o->crops,
                  "The scanned fields' crops (epure scan --crops writes DIR/crops): each feedback line shows what was read; "
                  "default: the crops directory beside --answers, if there is one")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--histogram", o->histogram, "Write the class's score histogram (SVG)");
  auto* ft = cmd->add_flag("--follow-through", o->follow_through, "Credit answers right from a wrong earlier answer (overrides the spec)");
  auto* nft = cmd->add_flag("--no-follow-through", o->no_follow_through, "Do not credit follow-through (overrides the spec)");
  ft->excludes(nft);
  cmd->add_option("--lang", o->language, "Language of the feedback (default: the key's)")->check(CLI::IsMember({"en", "fr"}));
  cmd->add_option("--delimiter", o->delimiter, "CSV delimiter (default: detected among , ; and tab)")
      ->check(CLI::IsMember({",", ";", "tab", "\\t"}));
  cmd->add_option("--corrections", o->corrections,
                  "The teacher's corrections (JSON, as epure scan's review page writes them): cells replaced before marking")
      ->check(CLI::ExistingFile);
  cmd->add_option("--class-report", o->class_report,
                  "Write the class report (class-report.html and class-report.pdf: plots and item analysis) into this directory");
  cmd->add_option("--gradebook", o->gradebook,
                  "Write the marks for a gradebook: 'moodle FILE' (Moodle's CSV grade import) or 'csv FILE' (every student, "
                  "in the set's language)")
      ->expected(2);
  cmd->add_option("--roster", o->roster,
                  "The class roster (CSV: student number; name; optional e-mail): who is who in the gradebook")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out-of", o->out_of,
                  "Marks out of N (default: the spec's scale, else 20 for a French set, else the points)");
  cmd->add_option("--round-to", o->round_to, "Round each mark to the nearest multiple of this step, halves up (default 0.01)");
  cmd->add_flag("--quiet,-q", o->quiet, "No summary on stdout when a report is written");
  cmd->callback([o, &status] {
    if (!o->gradebook.empty() && o->gradebook[0] != "moodle" && o->gradebook[0] != "csv") {
      fmt::print(stderr, "epure grade: --gradebook {}: the format is moodle or csv (--gradebook moodle marks.csv)\n", o->gradebook[0]);
      status = 2;
      return;
    }
    if (o->key_file.empty() && o->spec_file.empty()) {
      fmt::print(stderr, "epure grade: give the set's key (--key key.json) or its spec (--spec FILE)\n");
      status = 2;
      return;
    }
    try {
      status = run_grade(*o);
    } catch (const std::exception& e) {
      fmt::print(stderr, "epure grade: {}\n", e.what());
      status = 2;
    }
  });
}

}  // namespace epure::cli
