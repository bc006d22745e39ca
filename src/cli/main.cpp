// epure — randomised geometry worksheets from a ray tracer's toolbox.
#include <CLI/CLI.hpp>

#include <iostream>

#include "cli/commands.h"
#include "exercises/sheet_id.h"

#ifndef EPURE_VERSION
#define EPURE_VERSION "0.0.0"
#endif

int main(int argc, char** argv) {
  CLI::App app{"epure: randomised geometry worksheets, their answer keys, and the solver behind them",
               "epure"};
  // the program's version, and the generator's that sheet ids carry (a key is rebuilt only by it)
  app.set_version_flag("--version", "epure " EPURE_VERSION " (draw version " + std::to_string(epure::kDrawVersion) + ")");
  app.require_subcommand(1);
  int status = 0;
  epure::cli::add_check_command(app, status);
  epure::cli::add_explore_command(app, status);
  epure::cli::add_generate_command(app, status);
  epure::cli::add_grade_command(app, status);
  epure::cli::add_export_command(app, status);
  epure::cli::add_kinds_command(app, status);
  epure::cli::add_scan_command(app, status);
  epure::cli::add_preview_command(app, status);
  epure::cli::add_solve_command(app, status);
  epure::cli::add_starter_command(app, status);
  epure::cli::add_docs_commands(app, status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, then the way to more: a usage error is exit status 2.
    std::cerr << "epure: " << e.what() << " (see 'epure --help')\n";
    return 2;
  }
  return status;
}
