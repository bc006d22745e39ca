#pragma once
// Shell completion scripts for bash and zsh, written from the command tree (command_tree.h):
// subcommands, options, an option's choices (--lang en|fr, --spec builtin:3d, the kinds of
// `epure preview KIND`, all read from the program's own checks), file and directory names where
// a path is expected, nothing where a number is.
#include <string>
#include <string_view>

#include "cli/command_tree.h"

namespace epure::cli {

// For bash-completion's completions/epure, or `source <(epure completion bash)`.
std::string bash_completion(const CommandDoc& root, std::string_view version);
// For zsh's fpath, as _epure, or `source <(epure completion zsh)` after compinit.
std::string zsh_completion(const CommandDoc& root, std::string_view version);

// A word in single quotes, as bash and zsh read it (a quote inside as '\'').
std::string single_quoted(std::string_view s);

}  // namespace epure::cli
