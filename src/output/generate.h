#pragma once
// Writes a worksheet set to a directory: key.json, and as SVG sheets/<id>.svg, keys/<id>.svg and
// index.html, as PDF sheets.pdf and keys.pdf (the class set in id order) or, split, one
// sheets/<id>.pdf and keys/<id>.pdf per sheet. Sheets stream through in small batches and every
// file is written as they come, so memory stays flat whatever the number of sheets (issue 37);
// with several jobs, drawing, layout and SVG run in parallel and the output (order and bytes) is
// the same as with one.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <vector>

#include "exercises/key_json.h"
#include "exercises/worksheet.h"

namespace epure::output {

struct GenerateOptions {
  int sheets = 30;
  std::filesystem::path out = "out";
  bool svg = true;
  bool pdf = false;  // the CLI's default is both; the library's, SVG alone
  bool split = false;   // PDF: one file per sheet and per key instead of the class-set files
  bool duplex = false;  // PDF class sets: every sheet starts on an odd page (blank pages added)
  std::optional<std::int64_t> pdf_date;  // the PDFs' creation date (SOURCE_DATE_EPOCH)
  int jobs = 1;
  std::string epure_version;
  // A roster's students (`generate --roster`): one sheet each, in this order (`sheets` must be
  // their number), their name and number printed on its first page instead of the name line and
  // the number's comb, recorded in key.json and layout.json. Empty: anonymous sheets.
  std::vector<SheetStudent> students;
  // Called after each batch with the number of sheets written so far.
  std::function<void(int done, int total)> progress;
};

struct GenerateReport {
  int sheets = 0;
  std::string first_id, last_id;
};

// Throws std::runtime_error (file errors) or SpecError.
GenerateReport generate_set(WorksheetSet& set, const GenerateOptions& options);

}  // namespace epure::output
