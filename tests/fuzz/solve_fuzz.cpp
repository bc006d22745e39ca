// solve JSON lines (src/solve): every line gives exactly one output line, a JSON object, and an
// error names its field ("field 'r': …") or the line ("line: …"). The flat fast path and the
// JSON tree agree: a line and its canonical re-serialisation give the same result.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdint>

#include "fuzz_support.h"
#include "solve/json_out.h"
#include "solve/solve.h"

using namespace epure;
using nlohmann::json;

namespace {

std::string solve_one(std::string_view line, solve::Semantics semantics, std::string& error) {
  fmt::memory_buffer out;
  out.append(std::string_view("previous\n"));  // a result is appended: what was there stays
  error = solve::solve_line(line, out, semantics);
  const std::string all(out.data(), out.size());
  fuzz::check(fuzz::starts_with(all, "previous\n"), "solve_line changed what was before its result", all);
  std::string result = all.substr(9);
  fuzz::check(result.find('\n') == std::string::npos, "a result spans several lines", result);
  const json parsed = json::parse(result, nullptr, false);
  fuzz::check(parsed.is_object(), "a result is not a JSON object", result);
  if (error.empty()) {
    fuzz::check(!parsed.contains("error"), "a solved line carries an error", result);
  } else {
    // the message as written: its bytes that are no UTF-8 become U+FFFD in JSON
    bool utf8 = true;
    for (std::size_t i = 0; i < error.size() && utf8;) {
      const std::size_t n = utf8_char_length(std::string_view(error).substr(i));
      utf8 = n != 0;
      i += n;
    }
    fuzz::check(parsed.size() == 1 && parsed.contains("error") && parsed["error"].is_string() &&
                    (!utf8 || parsed["error"] == error),
                "an error line is not {\"error\": message}", result);
    fuzz::check(fuzz::starts_with(error, "field '") || fuzz::starts_with(error, "line: "),
                "an error names neither a field nor the line", error);
  }
  return result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view input(reinterpret_cast<const char*>(data), size);
  // One line at a time, as `epure solve` hands them over.
  while (!input.empty()) {
    const auto nl = input.find('\n');
    const std::string_view line = input.substr(0, nl);
    input = nl == std::string_view::npos ? std::string_view{} : input.substr(nl + 1);
    for (auto semantics : {solve::Semantics::exact, solve::Semantics::worksheet}) {
      std::string error;
      const std::string result = solve_one(line, semantics, error);
      // The same figure, written canonically (no duplicate names, shortest numbers): the same
      // answer, whichever of the two readers takes it.
      const json figure = json::parse(line, nullptr, false);
      if (figure.is_discarded() || !figure.is_object()) continue;
      bool duplicate = false;  // nlohmann keeps the last of two names, the canonical text one
      std::size_t names = 0;
      json::parser_callback_t count = [&](int depth, json::parse_event_t e, json&) {
        if (depth == 1 && e == json::parse_event_t::key) ++names;
        return true;
      };
      (void)json::parse(line, count, false);
      duplicate = names != figure.size();
      if (duplicate) continue;
      std::string canonical_error;
      const std::string canonical = solve_one(figure.dump(), semantics, canonical_error);
      fuzz::check(canonical == result, "a line and its canonical JSON solve differently",
                  std::string(line) + "\n=> " + result + "\ncanonical " + figure.dump() + "\n=> " + canonical);
    }
  }
  return 0;
}
