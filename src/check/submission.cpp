#include "check/submission.h"

#include <algorithm>
#include <array>
#include <cctype>

#include <fmt/format.h>

namespace epure::check {

namespace {

constexpr std::array<std::string_view, 3> kStarterHeaders{"raytracer.h", "g2x.h", "g3x.h"};
// The C11 standard library's headers (ISO/IEC 9899:2011, 7.1.2).
constexpr std::array<std::string_view, 29> kStandardHeaders{
    "assert.h", "complex.h",  "ctype.h",  "errno.h",  "fenv.h",  "float.h",    "inttypes.h", "iso646.h",
    "limits.h", "locale.h",   "math.h",   "setjmp.h", "signal.h", "stdalign.h", "stdarg.h",   "stdatomic.h",
    "stdbool.h", "stddef.h",  "stdint.h", "stdio.h",  "stdlib.h", "stdnoreturn.h", "string.h", "tgmath.h",
    "threads.h", "time.h",    "uchar.h",  "wchar.h",  "wctype.h"};
// Directives that only define, test or stop (their bodies are scanned like the rest).
constexpr std::array<std::string_view, 12> kPlainDirectives{"define", "undef", "if",      "ifdef",   "ifndef",  "elif",
                                                            "else",   "endif", "error",   "warning", "elifdef", "elifndef"};
// Identifiers that open a door to other files, or let the compiler's input escape the scan.
constexpr std::array<std::string_view, 7> kForbiddenIdentifiers{
    "_Pragma", "__has_include", "__has_include_next", "__has_embed", "asm", "__asm", "__asm__"};

// The source after translation phases 1 and 2 (trigraphs replaced, line splices removed), each
// character with the line of the file it came from.
struct Logical {
  std::string text;
  std::vector<int> line;
};

char trigraph(char c) {
  switch (c) {
    case '=': return '#';
    case '(': return '[';
    case '/': return '\\';
    case ')': return ']';
    case '\'': return '^';
    case '<': return '{';
    case '!': return '|';
    case '>': return '}';
    case '-': return '~';
  }
  return 0;
}

Logical translate(std::string_view source) {
  // phase 1: trigraphs (gcc -std=c11 replaces them)
  std::string chars;
  std::vector<int> lines;
  chars.reserve(source.size());
  lines.reserve(source.size());
  int line = 1;
  for (std::size_t i = 0; i < source.size(); ++i) {
    char c = source[i];
    if (c == '?' && i + 2 < source.size() && source[i + 1] == '?' && trigraph(source[i + 2])) {
      c = trigraph(source[i + 2]);
      i += 2;
    }
    chars.push_back(c);
    lines.push_back(line);
    if (source[i] == '\n') ++line;
  }
  // phase 2: a backslash before the end of a line joins the lines (gcc allows spaces between)
  Logical out;
  out.text.reserve(chars.size());
  out.line.reserve(chars.size());
  for (std::size_t i = 0; i < chars.size(); ++i) {
    if (chars[i] == '\\') {
      std::size_t j = i + 1;
      while (j < chars.size() && (chars[j] == ' ' || chars[j] == '\t' || chars[j] == '\r')) ++j;
      if (j < chars.size() && chars[j] == '\n') {
        i = j;
        continue;
      }
    }
    out.text.push_back(chars[i]);
    out.line.push_back(lines[i]);
  }
  return out;
}

bool identifier_start(unsigned char c) { return std::isalpha(c) || c == '_' || c == '$' || c >= 0x80; }
bool identifier_char(unsigned char c) { return std::isalnum(c) || c == '_' || c == '$' || c >= 0x80; }

// Phase 3, as much of it as the checks need: tokens that matter (identifiers, directive
// starts, header names) are handed to the caller; comments and literals are skipped.
class Scanner {
 public:
  explicit Scanner(const Logical& l) : l_(l) {}

  SubmissionScan run(std::vector<Comment>* comments) {
    comments_ = comments;
    bool line_start = true;
    while (!done()) {  // past a refusal too: the functions it mentions are reported
      const char c = peek();
      if (c == '\n') {
        line_start = true;
        ++at_;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++at_;
        continue;
      }
      if (comment()) continue;
      const bool hash = c == '#' || (c == '%' && peek(1) == ':');
      if (hash && line_start) {
        at_ += c == '#' ? 1 : 2;
        directive();
        line_start = false;
        continue;
      }
      line_start = false;
      if (literal()) continue;
      if (identifier_start(static_cast<unsigned char>(c))) {
        identifier(read_identifier());
        continue;
      }
      if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1))))) {
        read_number();
        continue;
      }
      ++at_;
    }
    return std::move(scan_);
  }

 private:
  bool done() const { return at_ >= l_.text.size(); }
  char peek(std::size_t ahead = 0) const { return at_ + ahead < l_.text.size() ? l_.text[at_ + ahead] : '\0'; }
  int line() const { return l_.line.empty() ? 1 : l_.line[std::min(at_, l_.line.size() - 1)]; }

  void refuse(int line, std::string code, std::string detail) {
    if (!scan_.refusal) scan_.refusal = Refusal{line, std::move(code), std::move(detail)};
  }

  // A comment at the cursor: skipped (and recorded), true.
  bool comment() {
    if (peek() != '/' || (peek(1) != '*' && peek(1) != '/')) return false;
    const int start = line();
    const bool block = peek(1) == '*';
    at_ += 2;
    const std::size_t from = at_;
    std::size_t to;
    if (block) {
      const std::size_t end = l_.text.find("*/", at_);
      to = end == std::string::npos ? l_.text.size() : end;
      at_ = end == std::string::npos ? l_.text.size() : end + 2;
    } else {
      const std::size_t end = l_.text.find('\n', at_);
      to = end == std::string::npos ? l_.text.size() : end;
      at_ = to;
    }
    if (comments_) comments_->push_back({start, l_.text.substr(from, to - from)});
    return true;
  }

  // Spaces and comments, not the end of the line.
  void skip_blank() {
    while (!done()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++at_;
      } else if (c == '/' && peek(1) == '*') {
        comment();
      } else {
        return;
      }
    }
  }

  // A string or character literal (with its prefix) at the cursor: skipped, true.
  bool literal() {
    std::size_t quote = at_;
    if (peek() == 'u' && peek(1) == '8') quote += 2;
    else if (peek() == 'u' || peek() == 'U' || peek() == 'L') quote += 1;
    if (quote >= l_.text.size() || (l_.text[quote] != '"' && l_.text[quote] != '\'')) return false;
    const char close = l_.text[quote];
    at_ = quote + 1;
    while (!done() && peek() != close && peek() != '\n') at_ += peek() == '\\' ? 2 : 1;
    if (!done() && peek() == close) ++at_;
    return true;
  }

  std::string read_identifier() {
    const std::size_t from = at_;
    while (!done() && identifier_char(static_cast<unsigned char>(peek()))) ++at_;
    return l_.text.substr(from, at_ - from);
  }

  void read_number() {
    while (!done()) {
      const char c = peek();
      if ((c == '+' || c == '-') && at_ > 0) {
        const char e = l_.text[at_ - 1];
        if (e == 'e' || e == 'E' || e == 'p' || e == 'P') {
          ++at_;
          continue;
        }
        return;
      }
      if (!identifier_char(static_cast<unsigned char>(c)) && c != '.') return;
      ++at_;
    }
  }

  void identifier(const std::string& name) {
    if (std::find(kForbiddenIdentifiers.begin(), kForbiddenIdentifiers.end(), name) != kForbiddenIdentifiers.end()) {
      refuse(line(), "identifier", name);
      return;
    }
    if (auto fn = function_named(name))
      if (std::find(scan_.mentioned.begin(), scan_.mentioned.end(), *fn) == scan_.mentioned.end())
        scan_.mentioned.push_back(*fn);
  }

  void rest_of_line() {
    while (!done() && peek() != '\n') ++at_;
  }

  void directive() {
    const int where = line();
    skip_blank();
    if (done() || peek() == '\n') return;  // the null directive
    if (std::isdigit(static_cast<unsigned char>(peek()))) {
      refuse(where, "directive", "# <line number>");
      return;
    }
    if (!identifier_start(static_cast<unsigned char>(peek()))) {
      refuse(where, "directive", std::string(1, peek()));
      return;
    }
    const std::string name = read_identifier();
    if (name == "include") {
      include(where);
      return;
    }
    if (name == "pragma") {
      pragma(where);
      return;
    }
    if (std::find(kPlainDirectives.begin(), kPlainDirectives.end(), name) == kPlainDirectives.end())
      refuse(where, "directive", "#" + name);
    // the body (a macro's definition, a condition) is scanned as code
  }

  void include(int where) {
    skip_blank();
    const char open = peek();
    if (open != '"' && open != '<') {
      refuse(where, "include", "a computed #include (a macro, not a \"name\" or <name>)");
      return;
    }
    const char close = open == '"' ? '"' : '>';
    ++at_;
    const std::size_t from = at_;
    while (!done() && peek() != close && peek() != '\n') ++at_;
    const std::string header = l_.text.substr(from, at_ - from);
    if (done() || peek() != close) {
      refuse(where, "include", header);
      return;
    }
    ++at_;
    if (!allowed_header(header)) {
      refuse(where, "include", header);
      return;
    }
    scan_.includes.push_back(header);
    rest_of_line();
  }

  void pragma(int where) {
    std::vector<std::string> words;
    while (words.size() < 2) {
      skip_blank();
      if (done() || !identifier_start(static_cast<unsigned char>(peek()))) break;
      words.push_back(read_identifier());
    }
    const bool allowed = (!words.empty() && (words[0] == "once" || words[0] == "STDC")) ||
                         (words.size() == 2 && words[0] == "GCC" && words[1] == "diagnostic");
    if (!allowed) {
      std::string text = "#pragma";
      for (const auto& w : words) text += " " + w;
      refuse(where, "pragma", text);
      return;
    }
    rest_of_line();
  }

  const Logical& l_;
  std::size_t at_ = 0;
  SubmissionScan scan_;
  std::vector<Comment>* comments_ = nullptr;
};

}  // namespace

bool allowed_header(std::string_view name) {
  return std::find(kStarterHeaders.begin(), kStarterHeaders.end(), name) != kStarterHeaders.end() ||
         std::find(kStandardHeaders.begin(), kStandardHeaders.end(), name) != kStandardHeaders.end();
}

SubmissionScan scan_submission(std::string_view source) {
  if (source.size() > kMaxSubmissionBytes) {
    SubmissionScan scan;
    scan.refusal = Refusal{0, "size", fmt::format("{} bytes", source.size())};
    return scan;
  }
  if (const auto nul = source.find('\0'); nul != std::string_view::npos) {
    SubmissionScan scan;
    scan.refusal = Refusal{static_cast<int>(std::count(source.begin(), source.begin() + static_cast<long>(nul), '\n')) + 1,
                           "nul", "a NUL byte"};
    return scan;
  }
  const Logical logical = translate(source);
  return Scanner(logical).run(nullptr);
}

std::vector<Comment> comments_of(std::string_view source) {
  std::vector<Comment> comments;
  if (source.size() > kMaxSubmissionBytes) source = source.substr(0, kMaxSubmissionBytes);
  const Logical logical = translate(source);
  Scanner(logical).run(&comments);
  return comments;
}

}  // namespace epure::check
