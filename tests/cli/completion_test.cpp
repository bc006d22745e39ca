#include "cli/completion.h"

#include <doctest/doctest.h>

namespace {

bool contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

struct Sample {
  CLI::App app{"a sample tool", "epure"};
  int sheets = 30;
  std::string spec, kind, delimiter;
  bool quiet = false;
  Sample() {
    auto* gen = app.add_subcommand("generate", "Write a set: sheets and keys");
    gen->add_option("--sheets,-n", sheets, "Number of sheets [1, 99]")->capture_default_str();
    gen->add_option("--spec", spec, "Spec")->check(CLI::ExistingFile | CLI::IsMember({"builtin", "builtin:3d"}));
    gen->add_option("--delimiter", delimiter, "It's a delimiter")->check(CLI::IsMember({",", ";", "tab"}));
    gen->add_flag("--quiet,-q", quiet, "Quiet");
    app.add_subcommand("preview", "Draw")->add_option("kind", kind, "Kind")->required()->check(CLI::IsMember({"dot", "cross"}));
  }
};

}  // namespace

TEST_CASE("bash completion: the command tree as the script's tables") {
  Sample s;
  const std::string script = epure::cli::bash_completion(epure::cli::describe_commands(s.app), "9.8.7");
  CHECK(contains(script, "bash completion for epure 9.8.7"));
  CHECK(contains(script, "  ['epure']='generate preview'\n"));
  CHECK(contains(script, "  ['epure generate']='-h --help -n --sheets --spec --delimiter -q --quiet'\n"));
  CHECK(contains(script, "  ['epure generate --sheets']=none\n"));
  CHECK(contains(script, "  ['epure generate -n']=none\n"));
  CHECK(contains(script, "  ['epure generate --spec']=file+choices\n"));
  CHECK(contains(script, "  ['epure generate --spec']='builtin builtin:3d'\n"));
  CHECK(contains(script, "  ['epure generate --delimiter']='\\, \\; tab'\n"));  // as compgen -W reads them back
  CHECK(contains(script, "  ['epure preview #0']=choices\n"));
  CHECK(contains(script, "  ['epure preview #0']='dot cross'\n"));
  CHECK_FALSE(contains(script, "['epure generate --quiet']"));  // a flag has no value
  CHECK(contains(script, "\ncomplete -F _epure epure\n"));
}

TEST_CASE("zsh completion: an _arguments function per command") {
  Sample s;
  const std::string script = epure::cli::zsh_completion(epure::cli::describe_commands(s.app), "9.8.7");
  CHECK(script.starts_with("#compdef epure\n"));
  CHECK(contains(script, "_epure_cmd_epure_generate() {\n  _arguments -s -S : \\\n"));
  CHECK(contains(script, "'(-n --sheets)--sheets=[Number of sheets \\[1, 99\\]]:sheets: '"));
  CHECK(contains(script, "'(-n --sheets)-n+[Number of sheets \\[1, 99\\]]:sheets: '"));
  CHECK(contains(script, "'(--delimiter)--delimiter=[It'\\''s a delimiter]:delimiter:_epure_value_"));
  CHECK(contains(script, "'(-q --quiet)--quiet[Quiet]'"));
  CHECK(contains(script, "'(- *)--help[Print this help message and exit]'"));
  CHECK(contains(script, "local -a choices=('builtin' 'builtin:3d')\n  _alternative"));
  CHECK(contains(script, "'generate:Write a set: sheets and keys'"));
  CHECK(contains(script, "'1:kind:_epure_value_"));
  CHECK(contains(script, "(preview) _epure_cmd_epure_preview && ret=0 ;;"));
}
