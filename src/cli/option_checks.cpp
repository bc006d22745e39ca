// Option checks whose lists come from the program itself (the kinds' registry, the built-in
// specs), never from a copy: the help, the manual pages and the shell completion read them.
#include <fmt/format.h>

#include <algorithm>

#include "cli/commands.h"
#include "exercises/exercise.h"
#include "exercises/spec.h"

namespace epure::cli {

CLI::Validator kind_name_check() {
  std::vector<std::string> names;
  for (const ExerciseKind* kind : all_kinds()) names.emplace_back(kind->name());
  // described as CLI11's IsMember describes a set, {a,b,…}, which command_tree.h reads
  return CLI::Validator(
      [names](std::string& value) -> std::string {
        if (std::find(names.begin(), names.end(), value) != names.end()) return {};
        return fmt::format("unknown kind '{}' (kinds: {})", value, fmt::join(names, ", "));
      },
      fmt::format("{{{}}}", fmt::join(names, ",")), "KIND");
}

CLI::Validator spec_check() { return CLI::ExistingFile | CLI::IsMember(builtin_spec_names()); }

}  // namespace epure::cli
