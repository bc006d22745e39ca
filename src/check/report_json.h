#pragma once
// DIR/report.json: for each file and each function, cases, passed, failed, verdict, bug (a code
// or null), the bugs named, and the first failing cases with their input, expected and got; the
// tolerances and the case counts it was checked under. Written atomically, the same bytes for
// the same files and options (no date, no timing, no temporary path).
#include <filesystem>

#include "check/check.h"

namespace epure::check {

void write_report_json(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& path);

// The inputs of a case by name ({"A": [x, y], "u": [...], "r": 2}), as report.json and the
// feedback pages show them.
struct NamedValue {
  std::string name;
  std::vector<double> values;
};
std::vector<NamedValue> named_inputs(const Case& c);
// What a function gave, by name: hit (for the rays and segments), then J/I/P and N.
std::vector<NamedValue> named_outputs(Fn fn, const Outcome& o);

}  // namespace epure::check
