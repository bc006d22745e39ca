#pragma once
// A small JSON text writer for the outputs other tools read (`epure solve`, key.json): keys in
// the order they are written, numbers in their shortest round-trip form (fmt's Dragonbox), −0
// folded into 0, strings escaped. Writing text directly keeps `epure solve` fast and its bytes
// stable.
#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <string_view>

namespace epure {

class JsonWriter {
 public:
  explicit JsonWriter(fmt::memory_buffer& buffer) : buf_(buffer) {}

  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }

  JsonWriter& key(std::string_view k) {
    separate();
    string_literal(k);
    buf_.push_back(':');
    after_key_ = true;
    return *this;
  }
  JsonWriter& number(double x) {
    separate();
    // Finite by contract: callers check non-finite values before they reach the text.
    if (x == 0) x = 0;  // −0 and +0 are the same answer: print one spelling
    // Compiled "{}": the same shortest text, without parsing the format string per number.
    fmt::format_to(fmt::appender(buf_), FMT_COMPILE("{}"), x);
    return *this;
  }
  JsonWriter& integer(long long x) {
    separate();
    fmt::format_to(std::back_inserter(buf_), "{}", x);
    return *this;
  }
  JsonWriter& boolean(bool b) {
    separate();
    append(b ? "true" : "false");
    return *this;
  }
  JsonWriter& string(std::string_view s) {
    separate();
    string_literal(s);
    return *this;
  }
  // Already-valid JSON text (an object written by another JsonWriter), inserted as a value.
  JsonWriter& raw(std::string_view json_text) {
    separate();
    append(json_text);
    return *this;
  }

  template <class T>
  JsonWriter& field(std::string_view k, const T& value) {
    key(k);
    write(value);
    return *this;
  }

 private:
  void write(double x) { number(x); }
  void write(bool b) { boolean(b); }
  void write(std::string_view s) { string(s); }
  void write(const char* s) { string(s); }

  JsonWriter& open(char c) {
    separate();
    buf_.push_back(c);
    first_ = true;
    return *this;
  }
  JsonWriter& close(char c) {
    buf_.push_back(c);
    first_ = false;
    return *this;
  }
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_) buf_.push_back(',');
    first_ = false;
  }
  void append(std::string_view s) { buf_.append(s.data(), s.data() + s.size()); }
  void string_literal(std::string_view s);

  fmt::memory_buffer& buf_;
  bool first_ = true;
  bool after_key_ = false;
};

// The length of the UTF-8 character at the start of `s` (RFC 3629: no overlong form, no
// surrogate, nothing past U+10FFFF), or 0 when it is not one.
inline std::size_t utf8_char_length(std::string_view s) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const auto tail = [&](std::size_t k) { return k < s.size() && (at(k) & 0xc0) == 0x80; };
  const unsigned c = at(0);
  if (c < 0x80) return 1;
  if (c >= 0xc2 && c <= 0xdf) return tail(1) ? 2 : 0;
  if (c >= 0xe0 && c <= 0xef) {
    if (!tail(1) || !tail(2)) return 0;
    if ((c == 0xe0 && at(1) < 0xa0) || (c == 0xed && at(1) > 0x9f)) return 0;
    return 3;
  }
  if (c >= 0xf0 && c <= 0xf4) {
    if (!tail(1) || !tail(2) || !tail(3)) return 0;
    if ((c == 0xf0 && at(1) < 0x90) || (c == 0xf4 && at(1) > 0x8f)) return 0;
    return 4;
  }
  return 0;
}

inline void JsonWriter::string_literal(std::string_view s) {
  buf_.push_back('"');
  // Keys and names need no escape: copy them whole.
  const bool plain = std::all_of(s.begin(), s.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c >= 0x20 && c < 0x80 && ch != '"' && ch != '\\';
  });
  if (plain) {
    append(s);
    buf_.push_back('"');
    return;
  }
  for (std::size_t i = 0; i < s.size();) {
    const char ch = s[i];
    auto c = static_cast<unsigned char>(ch);
    if (c >= 0x80) {
      // JSON text is UTF-8: a byte that starts no character (an error message quoting a bad
      // input, a name in Windows-1252) is written as U+FFFD, never as itself
      const std::size_t n = utf8_char_length(s.substr(i));
      if (n == 0) {
        append("\\ufffd");
        ++i;
      } else {
        append(s.substr(i, n));
        i += n;
      }
      continue;
    }
    switch (ch) {
      case '"': append("\\\""); break;
      case '\\': append("\\\\"); break;
      case '\n': append("\\n"); break;
      case '\r': append("\\r"); break;
      case '\t': append("\\t"); break;
      default:
        if (c < 0x20) fmt::format_to(std::back_inserter(buf_), "\\u{:04x}", c);
        else buf_.push_back(ch);
    }
    ++i;
  }
  buf_.push_back('"');
}

}  // namespace epure
