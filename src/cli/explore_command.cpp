// `epure explore [--out DIR] [--lang en|fr]`: writes DIR/explore.html, the interactive page of
// every algorithm of the solve contract (src/explore/), one self-contained file.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "exercises/texts.h"
#include "output/atomic_file.h"
#include "output/explore_page.h"

namespace epure::cli {

namespace {

struct ExploreOptions {
  std::filesystem::path out = "out";
  std::string language = "en";
};

}  // namespace

void add_explore_command(CLI::App& app, int& status) {
  auto options = std::make_shared<ExploreOptions>();
  CLI::App* cmd = app.add_subcommand(
      "explore", "Write explore.html: every algorithm as an interactive figure with its worked steps (offline)");
  cmd->add_option("--out", options->out, "Directory to write explore.html into (default: out)");
  cmd->add_option("--lang", options->language, "Language of the worked steps: en or fr (default: en)");
  cmd->callback([options, &status] {
    status = run_reporting("epure explore", [&] {
      Texts::builtin(options->language);  // an unknown language is refused here, with the list
      if (!output::explore_available()) throw std::runtime_error(output::explore_unavailable_message());
      std::filesystem::create_directories(options->out);
      const auto path = options->out / "explore.html";
      output::write_file_atomically(path, output::explore_html(options->language));
      fmt::print("wrote {}\n", path.string());
      return 0;
    });
  });
}

}  // namespace epure::cli
