// Who a submission is from, read from its comments (src/check/sheet_tag.cpp): never throws; a
// sheet taken is a valid id whose text was written on its line; a refusal says why; a student's
// name is at most kMaxTagValue bytes of valid UTF-8 with no control character; the same bytes
// read the same twice.
#include <cstdint>

#include "check/sheet_tag.h"
#include "fuzz_support.h"

using namespace epure;
using namespace epure::check;

namespace {
bool valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return false;
    if (n == 1 && c < 0x20) return false;
    i += n;
  }
  return true;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const SubmissionTags t = read_tags(text);
  fuzz::check(t.student.size() <= kMaxTagValue && valid_utf8(t.student), "a student's name too long or not clean UTF-8",
              t.student);
  fuzz::check(t.sheet_text.size() <= kMaxTagValue && valid_utf8(t.sheet_text), "a sheet text too long or not clean", t.sheet_text);
  if (t.sheet) {
    fuzz::check(!t.sheet_problem, "a sheet taken and refused", text);
    const ParsedSheetId again = parse_sheet_id(t.sheet->str());
    fuzz::check(again.id && again.id->str() == t.sheet->str(), "a sheet taken that does not read back", t.sheet->str());
    fuzz::check(t.sheet_line >= 1, "a sheet without its line", text);
  }
  if (t.sheet_problem) fuzz::check(!t.sheet_problem->empty() && !t.sheet_text.empty(), "a refusal without its reason or text", text);
  const SubmissionTags again = read_tags(text);
  fuzz::check(again.student == t.student && again.sheet_text == t.sheet_text, "the same bytes read differently", text);
  return 0;
}
