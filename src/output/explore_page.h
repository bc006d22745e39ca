#pragma once
// explore.html, the page of `epure explore` (src/explore/): the WebAssembly page embedded in the
// binary at build time, with its configuration written in: the language it opens in and, when a
// set wrote it, every sheet's instances, so that explore.html#<sheet id>.<n> opens that
// student's exercise n.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace epure::output {

// One sheet's exercises as solve inputs (key.json's "instance" texts), in sheet order.
struct ExploreSheet {
  std::string id;
  std::vector<std::string> instances;
};

// Whether this binary holds the page (it was built with em++).
bool explore_available();

// Why it does not, for the user.
std::string explore_unavailable_message();

// The page, opening in `language`, with `sheets` reachable by their ids. Throws
// std::runtime_error when the page is not available (explore_unavailable_message()).
std::string explore_html(std::string_view language, const std::vector<ExploreSheet>& sheets = {});

}  // namespace epure::output
