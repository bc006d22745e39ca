#pragma once
// The manual pages, in roff (man(7)), written from the command tree (command_tree.h): epure(1)
// and one page per subcommand (epure-generate(1), epure-export-qti(1), …), each listing every
// option with its value, choices, range and default, as the program parses them.
#include <string>
#include <string_view>
#include <vector>

#include "cli/command_tree.h"

namespace epure::cli {

struct ManPage {
  std::string name;  // "epure-generate": the file is <name>.1
  std::string roff;
};

// The pages of the root and of every subcommand below it, the root's first. `version` is the
// program's ("0.1.0"), `draw_version` the generator's; no date, so the same program writes the
// same bytes.
std::vector<ManPage> man_pages(const CommandDoc& root, std::string_view version, int draw_version);

// Text as roff: backslashes escaped, option dashes as \-, characters outside ASCII as \[uXXXX],
// a line that would start with '.' or '\'' guarded by \&.
std::string roff_escape(std::string_view text);

}  // namespace epure::cli
