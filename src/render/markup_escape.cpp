#include "render/markup_escape.h"

#include <array>

#include "render/utf8.h"

namespace epure::render {

namespace {

// The bytes that go out as they are: printable ASCII but for the four XML specials.
constexpr std::array<bool, 256> kPlainByte = [] {
  std::array<bool, 256> plain{};
  for (int c = 0x20; c < 0x7F; ++c) plain[static_cast<std::size_t>(c)] = true;
  for (char c : {'&', '<', '>', '"'}) plain[static_cast<unsigned char>(c)] = false;
  return plain;
}();

}  // namespace

void append_escaped(std::string& out, std::string_view s, bool attribute) {
  // Runs of characters that need nothing (all of a number or a path) are copied at once.
  const auto plain = [](char c) { return kPlainByte[static_cast<unsigned char>(c)]; };
  for (std::size_t i = 0; i < s.size();) {
    std::size_t j = i;
    while (j < s.size() && plain(s[j])) ++j;
    if (j > i) {
      out.append(s.substr(i, j - i));
      i = j;
      if (i == s.size()) break;
    }
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += attribute ? "&quot;" : "\""; break;
        case '\t': out += attribute ? "&#9;" : "\t"; break;
        case '\n': out += attribute ? "&#10;" : "\n"; break;
        case '\r': out += attribute ? "&#13;" : "\r"; break;
        default:
          if (c >= 0x20 && c != 0x7F) out += static_cast<char>(c);  // other controls: dropped
      }
      ++i;
      continue;
    }
    const utf8::Decoded d = utf8::decode(s, i);
    if (!d.valid) {
      utf8::append(out, utf8::kReplacement);
    } else if (d.cp != 0xFFFE && d.cp != 0xFFFF) {
      out.append(s.substr(i, d.length));
    }
    i += d.length;
  }
}

namespace {

// HTML's and XML's four special characters.
constexpr std::array<bool, 256> kMarkupSpecial = [] {
  std::array<bool, 256> special{};
  for (char c : {'&', '<', '>', '"'}) special[static_cast<unsigned char>(c)] = true;
  return special;
}();

}  // namespace

void append_markup_escaped(std::string& out, std::string_view s) {
  // the runs between specials appended whole
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (!kMarkupSpecial[static_cast<unsigned char>(c)]) continue;
    out.append(s, run, i - run);
    out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : "&quot;";
    run = i + 1;
  }
  out.append(s, run, std::string_view::npos);
}

std::string markup_escaped(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  append_markup_escaped(out, s);
  return out;
}

}  // namespace epure::render
