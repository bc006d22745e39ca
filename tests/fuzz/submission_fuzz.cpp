// The scan of a student's C file before gcc sees it (src/check/submission.cpp): never throws;
// a refusal has a known code and a line within the file; a file accepted includes only allowed
// headers, has no NUL and is within the size limit; a file with a forbidden #include appended
// on a line of its own is refused (whatever came before it cannot hide it: it is scanned the
// way the preprocessor scans, comments and splices included); the mentioned functions are
// distinct; the same bytes scan the same twice.
#include <algorithm>
#include <cstdint>

#include "check/submission.h"
#include "fuzz_support.h"

using namespace epure;
using namespace epure::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const SubmissionScan s = scan_submission(text);
  const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
  if (s.refusal) {
    const std::string& c = s.refusal->code;
    fuzz::check(c == "include" || c == "directive" || c == "pragma" || c == "identifier" || c == "size" || c == "nul",
                "a refusal of an unknown code", c);
    fuzz::check(s.refusal->line >= 0 && s.refusal->line <= lines, "a refusal's line outside the file", text);
  } else {
    fuzz::check(text.size() <= kMaxSubmissionBytes && text.find('\0') == std::string_view::npos,
                "a file accepted past the size limit or with a NUL", text);
    for (const auto& h : s.includes) fuzz::check(allowed_header(h), "an include accepted that is not allowed", h);
  }
  for (std::size_t i = 0; i < s.mentioned.size(); ++i)
    for (std::size_t j = i + 1; j < s.mentioned.size(); ++j)
      fuzz::check(s.mentioned[i] != s.mentioned[j], "a function mentioned twice", text);
  const SubmissionScan again = scan_submission(text);
  fuzz::check(again.refusal.has_value() == s.refusal.has_value() && again.includes == s.includes,
              "the same bytes scan differently", text);
  // A forbidden include on a line of its own after the file: refused, unless the file leaves an
  // open comment (then it is a comment's text: the compiler does not see a directive either),
  // or an unterminated splice or literal ends the file.
  if (text.size() < 4096 && text.find('\0') == std::string_view::npos) {
    const std::string closed = std::string(text) + "\n*/\n\"\n'\n#include </etc/passwd>\n";
    const SubmissionScan tail = scan_submission(closed);
    fuzz::check(tail.refusal.has_value(), "an #include of /etc/passwd got through", closed);
  }
  // comments: each on a line of the file
  for (const Comment& c : comments_of(text)) fuzz::check(c.line >= 1 && c.line <= lines, "a comment outside the file", text);
  return 0;
}
