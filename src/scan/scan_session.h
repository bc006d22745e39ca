#pragma once
// `epure scan`: every page of every input read, identified, registered and its fields read;
// then the pages gathered by sheet (a page seen twice is a duplicate; a page missing is said).
// Pages are decoded one at a time by one thread and read by `jobs` others through a short queue;
// each page read is gathered as soon as the pages before it in the input are (so the first copy
// of a page counts whatever the number of jobs), and then all it keeps is its fields' readings:
// its image is gone, a duplicate's readings are dropped, its crops are written (--crops) or set
// aside on disk (review.html's). So memory stays flat over any number of pages but for the
// readings themselves, a few hundred bytes a field.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "grading/corrections.h"
#include "scan/crop_spool.h"
#include "scan/digit_classifier.h"
#include "scan/field_reading.h"
#include "scan/layout_file.h"

namespace epure::scan {

enum class PageStatus { identified, duplicate, unknown, blank, another_set, unreadable };
const char* page_status_name(PageStatus s);

struct PageRecord {
  std::string file;
  int page = 1;            // in its file
  std::string sheet;       // from its code, when read
  int sheet_page = 0;      // the page of that sheet, 0 when unknown
  PageStatus status = PageStatus::unreadable;
  std::string detail;      // why, for every status but identified
  int marks = 0;
  double residual = 0;     // points
};

struct FieldResult {
  FieldReading reading;
  int page = 0;                 // the sheet's page it is on
  CropRef crop;                 // the field as scanned, a PNG in the result's spool (uncertain fields only)
  bool corrected = false;       // settled by a correction
  std::string note;             // the correction's note
};

struct SheetResult {
  std::string sheet;
  int pages = 0;                       // the sheet's page count (layout)
  std::vector<bool> seen;              // per page: identified
  std::map<std::string, FieldResult> fields;  // by question id, in id order
  std::string student_number;          // as read ("" when not read or uncertain)
  std::string student_name;            // from the roster
  std::string roster_number;           // from the roster
  // The roster's number printed on the sheet (`generate --roster`): no comb to read it from.
  bool number_printed = false;
};

struct ScanOptions {
  int jobs = 0;            // 0: every core
  int render_dpi = 200;    // PDF pages without one embedded image
  // Write every field's crop (the feedback sheets) into out/crops/<sheet id>/<question id>.png
  // as its page is gathered; a field whose id cannot be a file name is left out (say_crops_not_written).
  bool all_crops = false;
  std::filesystem::path out;  // the output directory: the crops, and the spool of review.html's crops (empty: the temporary directory)
};

struct ScanResult {
  std::vector<PageRecord> pages;               // every input page, in input order
  std::map<std::string, SheetResult> sheets;   // every sheet with an identified page
  std::vector<std::string> problems;           // corrections that could not be applied, …
  std::shared_ptr<CropSpool> spool;            // the uncertain fields' crops (none: no crop)

  // The field's crop (a PNG), "" when it has none.
  std::string crop(const FieldResult& f) const { return spool && f.crop.size > 0 ? spool->read(f.crop) : std::string(); }
};

ScanResult scan_inputs(const std::vector<std::string>& inputs, const SetLayout& layout, const ScanOptions& options,
                       const DigitClassifier& net);

// Applies a teacher's corrections (grading/corrections.h: the file `epure grade --corrections`
// reads too), each to its sheet (any case, with or without dashes) and field (the question id in
// any case, or student_number). Each entry that cannot be placed (a sheet not scanned, a field
// not on its scanned pages), or that corrects a field again, is said in `texts`' language
// ("c.json: entry 3: …") in result.problems; the problems of the file itself are said by the
// caller. The last correction of a field is the one applied, as `epure grade` does.
void apply_corrections(ScanResult& result, const grading::Corrections& corrections, const Texts& texts);

}  // namespace epure::scan
