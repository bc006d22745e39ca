#include "grading/roster.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "grading/answer_reading.h"
#include "grading/csv_reader.h"
#include "grading/encoding.h"
#include "grading/words.h"

namespace epure::grading {

namespace {

// Where each field is in a record.
struct Columns {
  int number = -1, name = -1, first = -1, last = -1, email = -1;
};

std::string utf8(std::string_view s) { return valid_utf8(s) ? std::string(s) : cp1252_to_utf8(s); }

// The header's columns, or nothing when the first record is not a header (no cell names a
// student number, a name or an e-mail).
std::optional<Columns> header_columns(const std::vector<std::string_view>& cells) {
  Columns c;
  bool any = false;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto w = read_word(trim_cell(cells[i]));
    if (!w) continue;
    int* slot = *w == "student_number" ? &c.number
                : *w == "student"      ? &c.name
                : *w == "first_name"   ? &c.first
                : *w == "last_name"    ? &c.last
                : *w == "email"        ? &c.email
                                       : nullptr;
    if (slot && *slot < 0) {
      *slot = static_cast<int>(i);
      any = true;
    }
  }
  if (!any) return std::nullopt;
  // "Nom" beside "Prénom": the family name
  if (c.first >= 0 && c.last < 0 && c.name >= 0) std::swap(c.last, c.name);
  return c;
}

bool plausible_email(std::string_view e) {
  const auto at = e.find('@');
  return at != std::string_view::npos && at > 0 && at + 1 < e.size() && e.find_first_of(" \t;,") == std::string_view::npos &&
         e.find('@', at + 1) == std::string_view::npos;
}

Roster read(CsvReader& reader, std::string_view source) {
  Roster r;
  r.source = std::string(source);
  CsvRecord rec;
  std::optional<Columns> columns;
  bool first = true;
  std::unordered_map<std::string, int> seen;  // number key → its line
  try {
    while (reader.next(rec)) {
      if (!rec.problem.empty())
        r.problems.push_back({rec.line, true, "malformed", {{"why", std::string(rec.problem)}}});
      if (first) {
        first = false;
        columns = header_columns(rec.cells);
        if (columns) {
          if (columns->number < 0)
            r.problems.push_back({rec.line, true, "no_number_column", {}});
          continue;
        }
        columns = Columns{0, 1, -1, -1, 2};  // no header: number, name, e-mail
      }
      // read as UTF-8 (Windows-1252 when it is not), then trimmed: a Windows-1252 no-break space
      // is a blank like any other
      const auto cell = [&](int c) -> std::string {
        if (c < 0 || static_cast<std::size_t>(c) >= rec.cells.size()) return {};
        const std::string text = utf8(rec.cells[static_cast<std::size_t>(c)]);
        return std::string(trim_cell(text));
      };
      RosterEntry e;
      e.line = rec.line;
      e.number = cell(columns->number);
      e.name = cell(columns->name);
      if (e.name.empty() && (columns->first >= 0 || columns->last >= 0)) {
        const std::string f = cell(columns->first), l = cell(columns->last);
        e.name = f.empty() ? l : l.empty() ? f : f + " " + l;
      }
      e.email = cell(columns->email);
      if (e.number.empty() && e.name.empty() && e.email.empty()) continue;  // a row of empty cells
      if (e.number.empty()) {
        r.problems.push_back({rec.line, true, "no_number", {{"name", e.name}}});
        continue;
      }
      const std::string key = roster_number_key(e.number);
      if (auto [it, fresh] = seen.emplace(key, rec.line); !fresh) {
        r.problems.push_back({rec.line, true, "duplicate", {{"number", e.number}, {"first", std::to_string(it->second)}}});
        continue;
      }
      if (e.name.empty()) r.problems.push_back({rec.line, false, "no_name", {{"number", e.number}}});
      if (!e.email.empty() && !plausible_email(e.email)) {
        r.problems.push_back({rec.line, false, "bad_email", {{"email", e.email}, {"number", e.number}}});
        e.email.clear();
      }
      r.students.push_back(std::move(e));
    }
  } catch (const std::exception& ex) {  // a record past the reader's limits
    r.problems.push_back({0, true, "unreadable", {{"why", ex.what()}}});
  }
  if (r.students.empty()) r.problems.push_back({0, true, "empty", {}});
  r.index();
  return r;
}

}  // namespace

std::string roster_number_key(std::string_view number) {
  std::string k;
  for (const char c : number) {
    if (c == ' ' || c == '\t') continue;
    k.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
  }
  return k;
}

std::string roster_name_key(std::string_view name) {
  std::string folded = fold_word(name);
  for (char& c : folded)
    if (c == ',' || c == '-' || c == ';') c = ' ';
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < folded.size()) {
    const auto space = folded.find(' ', i);
    const auto w = folded.substr(i, space == std::string::npos ? std::string::npos : space - i);
    if (!w.empty()) words.push_back(w);
    if (space == std::string::npos) break;
    i = space + 1;
  }
  std::sort(words.begin(), words.end());
  return fmt::format("{}", fmt::join(words, " "));
}

void Roster::index() {
  numbers_.clear();
  emails_.clear();
  names_.clear();
  std::unordered_map<std::string, int> name_count;
  for (std::size_t i = 0; i < students.size(); ++i) {
    const RosterEntry& e = students[i];
    numbers_.emplace(roster_number_key(e.number), i);
    if (!e.email.empty()) emails_.emplace(fold_word(e.email), i);
    if (!e.name.empty()) {
      const std::string k = roster_name_key(e.name);
      if (++name_count[k] == 1) names_.emplace(k, i);
      else names_.erase(k);  // two students of one name: never matched by name
    }
  }
  for (const auto& [k, n] : name_count)
    if (n > 1) names_.erase(k);
}

const RosterEntry* Roster::by_number(std::string_view number) const {
  const auto it = numbers_.find(roster_number_key(number));
  return it == numbers_.end() ? nullptr : &students[it->second];
}

const RosterEntry* Roster::by_email(std::string_view email) const {
  const auto it = emails_.find(fold_word(email));
  return it == emails_.end() ? nullptr : &students[it->second];
}

const RosterEntry* Roster::by_name(std::string_view name) const {
  const auto it = names_.find(roster_name_key(name));
  return it == names_.end() ? nullptr : &students[it->second];
}

Roster read_roster(const std::filesystem::path& path) {
  CsvReader reader(path);
  return read(reader, path.string());
}

Roster read_roster_text(std::string text, std::string_view source) {
  CsvReader reader = CsvReader::from_text(std::move(text));
  return read(reader, source);
}

std::string describe(const RosterProblem& p, const Texts& texts) {
  return texts.format("grading.roster." + p.code, p.vars);
}

}  // namespace epure::grading
