#include "grading/expression.h"

#include "support/portable.h"

#include <charconv>
#include <cstdint>
#include <cmath>
#include <numbers>

namespace epure::grading {

namespace {

// UTF-8 spellings the parser knows.
constexpr std::string_view kMinus = "\u2212", kTimes = "\u00d7", kDot = "\u00b7", kDivide = "\u00f7",
                           kRoot = "\u221a", kPi = "\u03c0", kSquared = "\u00b2", kAbout = "\u2248",
                           kNbsp = "\u00a0", kNarrowNbsp = "\u202f", kThinSpace = "\u2009";

// A plain decimal ("-2,17", "+3", "1.5e-3", "−0.25"): copied with '.' for ',' and '-' for '−',
// then from_chars. Most answers are these.
bool fast_decimal(std::string_view s, double& out) {
  char buf[64];
  std::size_t n = 0;
  std::size_t i = 0;
  if (s.size() > 60) return false;
  if (!s.empty() && s[0] == '+') i = 1;
  else if (s.substr(0, 3) == kMinus) buf[n++] = '-', i = 3;
  bool separator = false;
  for (; i < s.size(); ++i) {
    char c = s[i];
    if (c == ',' || c == '.') {
      if (separator) return false;
      separator = true;
      c = '.';
    } else if (!((c >= '0' && c <= '9') || c == '-' || c == 'e' || c == 'E')) {
      return false;
    }
    buf[n++] = c;
  }
  if (n == 0) return false;
  // up to 15 digits and no exponent: the integer and its power of ten are exact doubles, and one
  // division rounds correctly (Clinger's fast path), as from_chars would
  {
    std::size_t k = buf[0] == '-' ? 1 : 0;
    std::int64_t digits = 0;
    int count = 0, after = -1;
    bool plain = k < n;
    for (; k < n && plain; ++k) {
      if (buf[k] == '.') {
        plain = after < 0;
        after = 0;
      } else if (buf[k] >= '0' && buf[k] <= '9') {
        digits = digits * 10 + (buf[k] - '0');
        if (++count > 15) plain = false;
        if (after >= 0) ++after;
      } else {
        plain = false;
      }
    }
    if (plain && count > 0) {
      static constexpr double kPow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
      out = static_cast<double>(digits) / kPow10[after < 0 ? 0 : after];
      if (buf[0] == '-') out = -out;
      return true;
    }
  }
  const auto [end, ec] = portable::parse_double(buf, buf + n, out);
  return ec == std::errc() && end == buf + n && std::isfinite(out);
}

// The commonest cell of all, a short plain decimal ("2,17", "-0.5", "12"), read straight from
// the text: an optional sign, up to 15 digits with at most one decimal comma or point, nothing
// else. Same value as fast_decimal gives it (the integer and its power of ten are exact doubles,
// one correctly rounded division); anything else is left to fast_decimal and the parser.
bool plain_decimal(std::string_view s, double& out) {
  std::size_t i = 0;
  bool negative = false;
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
    negative = s[0] == '-';
    i = 1;
  } else if (s.substr(0, 3) == kMinus) {
    negative = true;
    i = 3;
  }
  std::int64_t digits = 0;
  int count = 0, after = -1;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c >= '0' && c <= '9') {
      if (++count > 15) return false;
      digits = digits * 10 + (c - '0');
      if (after >= 0) ++after;
    } else if ((c == ',' || c == '.') && after < 0) {
      after = 0;
    } else {
      return false;
    }
  }
  if (count == 0) return false;
  static constexpr double kPow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  out = static_cast<double>(digits) / kPow10[after < 0 ? 0 : after];
  if (negative) out = -out;
  return true;
}

class Parser {
 public:
  explicit Parser(std::string_view s) : s_(s) {}

  ParsedNumber run() {
    skip();
    if (take(kAbout) || take("~") || take("=")) skip();
    const double v = sum();
    skip();
    if (!failed_ && pos_ != s_.size()) fail("number");
    if (!failed_ && !std::isfinite(v)) fail("number");
    if (failed_) return {false, 0, why_};
    return {true, v, {}};
  }

 private:
  void fail(std::string_view why) {
    if (!failed_) why_ = why;
    failed_ = true;
  }
  void skip() {
    while (pos_ < s_.size()) {
      if (s_[pos_] == ' ' || s_[pos_] == '\t') ++pos_;
      else if (at(kNbsp) || at(kNarrowNbsp) || at(kThinSpace)) pos_ += 2 + (s_[pos_] == '\xe2');
      else break;
    }
  }
  bool at(std::string_view t) const { return s_.substr(pos_, t.size()) == t; }
  bool take(std::string_view t) {
    if (!at(t)) return false;
    pos_ += t.size();
    return true;
  }
  // A word, any case ("sqrt", "SQRT", "Racine").
  bool take_word(std::string_view w) {
    if (s_.size() - pos_ < w.size()) return false;
    for (std::size_t i = 0; i < w.size(); ++i) {
      char c = s_[pos_ + i];
      if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
      if (c != w[i]) return false;
    }
    pos_ += w.size();
    return true;
  }

  // Every loop below stops at the first failure, and every turn of a loop consumes input
  // (an operator, or an atom that advanced), so the parser is linear in the cell's length.
  double sum() {
    double v = product();
    for (;;) {
      if (failed_) return 0;
      skip();
      if (take("+")) v += product();
      else if (take("-") || take(kMinus)) v -= product();
      else return v;
    }
  }

  double product() {
    double v = unary();
    for (;;) {
      if (failed_) return 0;
      skip();
      if (take("*") || take(kTimes) || take(kDot)) {
        v *= unary();
      } else if (take("/") || take(kDivide)) {
        const double d = unary();
        if (d == 0) {  // guards the division
          fail("division_by_zero");
          return 0;
        }
        v /= d;
      } else if (starts_atom()) {
        // implicit product: 2√3, 2sqrt(3), 3(1+√2). An atom that fails leaves the position
        // where it was: that ends the loop, never starts another turn of it. (Before, "√-√"
        // failed on "-", then "√" started an atom that returned at once, forever.)
        const std::size_t before = pos_;
        v *= power();
        if (!failed_ && pos_ == before) fail("number");
      } else {
        return v;
      }
    }
  }

  bool starts_atom() const {
    if (pos_ >= s_.size()) return false;
    const char c = s_[pos_];
    if (c == '(' || at(kRoot) || at(kPi)) return true;
    if (c == 's' || c == 'S' || c == 'r' || c == 'R' || c == 'p' || c == 'P') return true;
    return false;
  }

  // Nesting is bounded: "((((…", "----…" or "√√√…" a million deep is not a number a student
  // typed, and must not overflow the stack.
  struct Depth {
    explicit Depth(Parser& p) : p_(p) {
      if (++p_.depth_ > kMaxDepth) p_.fail("number");
    }
    ~Depth() { --p_.depth_; }
    Parser& p_;
  };
  static constexpr int kMaxDepth = 64;

  double unary() {
    Depth guard(*this);
    if (failed_) return 0;
    skip();
    if (take("+")) return unary();
    if (take("-") || take(kMinus)) return -unary();
    return power();
  }

  double power() {
    const double base = atom();
    skip();
    if (take(kSquared)) return base * base;
    if (take("^")) return std::pow(base, unary());
    return base;
  }

  double atom() {
    Depth guard(*this);
    skip();
    if (failed_ || pos_ >= s_.size()) {
      fail("number");
      return 0;
    }
    if (take("(")) {
      const double v = sum();
      skip();
      if (!take(")")) fail("number");
      return v;
    }
    if (take(kRoot) || take_word("sqrt") || take_word("racine")) {
      skip();
      const double v = s_.substr(pos_, 1) == "(" ? atom() : power();
      if (v < 0) {
        fail("negative_root");
        return 0;
      }
      return std::sqrt(v);
    }
    if (take(kPi) || take_word("pi")) return std::numbers::pi;
    return literal();
  }

  // Digits with one decimal point or comma.
  double literal() {
    const std::size_t start = pos_;
    char buf[64];
    std::size_t n = 0;
    bool separator = false, digits = false;
    while (pos_ < s_.size() && n < sizeof buf) {
      const char c = s_[pos_];
      if (c >= '0' && c <= '9') {
        digits = true;
      } else if ((c == '.' || c == ',') && !separator && pos_ + 1 < s_.size() && s_[pos_ + 1] >= '0' &&
                 s_[pos_ + 1] <= '9') {
        separator = true;
      } else {
        break;
      }
      buf[n++] = c == ',' ? '.' : c;
      ++pos_;
    }
    if (!digits) {
      pos_ = start;
      fail("number");
      return 0;
    }
    double v = 0;
    portable::parse_double(buf, buf + n, v);
    return v;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  bool failed_ = false;
  int depth_ = 0;
  std::string_view why_;
};

bool same_letters(std::string_view text, std::string_view lower) {
  if (text.size() != lower.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != lower[i]) return false;
  }
  return true;
}

// `s` without blanks (ASCII and the no-break ones) at its end.
std::string_view without_trailing_blanks(std::string_view s) {
  for (;;) {
    if (!s.empty() && (s.back() == ' ' || s.back() == '\t')) {
      s.remove_suffix(1);
      continue;
    }
    bool cut = false;
    for (const std::string_view space : {kNbsp, kNarrowNbsp, kThinSpace})
      if (s.size() > space.size() && s.substr(s.size() - space.size()) == space) {
        s.remove_suffix(space.size());
        cut = true;
      }
    if (!cut) return s;
  }
}

// A unit typed after the number, and the spaces before it, cut off: the sheet asks for the
// number in the figure's units (a length, a squared length such as d²) or in degrees, and a
// student who writes the unit means the number ("50,91°", "−71,57 °", "4,75 cm", "1,04 u",
// "1,8 u²", "3 unités"). Radians are not a unit dropped: "0.89 rad" stays unreadable (so to be
// checked), never read as 0.89°. Returns the text unchanged when it ends in no such unit.
std::string_view without_unit(std::string_view s) {
  // the tail after the last digit, closing parenthesis or root's argument: a unit is letters
  // (and '.', '²', '^2') only, after optional spaces
  static constexpr std::string_view kAngles[] = {"\u00b0", "\u00ba", "degrees", "degree", "degr\u00e9s", "degr\u00e9",
                                                 "degres", "degre", "degs", "deg"};
  static constexpr std::string_view kLengths[] = {"cm", "mm", "dm", "m", "u", "u.", "ua", "u.a.", "u.a", "ul", "u.l.",
                                                  "unit", "units", "unit\u00e9", "unit\u00e9s", "unite", "unites",
                                                  "unit\u00e9s de longueur", "units of length"};
  static constexpr std::string_view kSquares[] = {"", "\u00b2", "^2", "2"};
  for (const std::string_view unit : kAngles) {
    if (s.size() <= unit.size() || !same_letters(s.substr(s.size() - unit.size()), unit)) continue;
    return without_trailing_blanks(s.substr(0, s.size() - unit.size()));
  }
  for (const std::string_view square : kSquares) {
    if (s.size() <= square.size() || s.substr(s.size() - square.size()) != square) continue;
    const std::string_view body = s.substr(0, s.size() - square.size());
    for (const std::string_view unit : kLengths) {
      if (body.size() <= unit.size() || !same_letters(body.substr(body.size() - unit.size()), unit)) continue;
      const std::string_view number = body.substr(0, body.size() - unit.size());
      // a whole word: "4,75 cm" or "4,75cm", never the end of a word ("sqrt(2)m" is no unit of "m")
      const char before = number.back();
      if ((before >= 'a' && before <= 'z') || (before >= 'A' && before <= 'Z')) continue;
      // "2" after a letter as a square only right after the unit ("u2"), never after a blank
      if (square == "2" && unit.back() == '.') continue;
      return without_trailing_blanks(number);
    }
  }
  return s;
}

// The name a student copied before the value ("t = 4,75", "d² = 1,8", "I.x = 2,14",
// "t_proj=4,02"): letters, digits, '_', '.', '²' and blanks before a single '=', with a letter
// first. Returns what follows it, or nothing.
std::string_view after_name(std::string_view s) {
  const auto eq = s.find('=');
  if (eq == std::string_view::npos || eq == 0 || s.find('=', eq + 1) != std::string_view::npos) return {};
  const std::string_view name = without_trailing_blanks(s.substr(0, eq));
  if (name.empty() || !((name[0] >= 'a' && name[0] <= 'z') || (name[0] >= 'A' && name[0] <= 'Z'))) return {};
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == ' ')
      continue;
    if (name.substr(i, kSquared.size()) == kSquared) {
      i += kSquared.size() - 1;
      continue;
    }
    return {};
  }
  if (name.size() > 12) return {};
  std::string_view value = s.substr(eq + 1);
  while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
  return value;
}

ParsedNumber parse_plain(std::string_view text) {
  double v = 0;
  if (plain_decimal(text, v) || fast_decimal(text, v)) return {true, v, {}};
  return Parser(text).run();
}

// The number of a cell once a unit after it, a name before it ("t = ") and a full stop that ends
// it ("4,75.") are set aside, each at most once.
ParsedNumber parse_with_extras(std::string_view text) {
  std::string_view body = text;
  if (const std::string_view value = after_name(body); !value.empty()) body = value;
  const std::string_view number = without_unit(body);
  if (number.size() != body.size()) {
    // the unit alone ("°", "cm") is no number; one unit only ("5°°", "5 cm cm" are not read)
    if (number.empty() || without_unit(number).size() != number.size()) return {false, 0, "number"};
    body = number;
  }
  if (body.size() >= 2 && body.back() == '.' && body[body.size() - 2] >= '0' && body[body.size() - 2] <= '9')
    body.remove_suffix(1);
  if (body.size() == text.size()) return Parser(text).run();
  return parse_plain(body);
}

}  // namespace

ParsedNumber parse_number(std::string_view text) {
  // No number a student types is longer than this; a longer cell is not parsed at all, so the
  // work per cell is bounded whatever the file holds.
  constexpr std::size_t kMaxNumberLength = 256;
  if (text.size() > kMaxNumberLength) return {false, 0, "number"};
  // blanks around are no part of the number: " 1.5e-3 " reads as "1.5e-3" does (found by
  // tests/fuzz: the fast paths read exponents, the parser does not, and blanks sent the text
  // to the parser)
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  double v = 0;
  if (plain_decimal(text, v) || fast_decimal(text, v)) return {true, v, {}};
  const ParsedNumber whole = Parser(text).run();
  if (whole.ok || whole.why != "number") return whole;
  return parse_with_extras(text);
}

}  // namespace epure::grading
