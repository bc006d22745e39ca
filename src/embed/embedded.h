#pragma once
// The files of templates/ (texts per language, the built-in worksheet spec), compiled into the
// binary so that `epure` runs from anywhere with no install step.
#include <optional>
#include <string_view>
#include <vector>

namespace epure {

// The file's text by its path under templates/ ("text/en.toml", "course.toml").
std::optional<std::string_view> embedded_file(std::string_view name);
std::vector<std::string_view> embedded_files();

// The page of `epure explore` (one self-contained HTML file, src/explore/wasm.cmake), or nothing
// when this binary was built without emscripten.
std::optional<std::string_view> explore_page();

// The data files `epure scan` carries (src/scan/CMakeLists: the digit classifier's weights
// "classifier/digits.weights", the review page "review.html"), by their path under src/scan/.
std::optional<std::string_view> embedded_data(std::string_view name);

}  // namespace epure
