#pragma once
// layout.json: where a scan looks. `epure generate` writes it beside the set, from the same
// laid-out pages the PDF is drawn from; `epure scan` reads it (README, "layout.json"). For every
// sheet and page: the page's size, the centres of its four corner marks, the rectangle of its
// code, and every answer field with its question id, its type (comb: one character per cell;
// tick: boxes, each standing for an answer) and its cells' rectangles, in PDF points from the
// page's top-left corner, y down.
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace epure::scan {

struct Rect {
  double x = 0, y = 0, width = 0, height = 0;
  double cx() const { return x + width / 2; }
  double cy() const { return y + height / 2; }
};

struct Point {
  double x = 0, y = 0;
};

enum class FieldType { comb, tick };

struct FieldLayout {
  std::string question;  // "2.t", "2.P.x", "student_number"
  FieldType type = FieldType::comb;
  std::vector<Rect> cells;
  // comb: a first cell for the sign; the last `decimals` cells after the decimal separator
  bool sign = false;
  int decimals = 0;
  // tick: what each box stands for, as a student types it in the answers spreadsheet; whether
  // one box (a choice, yes/no) or any number of them (sides) may be ticked
  std::vector<std::string> values;
  bool multiple = false;
};

struct PageLayout {
  int page = 1;
  double width = 0, height = 0;
  std::array<Point, 4> marks;  // top-left, top-right, bottom-right, bottom-left
  double mark_size = 0;        // a mark's side
  Rect code;                   // the page code's modules and quiet zone
  std::vector<FieldLayout> fields;
};

struct StudentLayout {
  std::string number;
  std::string name;
};

struct SheetLayout {
  std::string sheet;
  std::optional<StudentLayout> student;  // from `generate --roster`
  std::vector<PageLayout> pages;
};

struct SetLayout {
  std::string title;
  std::string language = "en";
  std::string decimal_separator = ".";
  std::uint64_t seed = 0;
  int draw_version = 1;
  std::map<std::string, SheetLayout, std::less<>> sheets;

  const SheetLayout* find(std::string_view sheet) const {
    auto it = sheets.find(sheet);
    return it == sheets.end() ? nullptr : &it->second;
  }
};

class LayoutError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads a layout.json's text; `source` names it in messages. Throws LayoutError naming the
// sheet, page and field at fault.
SetLayout read_layout(std::string_view text, const std::string& source);
SetLayout read_layout_file(const std::string& path);

// The same as JSON text (the test fixtures write layouts with it).
std::string layout_json(const SetLayout& layout);
// The same written as it comes (`epure generate`, sheet after sheet, memory flat): begin (the
// set's fields; its sheets are not read), each sheet (first = true for the first), end.
std::string layout_json_begin(const SetLayout& layout);
std::string layout_json_sheet(const SheetLayout& sheet, bool first);
std::string layout_json_end();

inline constexpr std::size_t kMaxLayoutBytes = std::size_t{1} << 30;
inline constexpr int kMaxLayoutDepth = 16;
inline constexpr std::size_t kMaxPagesPerSheet = 64;
inline constexpr std::size_t kMaxCellsPerField = 64;

}  // namespace epure::scan
