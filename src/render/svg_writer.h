#pragma once
// A tiny XML writer for SVG, after matplotlib's XMLWriter: start/end/element, a tag stack that
// checks balance, every string escaped (text and attribute values), attributes written in the
// order given, numbers in one short fixed format. The same calls give the same bytes: no
// pointers, no time, ids from a counter.
//
// Elements are indented one space per level for diffing; inside an element opened with
// start_inline (a <text> and its <tspan>s) nothing is indented, since whitespace there would be
// drawn.
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "render/markup_escape.h"

namespace epure::render {

// `v` with at most `decimals` decimals, trailing zeros and a trailing point dropped, and no
// negative zero: 1.50 → "1.5", 2.0 → "2", -0.001 → "0". Throws std::domain_error on a NaN or an
// infinity (an SVG with "nan" in it is broken; better to fail loudly where it starts).
std::string format_number(double v, int decimals = 2);
void append_number(std::string& out, double v, int decimals = 2);
// The same number in two steps, for writers that compute with the written values (path data's
// relative steps): `v` as an integer count of its last written decimal (false, and `n` untouched,
// when `v` is too large for the fast form: write it with append_number), and such a count's text.
bool round_scaled(double v, int decimals, long long& n);
void append_scaled(std::string& out, long long n, int decimals);
// append_scaled's text written to end just before `end`, for a writer that puts several pieces
// in one append; returns where it starts. It takes at most kScaledRoom bytes (a count below
// 10^18: a sign, 19 digits and a point).
inline constexpr std::size_t kScaledRoom = 24;
char* scaled_before(char* end, long long n, int decimals);

// (append_escaped, the escaping of its text and attribute values: render/markup_escape.h)

class SvgWriter {
 public:
  // One attribute; a number is formatted with format_number.
  struct Attr {
    Attr(std::string_view name, std::string_view value) : name(name), value(value) {}
    Attr(std::string_view name, const char* value) : name(name), value(value) {}
    Attr(std::string_view name, const std::string& value) : name(name), value(value) {}
    Attr(std::string_view name, double value) : name(name), value(format_number(value)) {}
    Attr(std::string_view name, int value) : name(name), value(std::to_string(value)) {}
    std::string_view name;
    std::string value;
  };
  using Attrs = std::initializer_list<Attr>;

  // A sheet or key document is 40–120 KiB: start with room for most of one, not from empty
  // (fewer regrowths and copies; measured −0.3 % instructions, a little less time).
  SvgWriter() { out_.reserve(64 * 1024); }

  // <?xml version="1.0" encoding="UTF-8"?>; only as the very first output.
  void declaration();

  void start(std::string_view tag, Attrs attrs = {});
  void start(std::string_view tag, const std::vector<Attr>& attrs);
  // Like start, but the element's content is written without any added whitespace.
  void start_inline(std::string_view tag, Attrs attrs = {});
  void start_inline(std::string_view tag, const std::vector<Attr>& attrs);
  // Closes the innermost open element, which must be `tag` (std::logic_error otherwise).
  void end(std::string_view tag);
  // An empty element, <tag a="…"/>.
  void element(std::string_view tag, Attrs attrs = {});
  void element(std::string_view tag, const std::vector<Attr>& attrs);
  // <tag a="…">text</tag>, the text escaped.
  void element(std::string_view tag, Attrs attrs, std::string_view text);
  // Character data inside the current element, escaped.
  void text(std::string_view s);

  // The same, streamed, for hot paths (no attribute list is built): open(tag), attribute(…)
  // any number of times, then close_empty() for <tag …/> or close_start() to go on with content
  // (close_start_inline for content without indentation).
  void open(std::string_view tag);
  void attribute(std::string_view name, std::string_view value);
  void attribute(std::string_view name, double value);
  // A value with nothing to escape, by construction (path data: numbers, spaces and command
  // letters), copied as it is: a figure's paths are most of its bytes.
  void plain_attribute(std::string_view name, std::string_view value);
  void close_empty();
  void close_start();
  void close_start_inline();

  // A fresh id "prefix1", "prefix2", … counted per prefix within this document.
  std::string next_id(std::string_view prefix);

  std::size_t depth() const { return stack_.size(); }
  const std::string& str() const { return out_; }
  // The document; throws std::logic_error when an element is still open.
  std::string finish();

 private:
  struct Open {
    std::string tag;
    bool inline_content;
    bool has_children = false;
  };
  void open_tag(std::string_view tag, const Attr* begin, const Attr* end, bool self_close);
  void before_child();
  void attribute_name(std::string_view name);
  void new_line();
  bool in_inline() const { return !stack_.empty() && stack_.back().inline_content; }

  std::string out_;
  std::vector<Open> stack_;
  std::string opening_;  // the tag open() started, until it is closed; empty otherwise
  std::vector<std::pair<std::string, int>> id_counters_;
};

}  // namespace epure::render
