#pragma once
// DIR/marks.csv, as a gradebook imports it: one row per file, `sheet`, `file`, `student`, one
// column per function (its mark in points: the share of its cases passed, or all or nothing),
// `total`. Comma-separated, UTF-8, RFC 4180 quoting; a function the file does not define is 0.
#include <filesystem>

#include "check/check.h"

namespace epure::check {

std::string marks_csv(const CheckResult& result, const CheckOptions& options);
void write_marks_csv(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& path);

}  // namespace epure::check
