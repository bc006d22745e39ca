#pragma once
// One file per subcommand (CLI11's subcom_in_files manner): each registers its options on the
// app and runs the library; nothing here computes geometry.
#include <CLI/CLI.hpp>

namespace epure::cli {

// Registers `epure solve`; the callback stores its exit status in `status`.
void add_solve_command(CLI::App& app, int& status);
// Registers `epure generate`.
void add_generate_command(CLI::App& app, int& status);
// Registers `epure grade`.
void add_grade_command(CLI::App& app, int& status);

}  // namespace epure::cli
