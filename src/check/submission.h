#pragma once
// A student's C file read before any compiler sees it. The compiler reads whatever a file
// includes, so the preprocessor's door to the file system is checked first, on the text as the
// compiler's first translation phases see it (trigraphs, line splices, comments, digraphs):
//
//   - #include only of the starter's headers (raytracer.h, g2x.h, g3x.h) and of the C standard
//     library's, by name (no path, no macro that expands to one);
//   - none of the directives that read or name other files, or change what messages say
//     (#include_next, #import, #embed, #line and GNU line markers, #pragma but `once`,
//     `GCC diagnostic` and `STDC`), nor _Pragma, __has_include, or asm;
//   - at most kMaxSubmissionBytes, no NUL byte.
//
// A file refused here is not compiled; the refusal names the line. What gets past is compiled in
// a Landlock sandbox all the same (compile.h): these checks make the common cases clear, the
// sandbox holds for the rest (a name pasted together by ## that the scan cannot see).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check/functions.h"

namespace epure::check {

inline constexpr std::size_t kMaxSubmissionBytes = 256 * 1024;

struct Refusal {
  int line = 0;  // 1-based; 0 for the file as a whole
  std::string code;    // "include", "directive", "pragma", "identifier", "size", "nul"
  std::string detail;  // what was found: the header's name, the directive, the identifier
};

struct SubmissionScan {
  std::optional<Refusal> refusal;
  std::vector<std::string> includes;  // the headers it includes, in order
  std::vector<Fn> mentioned;          // the course's functions whose names it holds, in order
};

SubmissionScan scan_submission(std::string_view source);

// Whether `name` (as written between the quotes or brackets) is a header a submission may include.
bool allowed_header(std::string_view name);

// The text of every comment, with the line it starts on, after the translation phases (so that
// a tag in a comment reads as the compiler would see the comment). For sheet_tag.h.
struct Comment {
  int line;
  std::string text;
};
std::vector<Comment> comments_of(std::string_view source);

}  // namespace epure::check
