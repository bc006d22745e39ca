#pragma once
// DIR/summary.txt (and what `epure check` prints): one line per file (student, each function's
// verdict and cases passed, the bug named), then per function how many files passed it and the
// classic bugs named in the class, in the chosen language.
#include <filesystem>
#include <string>

#include "check/check.h"

namespace epure::check {

std::string summary_text(const CheckResult& result, const CheckOptions& options);
void write_summary_text(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& path);

}  // namespace epure::check
