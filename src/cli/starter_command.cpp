// `epure starter`: the files students start from (check/starter.h).
#include <fmt/format.h>

#include "check/starter.h"
#include "cli/commands.h"

namespace epure::cli {

namespace {

struct StarterCliOptions {
  std::string language = "fr";
  std::string out;
  bool force = false;
};

int run_starter(const StarterCliOptions& o) {
  const auto kept = check::write_starter(o.out, o.language, o.force);
  for (const auto& name : kept)
    fmt::print(stderr, "epure starter: {}/{} is there already: left as it is (--force to overwrite)\n", o.out, name);
  fmt::print("{}: raytracer.c, raytracer.h, g2x.h, g3x.h, README.md{}\n", o.out, kept.empty() ? "" : " (some kept)");
  return kept.empty() ? 0 : 1;
}

}  // namespace

void add_starter_command(CLI::App& app, int& status) {
  auto o = std::make_shared<StarterCliOptions>();
  CLI::App* cmd = app.add_subcommand("starter", "Write what students start from: the course's functions to write (C), its headers, a README");
  cmd->add_option("--lang", o->language, "Language of the comments and the README (default: fr, the course's)")
      ->check(CLI::IsMember({"en", "fr"}));
  cmd->add_option("--out,-o", o->out, "Directory to write into")->required();
  cmd->add_flag("--force", o->force, "Overwrite files already there");
  cmd->callback([o, &status] { status = run_reporting("epure starter", [&] { return run_starter(*o); }); });
}

}  // namespace epure::cli
