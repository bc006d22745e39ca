#include "render/svg_writer.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>


namespace epure::render {

namespace {

// Below this magnitude a number is rounded as an integer count of its last decimal; above it
// (never in a drawing) fmt's exact conversion takes over.
constexpr double kFastLimit = 1e12;
// Bytes of a tag written in one append (its line break, indent and name): more goes piece by piece.
constexpr std::size_t kOneAppend = 64;
constexpr long long kPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000};
// "00" to "99", for writing numbers two digits at a time.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Appends `s` without the trailing zeros of its decimals, and without a bare point.
void append_trimmed(std::string& out, std::string_view s) {
  if (s.find('.') != std::string_view::npos) {
    while (s.back() == '0') s.remove_suffix(1);
    if (s.back() == '.') s.remove_suffix(1);
  }
  if (s == "-0") s = "0";  // a value that rounds to zero from below
  out += s;
}

}  // namespace

bool round_scaled(double v, int decimals, long long& n) {
  if (!std::isfinite(v)) throw std::domain_error("SVG number is not finite");
  if (decimals < 0 || decimals >= static_cast<int>(std::size(kPow10)) || !(std::abs(v) < kFastLimit)) return false;
  // Round to an integer count of the last decimal, half away from zero as llround
  // (x − trunc(x) is exact).
  const double x = v * static_cast<double>(kPow10[decimals]);
  n = static_cast<long long>(x);
  const double rest = x - static_cast<double>(n);
  if (rest >= 0.5) ++n;
  if (rest <= -0.5) --n;
  return true;
}

char* scaled_before(char* end, long long n, int decimals) {
  char* p = end;
  if (n == 0) {
    *--p = '0';
    return p;
  }
  // Numbers are most of an SVG's bytes: the digits are written backwards into a buffer instead
  // of going through a general float conversion, the integer part two digits at a time (a
  // page's coordinates have three).
  unsigned long long m = n < 0 ? 0ULL - static_cast<unsigned long long>(n) : static_cast<unsigned long long>(n);
  int d = 0;
  if (decimals == 2) {  // the usual case, without a loop: "", ".d" or ".dd"
    const unsigned long long hundredths = m % 100;
    m /= 100;
    d = 2;
    if (hundredths % 10 != 0) {
      p -= 3;
      p[0] = '.';
      std::memcpy(p + 1, kDigitPairs + 2 * hundredths, 2);
    } else if (hundredths != 0) {
      p -= 2;
      p[0] = '.';
      p[1] = static_cast<char>('0' + hundredths / 10);
    }
  }
  for (; d < decimals && m % 10 == 0; ++d) m /= 10;  // trailing zeros of the decimals: none
  if (d < decimals) {
    for (; d < decimals; ++d, m /= 10) *--p = static_cast<char>('0' + m % 10);
    *--p = '.';
  }
  for (; m >= 100; m /= 100) {
    p -= 2;
    std::memcpy(p, kDigitPairs + 2 * (m % 100), 2);
  }
  if (m >= 10) {
    p -= 2;
    std::memcpy(p, kDigitPairs + 2 * m, 2);
  } else {
    *--p = static_cast<char>('0' + m);
  }
  if (n < 0) *--p = '-';
  return p;
}

void append_scaled(std::string& out, long long n, int decimals) {
  char buf[kScaledRoom];
  char* const end = std::end(buf);
  const char* p = scaled_before(end, n, decimals);
  out.append(p, static_cast<std::size_t>(end - p));
}

void append_number(std::string& out, double v, int decimals) {
  long long n = 0;
  if (round_scaled(v, decimals, n)) {
    append_scaled(out, n, decimals);
    return;
  }
  char buf[400];
  const auto r = fmt::format_to_n(buf, sizeof buf, "{:.{}f}", v, decimals);
  append_trimmed(out, std::string_view(buf, r.size < sizeof buf ? r.size : sizeof buf));
}

std::string format_number(double v, int decimals) {
  std::string s;
  append_number(s, v, decimals);
  return s;
}


void SvgWriter::declaration() {
  if (!out_.empty()) throw std::logic_error("the XML declaration must come first");
  out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>";
}

void SvgWriter::new_line() {
  // A line break and the indent of the depth (a copy of spaces: cheaper than a fill, per tag)
  constexpr std::string_view kSpaces = "                                ";
  out_ += '\n';
  for (std::size_t depth = stack_.size(); depth > 0;) {
    const std::size_t n = std::min(depth, kSpaces.size());
    out_.append(kSpaces.data(), n);
    depth -= n;
  }
}

void SvgWriter::before_child() {
  if (!opening_.empty())
    throw std::logic_error(fmt::format("SVG writer: <{}> is not closed", opening_));
  if (stack_.empty()) {
    if (!out_.empty()) out_ += '\n';
    return;
  }
  stack_.back().has_children = true;
  if (in_inline()) return;
  new_line();
}

void SvgWriter::open_tag(std::string_view tag, const Attr* begin, const Attr* end,
                         bool self_close) {
  before_child();
  out_ += '<';
  out_ += tag;
  for (const Attr* a = begin; a != end; ++a) {
    out_ += ' ';
    out_ += a->name;
    out_ += "=\"";
    append_escaped(out_, a->value, true);
    out_ += '"';
  }
  out_ += self_close ? "/>" : ">";
}

void SvgWriter::start(std::string_view tag, Attrs attrs) {
  open_tag(tag, std::data(attrs), std::data(attrs) + attrs.size(), false);
  stack_.push_back({std::string(tag), in_inline()});
}

void SvgWriter::start(std::string_view tag, const std::vector<Attr>& attrs) {
  open_tag(tag, attrs.data(), attrs.data() + attrs.size(), false);
  stack_.push_back({std::string(tag), in_inline()});
}

void SvgWriter::start_inline(std::string_view tag, Attrs attrs) {
  open_tag(tag, std::data(attrs), std::data(attrs) + attrs.size(), false);
  stack_.push_back({std::string(tag), true});
}

void SvgWriter::start_inline(std::string_view tag, const std::vector<Attr>& attrs) {
  open_tag(tag, attrs.data(), attrs.data() + attrs.size(), false);
  stack_.push_back({std::string(tag), true});
}

void SvgWriter::end(std::string_view tag) {
  if (!opening_.empty() || stack_.empty() || stack_.back().tag != tag) {
    throw std::logic_error(fmt::format("SVG writer: </{}> does not close <{}>", tag,
                                       stack_.empty() ? "" : stack_.back().tag));
  }
  const bool own_line = stack_.back().has_children && !stack_.back().inline_content;
  stack_.pop_back();
  // The line break and indent, if any, and `</tag>` in one append for a usual depth and tag
  // (every element of a page ends here); new_line's bytes otherwise.
  const std::size_t indent = own_line ? 1 + stack_.size() : 0;
  char buf[kOneAppend];
  if (indent + tag.size() + 3 <= sizeof buf) {
    if (own_line) {
      buf[0] = '\n';
      std::memset(buf + 1, ' ', indent - 1);
    }
    buf[indent] = '<';
    buf[indent + 1] = '/';
    std::memcpy(buf + indent + 2, tag.data(), tag.size());
    buf[indent + 2 + tag.size()] = '>';
    out_.append(buf, indent + tag.size() + 3);
    return;
  }
  if (own_line) new_line();
  out_ += "</";
  out_ += tag;
  out_ += '>';
}

void SvgWriter::element(std::string_view tag, Attrs attrs) {
  open_tag(tag, std::data(attrs), std::data(attrs) + attrs.size(), true);
}

void SvgWriter::element(std::string_view tag, const std::vector<Attr>& attrs) {
  open_tag(tag, attrs.data(), attrs.data() + attrs.size(), true);
}

void SvgWriter::element(std::string_view tag, Attrs attrs, std::string_view text) {
  open_tag(tag, std::data(attrs), std::data(attrs) + attrs.size(), false);
  append_escaped(out_, text, false);
  out_ += "</";
  out_ += tag;
  out_ += '>';
}

void SvgWriter::text(std::string_view s) {
  if (stack_.empty() || !opening_.empty())
    throw std::logic_error("SVG writer: text outside any element");
  append_escaped(out_, s, false);
}

void SvgWriter::open(std::string_view tag) {
  if (!opening_.empty())
    throw std::logic_error(fmt::format("SVG writer: <{}> is not closed", opening_));
  // before_child's line break and indent (inside an element whose content is not inline) and
  // `<tag` in one append for a usual depth and tag; before_child's own way otherwise.
  if (!stack_.empty() && !stack_.back().inline_content && stack_.size() + tag.size() + 2 <= kOneAppend) {
    stack_.back().has_children = true;
    char buf[kOneAppend];
    const std::size_t indent = 1 + stack_.size();
    buf[0] = '\n';
    std::memset(buf + 1, ' ', indent - 1);
    buf[indent] = '<';
    std::memcpy(buf + indent + 1, tag.data(), tag.size());
    out_.append(buf, indent + 1 + tag.size());
  } else {
    before_child();
    out_ += '<';
    out_ += tag;
  }
  opening_ = tag;
}

// ` name="`, in one append for a usual name: a page writes a few hundred thousand attributes.
void SvgWriter::attribute_name(std::string_view name) {
  if (opening_.empty()) throw std::logic_error("SVG writer: an attribute outside a start tag");
  char buf[32];
  if (name.size() + 3 > sizeof buf) {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    return;
  }
  buf[0] = ' ';
  std::memcpy(buf + 1, name.data(), name.size());
  buf[name.size() + 1] = '=';
  buf[name.size() + 2] = '"';
  out_.append(buf, name.size() + 3);
}

void SvgWriter::attribute(std::string_view name, std::string_view value) {
  attribute_name(name);
  append_escaped(out_, value, true);
  out_ += '"';
}

void SvgWriter::plain_attribute(std::string_view name, std::string_view value) {
  assert(std::all_of(value.begin(), value.end(), [](char c) {
    return c >= 0x20 && c < 0x7F && c != '&' && c != '<' && c != '>' && c != '"';
  }));
  attribute_name(name);
  out_ += value;
  out_ += '"';
}

void SvgWriter::attribute(std::string_view name, double value) {
  // ` name="value"` in one append for a usual name and number (a page writes hundreds of
  // them), else piece by piece; the same bytes either way.
  constexpr std::size_t kNameRoom = 32;
  long long n = 0;
  if (opening_.empty()) throw std::logic_error("SVG writer: an attribute outside a start tag");
  if (name.size() <= kNameRoom && round_scaled(value, 2, n)) {
    char buf[kNameRoom + 4 + kScaledRoom];
    char* const end = std::end(buf);
    end[-1] = '"';
    char* p = scaled_before(end - 1, n, 2);
    p -= 2;
    p[0] = '=';
    p[1] = '"';
    p -= name.size();
    std::memcpy(p, name.data(), name.size());
    *--p = ' ';
    out_.append(p, static_cast<std::size_t>(end - p));
    return;
  }
  attribute_name(name);
  append_number(out_, value);
  out_ += '"';
}

void SvgWriter::close_empty() {
  if (opening_.empty()) throw std::logic_error("SVG writer: no start tag to close");
  out_ += "/>";
  opening_.clear();
}

void SvgWriter::close_start() {
  if (opening_.empty()) throw std::logic_error("SVG writer: no start tag to close");
  out_ += '>';
  const bool parent_inline = in_inline();
  stack_.push_back({std::move(opening_), parent_inline});
  opening_.clear();
}

void SvgWriter::close_start_inline() {
  if (opening_.empty()) throw std::logic_error("SVG writer: no start tag to close");
  out_ += '>';
  stack_.push_back({std::move(opening_), true});
  opening_.clear();
}

std::string SvgWriter::next_id(std::string_view prefix) {
  for (auto& [p, n] : id_counters_) {
    if (p == prefix) return fmt::format("{}{}", prefix, ++n);
  }
  id_counters_.emplace_back(std::string(prefix), 1);
  return fmt::format("{}1", prefix);
}

std::string SvgWriter::finish() {
  if (!opening_.empty())
    throw std::logic_error(fmt::format("SVG writer: <{}> is not closed", opening_));
  if (!stack_.empty()) {
    throw std::logic_error(fmt::format("SVG writer: <{}> is still open", stack_.back().tag));
  }
  out_ += '\n';
  return std::move(out_);
}

}  // namespace epure::render
