// `epure completion bash|zsh`: the completion script on stdout. `epure __docs --out DIR` (hidden,
// run by the build): the manual pages and both completion scripts into DIR. Both are written
// from the options the program parses (command_tree.h), so a new option or subcommand is
// documented and completed with no other edit.
#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "cli/completion.h"
#include "cli/man_page.h"
#include "exercises/sheet_id.h"
#include "output/atomic_file.h"

#ifndef EPURE_VERSION
#define EPURE_VERSION "0.0.0"
#endif

namespace epure::cli {

namespace {

// DIR/man1/<page>.1, DIR/bash-completion/epure, DIR/zsh/_epure; the pages of commands that are
// gone are removed.
int write_docs(CLI::App& app, const std::filesystem::path& out) {
  const CommandDoc root = describe_commands(app);
  const auto man = out / "man1";
  std::filesystem::create_directories(man);
  for (const auto& entry : std::filesystem::directory_iterator(man))
    if (entry.path().extension() == ".1") std::filesystem::remove(entry.path());
  const auto pages = man_pages(root, EPURE_VERSION, kDrawVersion);
  for (const auto& page : pages) output::write_file_atomically(man / (page.name + ".1"), page.roff);
  std::filesystem::create_directories(out / "bash-completion");
  output::write_file_atomically(out / "bash-completion" / "epure", bash_completion(root, EPURE_VERSION));
  std::filesystem::create_directories(out / "zsh");
  output::write_file_atomically(out / "zsh" / "_epure", zsh_completion(root, EPURE_VERSION));
  fmt::print("epure __docs: {} manual pages and the bash and zsh completions into {}/\n", pages.size(), out.string());
  return 0;
}

}  // namespace

void add_docs_commands(CLI::App& app, int& status) {
  auto shell = std::make_shared<std::string>();
  CLI::App* completion = app.add_subcommand(
      "completion", "Print the shell completion script for bash or zsh (for this shell: source <(epure completion bash))");
  completion->add_option("shell", *shell, "The shell")->required()->check(CLI::IsMember({"bash", "zsh"}));
  completion->callback([&app, shell, &status] {
    status = run_reporting("epure completion", [&] {
      const CommandDoc root = describe_commands(app);
      fmt::print("{}", *shell == "zsh" ? zsh_completion(root, EPURE_VERSION) : bash_completion(root, EPURE_VERSION));
      return 0;
    });
  });

  auto out = std::make_shared<std::string>();
  CLI::App* docs = app.add_subcommand("__docs", "Write the manual pages and the completion scripts (run by the build)");
  docs->group("");  // hidden: not in the help, the pages or the completion
  docs->add_option("--out", *out, "Directory to write into")->required();
  docs->callback([&app, out, &status] { status = run_reporting("epure __docs", [&] { return write_docs(app, *out); }); });
}

}  // namespace epure::cli
