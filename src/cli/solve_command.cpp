// `epure solve [FILE]`: JSON Lines in, one result per line out, in order.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "cli/commands.h"
#include "solve/solve.h"

namespace epure::cli {

namespace {

struct SolveOptions {
  std::string file;  // empty or "-": standard input
};

// Reads lines from `in`, writes results to stdout; bad lines are reported on stderr with their
// line number and the rest is still solved. Returns the exit status: 1 if any line failed.
int run_solve(std::istream& in, const std::string& name) {
  fmt::memory_buffer out;
  std::string line;
  long line_number = 0;
  int failed = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::string error = solve::solve_line(line, out);
    out.push_back('\n');
    if (!error.empty()) {
      ++failed;
      fmt::print(stderr, "epure solve: {}:{}: {}\n", name, line_number, error);
    }
    if (out.size() > (1 << 16)) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  if (in.bad()) {
    fmt::print(stderr, "epure solve: {}: read error after line {}\n", name, line_number);
    return 1;
  }
  return failed > 0 ? 1 : 0;
}

}  // namespace

void add_solve_command(CLI::App& app, int& status) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* cmd = app.add_subcommand(
      "solve", "Solve figures given as JSON Lines (one object per line); one JSON result per line");
  cmd->add_option("file", options->file, "Input file (default: standard input)");
  cmd->footer(
      "Kinds: vectors, projection, segments, ray_circle, ray_square, ray_ellipse, ray_rectangle,\n"
      "ray_sphere, ray_cube. A bad line yields {\"error\": ...} and the rest is still solved;\n"
      "the exit status is 1 if any line failed.");
  cmd->callback([options, &status] {
    std::ios::sync_with_stdio(false);
    if (options->file.empty() || options->file == "-") {
      status = run_solve(std::cin, "<stdin>");
      return;
    }
    std::ifstream in(options->file, std::ios::binary);
    if (!in) {
      fmt::print(stderr, "epure solve: cannot open '{}'\n", options->file);
      status = 2;
      return;
    }
    status = run_solve(in, options->file);
  });
}

}  // namespace epure::cli
