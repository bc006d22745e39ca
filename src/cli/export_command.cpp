// `epure export moodle|qti --set DIR`: a generated set published to a learning platform, one
// online question per student variant and exercise (src/export/).
#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "export/export_set.h"
#include "export/moodle_xml.h"
#include "export/qti_package.h"
#include "output/atomic_file.h"

namespace epure::cli {

namespace {

struct ExportOptions {
  std::string set;
  std::string out;  // default: DIR/moodle.xml or DIR/qti.zip
  std::string language;
  std::string image = "png";
};

int run_export(const ExportOptions& o, bool moodle) {
  const char* command = moodle ? "epure export moodle" : "epure export qti";
  exporting::ExportSet set;
  try {
    set = exporting::read_set(o.set, o.language,
                              o.image == "svg" ? exporting::ImageFormat::svg : exporting::ImageFormat::png);
  } catch (const exporting::ExportError& e) {
    fmt::print(stderr, "{}: {}\n", command, e.what());
    return 2;  // nothing could be exported
  }
  const std::filesystem::path out =
      o.out.empty() ? std::filesystem::path(o.set) / (moodle ? "moodle.xml" : "qti.zip") : std::filesystem::path(o.out);
  output::write_file_atomically(out, moodle ? exporting::moodle_xml(set) : exporting::qti_package(set));
  std::size_t questions = 0;
  for (const auto& slot : set.exercises) questions += slot.variants.size();
  fmt::print("{}: {} questions ({} exercises, one question per sheet in each) into {}\n", command, questions,
             set.exercises.size(), out.string());
  return 0;
}

void add_target(CLI::App& parent, const char* name, const char* what, bool moodle, int& status) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* cmd = parent.add_subcommand(name, what);
  cmd->add_option("--set", o->set, "A set written by 'epure generate' (its key.json)")->required();
  cmd->add_option("--out,-o", o->out, moodle ? "Output file (default DIR/moodle.xml)" : "Output file (default DIR/qti.zip)");
  cmd->add_option("--lang", o->language, "Language of the questions (default: the set's)")
      ->check(CLI::IsMember({"en", "fr"}));
  cmd->add_option("--image", o->image, "Diagrams as png (drawn by cairo) or svg")
      ->check(CLI::IsMember({"png", "svg"}))
      ->capture_default_str();
  const char* command = moodle ? "epure export moodle" : "epure export qti";
  cmd->callback([o, moodle, command, &status] { status = run_reporting(command, [&] { return run_export(*o, moodle); }); });
}

}  // namespace

void add_export_command(CLI::App& app, int& status) {
  CLI::App* cmd = app.add_subcommand("export", "Publish a set to a learning platform (Moodle XML, QTI 2.1)");
  cmd->require_subcommand(1);
  add_target(*cmd, "moodle", "Moodle XML: one Cloze question per variant, a category per exercise", true, status);
  add_target(*cmd, "qti", "QTI 2.1 content package (zip): one item per variant, a section per exercise", false, status);
}

}  // namespace epure::cli
