#pragma once
// The command line as data: every visible subcommand, option and positional of the CLI11 App
// the program parses, with what each value is (a set of choices, a file, a directory, a number).
// The manual pages (man_page.h) and the shell completions (completion.h) are written from this
// walk, so that an option added to a subcommand is documented and completed with no other edit.
//
// What a value is comes from the option's own definition: its CLI11 checks (an IsMember set,
// written {a,b,…}; ExistingFile; ExistingDirectory; a Range) and its type (INT, UINT, FLOAT: a
// number). A free-text value is taken as a path (an output file or directory, as bash would
// complete it). Subcommands and options in the empty group (CLI11's hidden ones) are left out.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace epure::cli {

// What an option's value may be.
struct ValueDoc {
  std::vector<std::string> choices;  // a fixed set (an IsMember check), in the check's order
  bool file = false;                 // a path (alone, or beside the choices: --spec FILE|builtin)
  bool directory = false;            // a directory (ExistingDirectory)
  bool number = false;               // INT, UINT or FLOAT without choices: nothing to complete
  std::string placeholder;           // the value's name in a synopsis: KIND, FILE, SHEETS, …
  std::string range;                 // "1 to 32768" from a Range check, else empty
  std::string separator;             // "," for a list in one word (--format svg,pdf), else empty
};

struct OptionDoc {
  std::vector<std::string> names;  // short names first ("-n", "--sheets"); empty for a positional
  std::string positional;          // a positional's name ("kind"), else empty
  std::string description;
  std::string default_value;  // as the help shows it ("30"), empty when none is captured
  bool takes_value = false;   // false for a flag
  bool required = false;
  bool repeats = false;                // may be given several times (a positional: several values)
  std::vector<std::string> excludes;  // the options it cannot be given with (their first long name)
  std::string environment;            // the variable it is also read from (CLI11's envname), if any
  ValueDoc value;

  // "--sheets" (or "-n" if there is no long name; the positional's name for a positional).
  std::string main_name() const;
};

struct CommandDoc {
  std::vector<std::string> path;  // {"epure"}, {"epure", "generate"}, {"epure", "export", "qti"}
  std::string description;
  std::string footer;
  std::vector<OptionDoc> options;      // named options, in definition order (help first)
  std::vector<OptionDoc> positionals;  // in order
  std::vector<CommandDoc> subcommands;
  bool needs_subcommand = false;

  // "epure export qti"
  std::string command_line() const;
  // "epure-export-qti": the manual page's name
  std::string page_name() const;
};

// Walks the app (not const: CLI11 hands out its checks only from a mutable option).
CommandDoc describe_commands(CLI::App& app);

}  // namespace epure::cli
