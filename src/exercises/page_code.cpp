#include "exercises/page_code.h"

#include <fmt/format.h>

#include <charconv>
#include <vector>

#include "exercises/sheet_id.h"

namespace epure {

namespace {

constexpr std::string_view kAlphabet = "0123456789ABCDEFGHJKMNPQRSTVWXYZ";
constexpr int kMaxPages = 999;

char check_char(std::string_view sheet, int page, int pages) {
  std::vector<int> values;
  for (char ch : sheet)
    if (auto pos = kAlphabet.find(ch); pos != std::string_view::npos) values.push_back(static_cast<int>(pos));
  for (char ch : std::to_string(page)) values.push_back(ch - '0');
  for (char ch : std::to_string(pages)) values.push_back(ch - '0');
  // Luhn mod 32, as the sheet id's own check: from the right, every second value doubled
  int sum = 0;
  bool twice = true;
  for (auto it = values.rbegin(); it != values.rend(); ++it) {
    int addend = *it * (twice ? 2 : 1);
    sum += addend / 32 + addend % 32;
    twice = !twice;
  }
  return kAlphabet[static_cast<std::size_t>((32 - sum % 32) % 32)];
}

std::optional<int> small_number(std::string_view s) {
  if (s.empty() || s.size() > 3 || s[0] == '0') return std::nullopt;
  int v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

}  // namespace

std::string page_code_text(const PageCode& code) {
  return fmt::format("{}/{}/{}/{}", code.sheet, code.page, code.pages, check_char(code.sheet, code.page, code.pages));
}

std::optional<PageCode> parse_page_code(std::string_view text) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == '/') {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  if (parts.size() != 4 || parts[3].size() != 1) return std::nullopt;
  const auto id = parse_sheet_id(parts[0]);
  if (!id.id || id.id->str() != parts[0]) return std::nullopt;
  const auto page = small_number(parts[1]);
  const auto pages = small_number(parts[2]);
  if (!page || !pages || *page > *pages || *pages > kMaxPages) return std::nullopt;
  if (check_char(parts[0], *page, *pages) != parts[3][0]) return std::nullopt;
  return PageCode{std::string(parts[0]), *page, *pages};
}

}  // namespace epure
