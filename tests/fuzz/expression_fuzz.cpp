// The expression parser for typed answers (src/grading/expression.cpp): never throws, a number
// read is finite, a refusal says why in one of its three words, and the text's spelling does not
// matter: a decimal comma reads as the point, "−" as "-", blanks around as none.
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "grading/expression.h"

using namespace epure;
using namespace epure::grading;

namespace {

ParsedNumber parse(std::string_view text) {
  const ParsedNumber p = parse_number(text);
  if (p.ok) {
    fuzz::check(std::isfinite(p.value), "a number read is not finite", text);
  } else {
    fuzz::check(p.why == "number" || p.why == "division_by_zero" || p.why == "negative_root", "an unknown reason", p.why);
  }
  return p;
}

bool same(const ParsedNumber& a, const ParsedNumber& b) {
  if (a.ok != b.ok) return false;
  return !a.ok || a.value == b.value || (std::isnan(a.value) && std::isnan(b.value));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const ParsedNumber p = parse(text);
  fuzz::check(same(p, parse(text)), "the same text read twice differently", text);
  if (text.size() + 2 <= 256) {
    const ParsedNumber spaced = parse(" " + text + " ");
    fuzz::check(same(p, spaced), "blanks around the text change its value", text);
  }
  // a plain decimal is read as strtod reads it (the fast path and the parser agree)
  bool plain = !text.empty() && text.size() < 64;
  for (std::size_t i = 0; i < text.size() && plain; ++i) {
    const char c = text[i];
    plain = (c >= '0' && c <= '9') || (c == '.' && text.find('.') == i) || (c == '-' && i == 0);
  }
  if (plain && text.find_first_of("0123456789") != std::string::npos && text != "-" && text.back() != '.' &&
      text.front() != '.' && !(text.size() > 1 && text[0] == '-' && text[1] == '.')) {
    const double ref = std::strtod(text.c_str(), nullptr);
    if (std::isfinite(ref)) fuzz::check(p.ok && p.value == ref, "a plain decimal not read as strtod reads it", text);
  }
  return 0;
}
