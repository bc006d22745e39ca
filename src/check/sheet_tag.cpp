#include "check/sheet_tag.h"

#include <algorithm>
#include <array>
#include <cctype>

#include "check/submission.h"

namespace epure::check {

namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '*' || c == '/'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// The key folded: lower case ASCII, é/è/É as e, spaces and dashes as one space.
std::string fold(std::string_view key) {
  std::string out;
  for (std::size_t i = 0; i < key.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(key[i]);
    if (c == 0xC3 && i + 1 < key.size()) {
      const unsigned char d = static_cast<unsigned char>(key[i + 1]);
      if (d == 0xA9 || d == 0xA8 || d == 0x89 || d == 0x88) {  // é è É È
        out += 'e';
        ++i;
        continue;
      }
    }
    if (c == ' ' || c == '-' || c == '_' || c == '\t') {
      if (!out.empty() && out.back() != ' ') out += ' ';
      continue;
    }
    out += static_cast<char>(std::tolower(c));
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

constexpr std::array<std::string_view, 6> kSheetKeys{"sheet", "sheet id", "feuille", "id", "identifiant",
                                                     "id de feuille"};
constexpr std::array<std::string_view, 7> kStudentKeys{"student", "name", "etudiant", "etudiante", "nom", "eleve",
                                                       "student name"};

bool one_of(const std::string& key, auto const& keys) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }

// The starter's placeholders ("XXXX-XXXX-XXXX", "First Last", "Prénom Nom") say nothing.
bool placeholder(std::string_view value) {
  return value.empty() || value == "First Last" || value == "Prénom Nom" ||
         value.find("XXXX") != std::string_view::npos;
}

// Cut at kMaxTagValue bytes, not inside a UTF-8 character; invalid bytes become '?'.
std::string clean(std::string_view value) {
  std::string out;
  for (std::size_t i = 0; i < value.size() && out.size() < kMaxTagValue;) {
    const unsigned char c = static_cast<unsigned char>(value[i]);
    std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    bool valid = n > 0 && i + n <= value.size();
    for (std::size_t k = 1; valid && k < n; ++k) valid = (static_cast<unsigned char>(value[i + k]) >> 6) == 2;
    if (!valid || (n == 1 && c < 0x20)) {
      out += '?';
      ++i;
      continue;
    }
    if (out.size() + n > kMaxTagValue) break;
    out.append(value.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace

SubmissionTags read_tags(std::string_view source) {
  SubmissionTags tags;
  bool have_sheet = false, have_student = false;
  for (const Comment& comment : comments_of(source)) {
    std::string_view text = comment.text;
    int line = comment.line;
    while (!text.empty() && !(have_sheet && have_student)) {
      const std::size_t end = text.find('\n');
      const std::string_view raw = text.substr(0, end);
      text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
      const int this_line = line++;
      const std::size_t colon = raw.find(':');
      if (colon == std::string_view::npos || colon > 40) continue;
      const std::string key = fold(trim(raw.substr(0, colon)));
      std::string_view value = trim(raw.substr(colon + 1));
      // what follows the value on the line, after two spaces ("<- the id printed …"), is a note
      if (const std::size_t gap = value.find("  "); gap != std::string_view::npos) value = trim(value.substr(0, gap));
      if (!have_sheet && one_of(key, kSheetKeys)) {
        have_sheet = true;
        if (placeholder(value)) continue;
        tags.sheet_text = clean(value);
        tags.sheet_line = this_line;
        const ParsedSheetId parsed = parse_sheet_id(value);
        if (parsed.id) tags.sheet = parsed.id;
        else tags.sheet_problem = parsed.error.message;
      } else if (!have_student && one_of(key, kStudentKeys)) {
        have_student = true;
        if (!placeholder(value)) tags.student = clean(value);
      }
    }
    if (have_sheet && have_student) break;
  }
  return tags;
}

}  // namespace epure::check
