#pragma once
// index.html: every sheet and its key side by side, for a quick look in a browser.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace epure::output {

struct IndexEntry {
  std::string id;
  int exercises = 0;  // linked to explore.html#<id>.<n> when the set wrote explore.html
};

// Which PDFs were written beside the SVGs, to link them.
enum class PdfLinks { none, class_set, per_sheet };

// `title` and `course` are escaped; images load lazily so that 3,000 sheets stay light. Written
// into `write` a sheet at a time: the page of a large set is never held whole.
void write_index_html(const std::function<void(std::string_view)>& write, const std::string& title,
                      const std::string& course, const std::string& language,
                      const std::vector<IndexEntry>& entries, PdfLinks pdfs = PdfLinks::none, bool explore = false);

}  // namespace epure::output
