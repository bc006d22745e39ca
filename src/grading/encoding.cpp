#include "grading/encoding.h"

#include <cstdint>
#include <cstring>

namespace epure::grading {

bool valid_utf8(std::string_view s) {
  // nearly every byte is ASCII: eight at a time, and back to eight at a time after each
  // multi-byte character (a name's "é" must not send the rest of a record byte by byte)
  std::size_t i = 0;
  while (i < s.size()) {
    if (i + 8 <= s.size()) {
      std::uint64_t word;
      std::memcpy(&word, s.data() + i, 8);
      if (!(word & 0x8080808080808080ull)) {
        i += 8;
        continue;
      }
    }
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      ++i;
      continue;
    }
    int extra = 0;
    if (c >= 0xc2 && c <= 0xdf) extra = 1;
    else if (c >= 0xe0 && c <= 0xef) extra = 2;
    else if (c >= 0xf0 && c <= 0xf4) extra = 3;
    else return false;
    if (i + extra >= s.size()) return false;
    for (int k = 1; k <= extra; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
    // RFC 3629: no overlong form (E0 80–9F, F0 80–8F), no surrogate (ED A0–BF), nothing past
    // U+10FFFF (F4 90–BF); tests/fuzz found these taken as UTF-8 and written out as they came
    const auto second = static_cast<unsigned char>(s[i + 1]);
    if ((c == 0xe0 && second < 0xa0) || (c == 0xed && second > 0x9f) || (c == 0xf0 && second < 0x90) ||
        (c == 0xf4 && second > 0x8f))
      return false;
    i += 1 + extra;
  }
  return true;
}

bool all_valid_utf8(std::span<const std::string_view> cells) {
  if (cells.empty()) return true;
  // Cells split from one CSV record lie in order in one buffer: one pass over the whole stretch
  // instead of a call per cell. A valid stretch has valid cells when no cell starts or ends
  // inside a character (a substring of valid UTF-8 cut at character starts is valid UTF-8).
  const auto at = [](const char* p) { return reinterpret_cast<std::uintptr_t>(p); };
  const char* first = cells.front().data();
  const char* last = cells.back().data() + cells.back().size();
  bool in_order = first != nullptr && at(first) <= at(last);
  for (std::size_t c = 1; in_order && c < cells.size(); ++c)
    in_order = cells[c].data() != nullptr &&
               at(cells[c - 1].data() + cells[c - 1].size()) <= at(cells[c].data()) &&
               at(cells[c].data()) <= at(last);
  if (in_order) {
    const std::string_view stretch(first, static_cast<std::size_t>(last - first));
    if (valid_utf8(stretch)) {
      const auto inside = [](char b) { return (static_cast<unsigned char>(b) & 0xc0) == 0x80; };
      bool cut = false;
      for (const auto c : cells) {
        if (c.empty()) continue;
        cut = cut || inside(c.front());
        if (c.data() + c.size() < last) cut = cut || inside(c.data()[c.size()]);
      }
      if (!cut) return true;
    }
  }
  // cells apart (JSON), or some text not UTF-8: cell by cell
  for (const auto c : cells)
    if (!valid_utf8(c)) return false;
  return true;
}

std::string cp1252_to_utf8(std::string_view s) {
  // 0x80–0x9F, where Windows-1252 differs from Latin-1
  static constexpr char16_t kHigh[32] = {
      0x20ac, 0xfffd, 0x201a, 0x0192, 0x201e, 0x2026, 0x2020, 0x2021, 0x02c6, 0x2030, 0x0160,
      0x2039, 0x0152, 0xfffd, 0x017d, 0xfffd, 0xfffd, 0x2018, 0x2019, 0x201c, 0x201d, 0x2022,
      0x2013, 0x2014, 0x02dc, 0x2122, 0x0161, 0x203a, 0x0153, 0xfffd, 0x017e, 0x0178};
  std::string out;
  out.reserve(s.size() + 8);
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    char16_t u = c < 0x80 ? c : c < 0xa0 ? kHigh[c - 0x80] : c;
    if (u < 0x80) {
      out.push_back(static_cast<char>(u));
    } else if (u < 0x800) {
      out.push_back(static_cast<char>(0xc0 | (u >> 6)));
      out.push_back(static_cast<char>(0x80 | (u & 0x3f)));
    } else {
      out.push_back(static_cast<char>(0xe0 | (u >> 12)));
      out.push_back(static_cast<char>(0x80 | ((u >> 6) & 0x3f)));
      out.push_back(static_cast<char>(0x80 | (u & 0x3f)));
    }
  }
  return out;
}

}  // namespace epure::grading
