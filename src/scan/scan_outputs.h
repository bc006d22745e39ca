#pragma once
// What `epure scan` writes into its output directory (every file atomically):
//   answers.json, answers.csv  the read values, one row per sheet, as `epure grade` reads them
//                              (a field sent to review is left out until a correction settles it)
//   pages.csv                  every input page: file, page, sheet, sheet page, status, detail
//   sheets.csv                 every sheet: pages read and missing, student number read and the
//                              roster's, fields read, fields to review
//   fields.csv                 every field: its status (read, blank, review, corrected), value,
//                              confidence, each cell's character or each box's state, and why
//   review.html                every field to review, with its crop (one offline page)
//   crops/<sheet>/<question>.png  with --crops: every field as scanned (the feedback sheets of
//                              `epure grade` show each under its question), written by
//                              scan_inputs as each page is gathered
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "scan/layout_file.h"
#include "scan/scan_session.h"

namespace epure::scan {

std::string answers_json(const ScanResult& result);
std::string answers_csv(const ScanResult& result, const SetLayout& layout);
std::string pages_csv(const ScanResult& result);
std::string sheets_csv(const ScanResult& result);
std::string fields_csv(const ScanResult& result);
std::string review_html(const ScanResult& result, const SetLayout& layout);
// review.html a piece at a time (its crops read back from the result's spool one by one), the
// same bytes review_html returns.
void write_review_html(const ScanResult& result, const SetLayout& layout, const std::function<void(std::string_view)>& out);

// Every file above into `dir` (created if needed).
void write_scan_outputs(const std::filesystem::path& dir, const ScanResult& result, const SetLayout& layout);

// With --crops (ScanOptions::all_crops: every field's crop written as its page was gathered),
// says in the result's problems each field whose crop was left out, its sheet or question id not
// a file name; in sheet and question order, after the corrections' problems.
void say_crops_not_written(ScanResult& result);

// Fields sent to review and not settled by a correction.
std::size_t fields_to_review(const ScanResult& result);

}  // namespace epure::scan
