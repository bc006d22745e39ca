#pragma once
// Writes a worksheet set to a directory: sheets/<id>.svg, keys/<id>.svg, key.json and
// index.html. Sheets stream through in small batches (memory stays flat for 10,000 sheets);
// with several jobs, drawing and drawing-to-SVG run in parallel and the output (order and bytes)
// is the same as with one.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "exercises/worksheet.h"

namespace epure::output {

struct GenerateOptions {
  int sheets = 30;
  std::filesystem::path out = "out";
  bool svg = true;
  int jobs = 1;
  std::string epure_version;
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
