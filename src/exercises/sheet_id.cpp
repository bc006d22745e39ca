#include "exercises/sheet_id.h"

#include <fmt/format.h>

#include <array>

namespace epure {

namespace {

constexpr std::string_view kAlphabet = "0123456789ABCDEFGHJKMNPQRSTVWXYZ";
constexpr int kDataChars = 11;

int value_of(char ch) {
  if (ch >= 'a' && ch <= 'z') ch = static_cast<char>(ch - 'a' + 'A');
  if (ch == 'O') ch = '0';
  if (ch == 'I' || ch == 'L') ch = '1';
  auto pos = kAlphabet.find(ch);
  return pos == std::string_view::npos ? -1 : static_cast<int>(pos);
}

// Luhn mod N (N = 32): from the right, every second value doubled and folded back into 0..31.
int check_value(const std::array<int, kDataChars>& data) {
  int sum = 0;
  bool twice = true;
  for (int i = kDataChars - 1; i >= 0; --i) {
    int addend = data[i] * (twice ? 2 : 1);
    addend = addend / 32 + addend % 32;
    sum += addend;
    twice = !twice;
  }
  return (32 - sum % 32) % 32;
}

std::string format_id(const std::array<int, kDataChars>& data, int check) {
  std::string s;
  for (int i = 0; i < kDataChars; ++i) {
    if (i == 4 || i == 8) s.push_back('-');
    s.push_back(kAlphabet[data[i]]);
  }
  s.push_back(kAlphabet[check]);
  return s;
}

}  // namespace

std::string SheetId::str() const {
  // 55 bits: version (5) | seed (35) | index (15), most significant first
  const std::uint64_t bits = (std::uint64_t(version) << 50) | (seed << 15) | std::uint64_t(index);
  std::array<int, kDataChars> data{};
  for (int i = 0; i < kDataChars; ++i) data[i] = int((bits >> (5 * (kDataChars - 1 - i))) & 31);
  return format_id(data, check_value(data));
}

ParsedSheetId parse_sheet_id(std::string_view text) {
  std::array<int, kDataChars + 1> values{};
  int count = 0;
  for (char ch : text) {
    if (ch == '-' || ch == ' ' || ch == '\t') continue;
    int v = value_of(ch);
    if (v < 0) return {std::nullopt, {fmt::format("'{}' is not a sheet-id character", ch), "character", std::string(1, ch)}};
    if (count == kDataChars + 1)
      return {std::nullopt, {"too long for a sheet id (12 characters)", "too_long", {}}};
    values[count++] = v;
  }
  if (count != kDataChars + 1)
    return {std::nullopt, {fmt::format("a sheet id has 12 characters, this one has {}", count), "length", std::to_string(count)}};

  std::array<int, kDataChars> data{};
  for (int i = 0; i < kDataChars; ++i) data[i] = values[i];
  if (check_value(data) != values[kDataChars]) {
    // Any single mistyped character or adjacent swap lands here. Which id was meant is for
    // the caller to say, from the ids it knows (grading suggests the nearest id of the set).
    return {std::nullopt, {"check character does not match: a character is mistyped", "check", {}}};
  }
  std::uint64_t bits = 0;
  for (int v : data) bits = (bits << 5) | std::uint64_t(v);
  SheetId id;
  id.version = int(bits >> 50);
  id.seed = (bits >> 15) & kMaxSeed;
  id.index = int(bits & (kMaxSheets - 1));
  return {id, {}};
}

}  // namespace epure
