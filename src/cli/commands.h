#pragma once
// One file per subcommand (CLI11's subcom_in_files manner): each registers its options on the
// app and runs the library; nothing here computes geometry.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "exercises/spec.h"

namespace epure::cli {

// Runs a subcommand's body: a spec error (the user's file) is exit status 2, any other failure
// (a file that cannot be written, …) 1, each reported as one line prefixed with the command.
template <class Body>
int run_reporting(const char* command, Body&& body) {
  try {
    return body();
  } catch (const SpecError& e) {
    fmt::print(stderr, "{}: {}\n", command, e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: {}\n", command, e.what());
    return 1;
  }
}

// A file the user named, whole (a key, a spec): "FILE: cannot read" when it cannot be opened.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read", path));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Registers `epure solve`; the callback stores its exit status in `status`.
void add_solve_command(CLI::App& app, int& status);
// Registers `epure generate`.
void add_generate_command(CLI::App& app, int& status);
// Registers `epure preview`.
void add_preview_command(CLI::App& app, int& status);
// Registers `epure kinds`.
void add_kinds_command(CLI::App& app, int& status);
// Registers `epure explore`.
void add_explore_command(CLI::App& app, int& status);
// Registers `epure grade`.
void add_grade_command(CLI::App& app, int& status);
// Registers `epure scan`.
void add_scan_command(CLI::App& app, int& status);
// Registers `epure export moodle|qti`.
void add_export_command(CLI::App& app, int& status);
// Registers `epure starter`.
void add_starter_command(CLI::App& app, int& status);
// Registers `epure check`.
void add_check_command(CLI::App& app, int& status);
// Registers `epure completion bash|zsh` and the hidden `epure __docs` (the manual pages and the
// completion scripts, written by the build): after every other command.
void add_docs_commands(CLI::App& app, int& status);

// A kind's name, checked against the registry (option_checks.cpp).
CLI::Validator kind_name_check();
// A spec: an existing file or a built-in spec's name (builtin, builtin:3d).
CLI::Validator spec_check();

}  // namespace epure::cli
