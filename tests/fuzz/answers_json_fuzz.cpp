// The answers JSON (src/grading/answer_source.cpp): JSON Lines give one row for every line that is
// not blank, an array one row per element (rows in = rows reported), rows as wide as the names
// seen, and a syntax error in an array stops the reading with a reason naming the byte.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>

#include "answers_support.h"

using namespace epure;
using namespace epure::grading;
using nlohmann::json;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  {
    // what read_answers takes as JSON ('[' or '{' first, after a byte-order mark and blanks);
    // the rest is answers_csv's
    std::string_view h = text;
    if (h.substr(0, 3) == "\xef\xbb\xbf") h.remove_prefix(3);
    const auto i = h.find_first_not_of(" \t\r\n");
    if (i == std::string_view::npos || (h[i] != '[' && h[i] != '{')) return 0;
  }
  fuzz::Recorder rec;
  rec.json = true;
  SourceInfo info;
  try {
    info = read_answers_text(text, "fuzz.json", rec);
  } catch (const std::exception& e) {
    fuzz::broken("a JSON reader threw", e.what());
  }
  fuzz::check(info.rows == static_cast<int>(rec.rows.size()), "rows in ≠ rows reported");
  if (info.format == "jsonl") {
    std::string_view t = text;
    if (t.substr(0, 3) == "\xef\xbb\xbf") t.remove_prefix(3);
    int lines = 0, blank = 0;
    while (!t.empty()) {  // the empty rest after a last '\n' is no line
      const auto nl = t.find('\n');
      const std::string_view l = t.substr(0, nl);
      ++lines;
      if (l.find_first_not_of(" \t\r") == std::string_view::npos) ++blank;
      if (nl == std::string_view::npos) break;
      t.remove_prefix(nl + 1);
    }
    fuzz::check(info.rows + info.blank_lines == lines && info.blank_lines == blank,
                "a JSON line gave no row or two");
  } else {
    fuzz::check(info.format == "json", "an unknown format", info.format);
    // brackets outside strings: a closer inside a string ("}}}") must not hide the depth of
    // the arrays after it, which the reader does count
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
      if (in_string) {
        if (escaped) escaped = false;
        else if (c == '\\') escaped = true;
        else if (c == '"') in_string = false;
        continue;
      }
      if (c == '"') in_string = true;
      if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
      if (c == ']' || c == '}') --depth;
    }
    if (fuzz::starts_with(info.stopped, "record ") && info.stopped.find(" is nested deeper than ") != std::string::npos) {
      // the limit (kMaxJsonDepth): only where the text nests that deep
      fuzz::check(deepest >= kMaxJsonDepth, "stopped as too deep, and is not", info.stopped);
      return 0;
    }
    const json whole = deepest < kMaxJsonDepth ? json::parse(text, nullptr, false) : json(json::value_t::discarded);
    if (deepest >= kMaxJsonDepth) {
      // not parsed whole here (the harness would hold the tree the limit spares the reader)
    } else if (!whole.is_discarded()) {
      fuzz::check(info.stopped.empty(), "a valid JSON file stopped", info.stopped);
      if (whole.is_array()) fuzz::check(static_cast<std::size_t>(info.rows) == whole.size(), "array elements ≠ rows");
    } else {
      fuzz::check(!info.stopped.empty() && (info.stopped.find("byte ") != std::string::npos ||
                                             info.stopped.find("number overflow") != std::string::npos),
                  "invalid JSON read to the end, or stopped without naming the byte", info.stopped);
    }
  }
  return 0;
}
