#pragma once
// explore.html, the page of `epure explore` (src/explore/): the WebAssembly page embedded in the
// binary at build time, with its configuration written in: the language it opens in and, when a
// set wrote it, every sheet's instances, so that explore.html#<sheet id>.<n> opens that
// student's exercise n.
#include <functional>
#include <map>
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

// What a set's sheets call their exercises, by place, in each language the page can switch to
// ({"en": ["Preamble", "Exercise 1", …], "fr": […]}): a sheet's exercise opened from its link
// is titled as on the paper. Empty for the page of `epure explore` alone.
using ExerciseLabels = std::map<std::string, std::vector<std::string>, std::less<>>;

// The page, opening in `language`, with `sheets` (in increasing id order) reachable by their ids.
// Throws std::runtime_error when the page is not available (explore_unavailable_message()).
std::string explore_html(std::string_view language, const std::vector<ExploreSheet>& sheets = {},
                         const ExerciseLabels& labels = {});

// The same page written as a set's sheets come, into `write`: the page up to its configuration
// first, each sheet's instances as they are added, the rest at finish(). Nothing of the sheets
// is kept, so a set of any size writes it in the same memory. Sheets come in increasing id order
// (a set's index order; std::logic_error otherwise): the configuration is then the JSON object
// nlohmann writes, whose keys are sorted.
class ExplorePageWriter {
 public:
  using Write = std::function<void(std::string_view)>;
  // Throws std::runtime_error when the page is not available.
  ExplorePageWriter(std::string_view language, Write write, const ExerciseLabels& labels = {});
  void add(const ExploreSheet& sheet);
  void finish();

 private:
  void put(std::string text);
  Write write_;
  std::string_view page_;
  std::size_t config_at_ = 0;
  std::string last_id_;
  bool first_ = true;
};

}  // namespace epure::output
