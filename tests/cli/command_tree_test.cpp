#include "cli/command_tree.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <memory>

namespace {

using epure::cli::CommandDoc;
using epure::cli::OptionDoc;

// A small command line in the manner of epure's: every kind of value its commands use.
struct Sample {
  CLI::App app{"a sample tool", "tool"};
  int sheets = 30;
  std::uint64_t seed = 1;
  double dpi = 150;
  std::string spec, lang, out = "out", kind, key, answers, dir;
  bool quiet = false, yes = false, no = false;
  std::vector<std::string> files, formats{"svg", "pdf"};
  std::string delimiter;

  Sample() {
    app.set_version_flag("--version", "tool 1");
    auto* gen = app.add_subcommand("generate", "Write a set");
    gen->add_option("--sheets,-n", sheets, "Number of sheets")->check(CLI::Range(1, 32768))->capture_default_str();
    gen->add_option("--seed", seed, "Seed")->capture_default_str();
    gen->add_option("--dpi", dpi, "Resolution")->capture_default_str();
    gen->add_option("--spec", spec, "Spec")->check(CLI::ExistingFile | CLI::IsMember({"builtin", "builtin:3d"}));
    gen->add_option("--lang", lang, "Language")->check(CLI::IsMember({"en", "fr"}));
    gen->add_option("--paper", lang, "Paper")->transform(CLI::IsMember({"a4", "letter"}, CLI::ignore_case));
    gen->add_option("--out,-o", out, "Output directory")->capture_default_str();
    gen->add_option("--into", dir, "An existing directory")->check(CLI::ExistingDirectory);
    gen->add_flag("--quiet,-q", quiet, "Quiet");
    gen->add_option("--format", formats, "Formats")->delimiter(',')->check(CLI::IsMember({"svg", "pdf"}))->capture_default_str();
    gen->add_option("--delimiter", delimiter, "Delimiter")->check(CLI::IsMember({",", ";", "tab", "\\t"}));
    auto* preview = app.add_subcommand("preview", "Draw a kind");
    preview->add_option("kind", kind, "Kind")->required()->check(CLI::IsMember({"dot", "cross"}));
    auto* grade = app.add_subcommand("grade", "Grade");
    auto* k = grade->add_option("--key,-k", key, "Key")->check(CLI::ExistingFile);
    auto* s = grade->add_option("--spec", spec, "Spec");
    k->excludes(s);
    grade->add_option("--answers", answers, "Answers")->required();
    auto* y = grade->add_flag("--yes", yes, "Yes");
    auto* n = grade->add_flag("--no", no, "No");
    y->excludes(n);
    auto* exp = app.add_subcommand("export", "Export");
    exp->require_subcommand(1);
    exp->add_subcommand("qti", "QTI")->add_option("files", files, "Files");
    app.add_subcommand("__hidden", "Hidden")->group("");
    app.add_subcommand("gen2", "")->add_option("--secret", lang, "Secret")->group("");
  }
};

const OptionDoc& option(const CommandDoc& c, std::string_view name) {
  for (const auto& o : c.options)
    if (o.main_name() == name) return o;
  for (const auto& o : c.positionals)
    if (o.main_name() == name) return o;
  FAIL("no option " << name);
  throw;
}

}  // namespace

TEST_CASE("command tree: the commands, paths and page names, hidden ones left out") {
  Sample s;
  const CommandDoc root = epure::cli::describe_commands(s.app);
  CHECK(root.path == std::vector<std::string>{"tool"});
  CHECK(root.description == "a sample tool");
  REQUIRE(root.subcommands.size() == 5);  // generate preview grade export gen2; not __hidden
  CHECK(root.subcommands[0].command_line() == "tool generate");
  CHECK(root.subcommands[3].needs_subcommand);
  REQUIRE(root.subcommands[3].subcommands.size() == 1);
  CHECK(root.subcommands[3].subcommands[0].page_name() == "tool-export-qti");
  CHECK(root.subcommands[4].options.size() == 1);  // --help only: --secret is hidden
  CHECK(option(root, "--version").takes_value == false);
  CHECK(option(root, "--help").names == std::vector<std::string>{"-h", "--help"});
}

TEST_CASE("command tree: what each value is, from the option's own checks and type") {
  Sample s;
  const CommandDoc root = epure::cli::describe_commands(s.app);
  const CommandDoc& gen = root.subcommands[0];
  SUBCASE("1. a number in a range, with its default") {
    const OptionDoc& o = option(gen, "--sheets");
    CHECK(o.names == std::vector<std::string>{"-n", "--sheets"});
    CHECK(o.takes_value);
    CHECK(o.value.number);
    CHECK_FALSE(o.value.file);
    CHECK(o.value.range == "1 to 32768");
    CHECK(o.default_value == "30");
    CHECK(o.value.placeholder == "SHEETS");
    CHECK(option(gen, "--seed").value.number);
    CHECK(option(gen, "--dpi").value.number);
    CHECK(option(gen, "--dpi").default_value == "150");
  }
  SUBCASE("2. a file or a built-in name") {
    const OptionDoc& o = option(gen, "--spec");
    CHECK(o.value.file);
    CHECK(o.value.choices == std::vector<std::string>{"builtin", "builtin:3d"});
    CHECK(o.value.placeholder == "SPEC");
    CHECK(o.default_value.empty());
  }
  SUBCASE("3. choices, by a check or by a transform") {
    CHECK(option(gen, "--lang").value.choices == std::vector<std::string>{"en", "fr"});
    CHECK_FALSE(option(gen, "--lang").value.file);
    CHECK(option(gen, "--paper").value.choices == std::vector<std::string>{"a4", "letter"});
  }
  SUBCASE("4. free text is a path; a directory check is a directory") {
    CHECK(option(gen, "--out").value.file);
    CHECK(option(gen, "--out").default_value == "out");
    CHECK(option(gen, "--into").value.directory);
    CHECK(option(gen, "--into").value.placeholder == "DIR");
  }
  SUBCASE("5. a list in one word; a choice that is a comma") {
    const OptionDoc& f = option(gen, "--format");
    CHECK(f.value.separator == ",");
    CHECK(f.value.choices == std::vector<std::string>{"svg", "pdf"});
    CHECK(f.default_value == "svg,pdf");  // as typed, not CLI11's [svg,pdf]
    CHECK(option(gen, "--delimiter").value.choices == std::vector<std::string>{",", ";", "tab", "\\t"});
    CHECK(option(gen, "--delimiter").value.separator.empty());
  }
  SUBCASE("6. a flag takes no value") {
    const OptionDoc& o = option(gen, "--quiet");
    CHECK_FALSE(o.takes_value);
    CHECK(o.names == std::vector<std::string>{"-q", "--quiet"});
  }
  SUBCASE("7. positionals: required, with choices; repeated") {
    const CommandDoc& preview = root.subcommands[1];
    REQUIRE(preview.positionals.size() == 1);
    CHECK(preview.positionals[0].positional == "kind");
    CHECK(preview.positionals[0].required);
    CHECK(preview.positionals[0].value.choices == std::vector<std::string>{"dot", "cross"});
    CHECK(preview.positionals[0].value.placeholder == "KIND");
    const CommandDoc& qti = root.subcommands[3].subcommands[0];
    REQUIRE(qti.positionals.size() == 1);
    CHECK(qti.positionals[0].repeats);
    CHECK(qti.positionals[0].value.file);
  }
  SUBCASE("8. exclusions and required options") {
    const CommandDoc& grade = root.subcommands[2];
    CHECK(option(grade, "--key").excludes == std::vector<std::string>{"--spec"});
    CHECK(option(grade, "--key").value.placeholder == "FILE");
    CHECK(option(grade, "--yes").excludes == std::vector<std::string>{"--no"});
    CHECK(option(grade, "--answers").required);
  }
}
