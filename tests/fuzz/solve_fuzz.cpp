// solve JSON lines (src/solve): every line gives exactly one output line, a JSON object, and an
// error names its field ("field 'r': …") or the line ("line: …"). The flat fast path and the
// JSON tree agree: a line and its canonical re-serialisation give the same result.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>

#include "fuzz_support.h"
#include "geometry/decimal.h"
#include "solve/json_out.h"
#include "solve/solve.h"

using namespace epure;
using nlohmann::json;

namespace {

std::string solve_one(std::string_view line, std::string& error) {
  fmt::memory_buffer out;
  out.append(std::string_view("previous\n"));  // a result is appended: what was there stays
  error = solve::solve_line(line, out);
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

// The number tokens of a line (outside its strings), and whether each is, as a decimal, what
// nlohmann's dump writes for its double: only then does the canonical text mean the same numbers. Each token's reading is checked on the way: hi is the
// double strtod gives, and hi + lo is the decimal to within the bound Decimal::error states.
bool numbers_are_shortest(std::string_view line) {
  bool in_string = false, shortest = true;
  for (std::size_t i = 0; i < line.size();) {
    const char c = line[i];
    if (in_string) {
      if (c == '\\') i += 2;
      else {
        in_string = c != '"';
        ++i;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
      ++i;
      continue;
    }
    if (!(c == '-' || (c >= '0' && c <= '9'))) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < line.size() && std::string_view("0123456789.eE+-").find(line[j]) != std::string_view::npos) ++j;
    const std::string token(line.substr(i, j - i));
    i = j;
    const json parsed = json::parse(token, nullptr, false);
    if (parsed.is_discarded() || !parsed.is_number()) continue;
    const double x = parsed.get<double>();
    if (!std::isfinite(x)) continue;
    const geo::Decimal d = geo::read_decimal(token, x);
    const auto rest = geo::exact::exact_value(d) - geo::exact::exact_value(x) - geo::exact::exact_value(d.lo);
    const auto bound = geo::exact::exact_value(d.error());
    fuzz::check((rest.m.sign() >= 0 ? (bound - rest) : (bound + rest)).m.sign() >= 0,
                "a number's rest is off by more than its error bound", token);
    // the text the canonical line holds: nlohmann's own writing of the double, which is a
    // shortest round trip but not always the one nearest the double (2.9802322387695312e-08 is
    // written ...313e-08, another decimal of the same double)
    const std::string canonical_text = json(x).dump();
    if (!geo::same_value(d, geo::read_decimal(canonical_text, x))) shortest = false;
  }
  return shortest;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view input(reinterpret_cast<const char*>(data), size);
  // One line at a time, as `epure solve` hands them over.
  while (!input.empty()) {
    const auto nl = input.find('\n');
    const std::string_view line = input.substr(0, nl);
    input = nl == std::string_view::npos ? std::string_view{} : input.substr(nl + 1);
    {
      std::string error;
      const std::string result = solve_one(line, error);
      // The same figure, written canonically (no duplicate names, shortest numbers): the same
      // answer, whichever of the two readers takes it, when its numbers are the same decimals.
      if (!numbers_are_shortest(line)) continue;
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
      const std::string canonical = solve_one(figure.dump(), canonical_error);
      fuzz::check(canonical == result, "a line and its canonical JSON solve differently",
                  std::string(line) + "\n=> " + result + "\ncanonical " + figure.dump() + "\n=> " + canonical);
    }
  }
  return 0;
}
