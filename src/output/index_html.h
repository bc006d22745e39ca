#pragma once
// index.html: every sheet and its key side by side, for a quick look in a browser.
#include <string>
#include <vector>

namespace epure::output {

struct IndexEntry {
  std::string id;
};

// `title` and `course` are escaped; images load lazily so that 3,000 sheets stay light.
std::string index_html(const std::string& title, const std::string& course,
                       const std::string& language, const std::vector<IndexEntry>& entries);

}  // namespace epure::output
