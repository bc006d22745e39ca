#include "grading/session.h"

#include <fmt/format.h>

#include <algorithm>

#include "grading/answer_reading.h"
#include "grading/encoding.h"
#include "grading/sheet_lookup.h"
#include "grading/words.h"

namespace epure::grading {

namespace {

// Control characters written as escapes (\n, \t, \x00): a problem is one line of the
// terminal, whatever the file's cells and header hold.
std::string one_line(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) out += fmt::format("\\x{:02x}", u);
    else out += c;
  }
  return out;
}

// "2.t “abc”": a cell quoted in a message, cut when long.
std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 40;
  if (s.size() <= kMax) return fmt::format("\"{}\"", s);
  std::size_t cut = kMax;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xc0) == 0x80) --cut;  // not mid-character
  return fmt::format("\"{}…\"", s.substr(0, cut));
}

std::string_view why_unreadable(std::string_view code) {
  if (code == "division_by_zero") return "divides by zero";
  if (code == "negative_root") return "takes the root of a negative number";
  if (code == "boolean") return "is not yes or no";
  if (code == "word") return "is not one of the answers offered";
  if (code == "faces") return "is not a list of sides such as +x -y";
  return "is not a number";
}

bool looks_like_question(std::string_view name) {
  return !name.empty() && name[0] >= '0' && name[0] <= '9' && name.find('.') != std::string_view::npos;
}

}  // namespace

GradingSession::GradingSession(const AnswerKey& key, SessionOptions options)
    : key_(key), options_(std::move(options)), stats_(key.question_ids()) {
  marking_.follow_through = options_.follow_through.value_or(key.info.follow_through);
  const std::string language = options_.language.empty() ? key.info.language : options_.language;
  marking_.numbers = NumberStyle::for_language(language);
  marking_.decimals = key.info.decimals;
  outcome_.answers = options_.answers_name;
  outcome_.follow_through = marking_.follow_through;
  outcome_.language = language;
  counts_.assign(key.sheets().size(), 0);
  first_line_.assign(key.sheets().size(), 0);
  for (const auto& [id, n] : options_.sheet_counts)
    if (const SheetKey* s = key.find(id)) counts_[key.index_of(*s)] = n;
}

void GradingSession::problem(int line, std::string message, bool error, std::string_view kind) {
  message = one_line(message);
  (error ? outcome_.errors : outcome_.warnings)++;
  int& printed = printed_[std::string(kind)];
  if (options_.log) {
    const std::string where = line > 0 ? fmt::format("{}:{}", options_.answers_name, line)
                                       : std::string(options_.answers_name);
    if (printed < kPrintedPerKind) {
      fmt::print(options_.log, "{}: {}: {}\n", where, error ? "error" : "warning", message);
    } else if (printed == kPrintedPerKind) {
      fmt::print(options_.log, "{}: more problems like the previous ones are counted, not printed (--json lists every row's)\n",
                 options_.answers_name);
    }
  }
  ++printed;
  if (outcome_.problems.size() < kKeptProblems) outcome_.problems.push_back({line, std::move(message), error});
  else ++outcome_.problems_not_kept;
}

void GradingSession::header(const std::vector<std::string>& names, int line) {
  names_ = names;
  for (auto& n : names_)
    if (!valid_utf8(n)) n = cp1252_to_utf8(n);
  if (line > 0) header_line_ = line;
  columns_.assign(key_.sheets().size(), nullptr);
  layouts_.clear();
  sheet_column_ = student_column_ = -1;
  const auto& ids = key_.question_ids();
  question_column_.assign(ids.size(), -1);
  column_question_.assign(names_.size(), -1);
  for (std::size_t c = 0; c < names_.size(); ++c) {
    std::string_view name = trim_cell(names_[c]);
    if (c == 0 && name.substr(0, 3) == "\xef\xbb\xbf") name.remove_prefix(3);  // a BOM written twice
    const auto word = read_word(name);
    if (word && *word == "sheet" && sheet_column_ < 0) {
      sheet_column_ = static_cast<int>(c);
      continue;
    }
    if (word && *word == "student" && student_column_ < 0) {
      student_column_ = static_cast<int>(c);
      continue;
    }
    auto it = std::find(ids.begin(), ids.end(), name);
    if (it == ids.end()) {
      // "2.T_AB" for "2.t_ab": ids are lower case but for the point names
      it = std::find_if(ids.begin(), ids.end(), [&](const std::string& id) {
        return id.size() == name.size() && std::equal(id.begin(), id.end(), name.begin(), [](char a, char b) {
                 return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
               });
      });
    }
    if (it != ids.end()) {
      const auto q = static_cast<std::size_t>(it - ids.begin());
      if (question_column_[q] >= 0) {
        problem(header_line_, fmt::format("column {} ({}) repeats column {}: the repeat is not read", c + 1, *it,
                                          question_column_[q] + 1),
                true, "column");
        continue;
      }
      question_column_[q] = static_cast<int>(c);
      column_question_[c] = static_cast<int>(q);
      continue;
    }
    if (name.empty() || warned_columns_.count(name)) continue;
    warned_columns_.emplace(std::string(name), true);
    // a name shaped like a question id is most likely a typo: an error; any other column (an
    // e-mail, a time stamp) a warning
    if (looks_like_question(name))
      problem(header_line_, fmt::format("column {} '{}' is not a question of this key: its answers are not read", c + 1, name),
              true, "column");
    else
      problem(header_line_, fmt::format("column {} '{}' is not a question: ignored", c + 1, name), false, "column");
  }
  if (sheet_column_ < 0)
    throw std::runtime_error(fmt::format("{}:{}: no sheet column: the header row needs a column named 'sheet' "
                                         "(the sheet id of each row); it has: {}",
                                         options_.answers_name, std::max(header_line_, 1),
                                         one_line(fmt::format("{}", fmt::join(names_, ", ")))));
}

const GradingSession::SheetColumns& GradingSession::columns_for(const SheetKey& sheet) {
  auto& slot = columns_[key_.index_of(sheet)];
  if (slot) return *slot;
  const auto& ids = key_.question_ids();
  std::vector<std::vector<int>> layout;
  for (const auto& e : sheet.exercises) {
    auto& rep = layout.emplace_back();
    for (const auto& q : e.questions)
      rep.push_back(static_cast<int>(std::find(ids.begin(), ids.end(), q.id) - ids.begin()));
  }
  auto& shared = layouts_[layout];
  if (!shared) {
    // the columns and the questions asked follow from the layout and the header alone
    SheetColumns c;
    c.asked.assign(names_.size(), 0);
    for (const auto& rep : layout) {
      auto& col = c.column.emplace_back();
      for (const int q_index : rep) {
        const int column = question_column_[static_cast<std::size_t>(q_index)];
        col.push_back(column);
        if (column >= 0) c.asked[static_cast<std::size_t>(column)] = 1;
      }
    }
    c.report_index = std::move(layout);
    shared = std::make_unique<SheetColumns>(std::move(c));
  }
  slot = shared.get();
  return *slot;
}

void GradingSession::flag(Submission& s, std::string_view code, std::string message, bool error) {
  problem(s.line, message, error, code);
  s.flags.push_back({code, std::move(message)});
}

void GradingSession::row(const AnswerRow& in) {
  // Windows-1252 text (Excel's plain "CSV"): every cell that is not UTF-8 is read as such
  AnswerRow r = in;
  const bool foreign = !all_valid_utf8(in.cells);
  if (foreign) {
    transcoded_.clear();
    for (auto c : in.cells) transcoded_.push_back(valid_utf8(c) ? std::string(c) : cp1252_to_utf8(c));
    transcoded_views_.assign(transcoded_.begin(), transcoded_.end());
    r.cells = transcoded_views_;
    if (!transcoded_warned_) {
      transcoded_warned_ = true;
      problem(r.line, "text that is not UTF-8 (a spreadsheet's plain \"CSV\" on Windows): read as Windows-1252; "
                      "export as \"CSV UTF-8\" to be sure",
              false, "encoding");
    }
  }
  const std::size_t width = names_.size();
  auto cell = [&](int c) -> std::string_view {
    return c >= 0 && static_cast<std::size_t>(c) < r.cells.size() ? r.cells[static_cast<std::size_t>(c)]
                                                                   : std::string_view{};
  };
  if (std::all_of(r.cells.begin(), r.cells.end(), [](std::string_view c) { return trim_cell(c).empty(); }) &&
      r.problem.empty()) {
    ++outcome_.empty_rows;
    return;
  }
  ++outcome_.rows;
  Submission& s = current_;
  s.line = r.line;
  s.last_line = r.last_line;
  s.sheet = nullptr;
  s.marks = {};
  s.report_index = {};
  s.score = s.max = 0;
  s.flags.clear();
  s.sheet_text = trim_cell(cell(sheet_column_));
  s.student.assign(trim_cell(cell(student_column_)));

  if (r.problem == "unclosed_quote")
    flag(s, "malformed", fmt::format("a quote opened on this row is never closed: lines {} to {} were read as one row", r.line, r.last_line), true);
  else if (r.problem == "text_after_quote")
    flag(s, "malformed", "text after a closing quote, kept in its cell (a quote inside a cell is written \"\")", true);
  else if (r.problem == "not_an_object")
    flag(s, "malformed", "not a JSON object: nothing on it could be read", true);
  else if (r.problem == "too_many_names")
    flag(s, "malformed", "names beyond the file's first 1024 different ones are not read", true);

  if (r.cells.size() < width && r.problem.empty()) {
    flag(s, "ragged", fmt::format("{} cells where the header has {}: the missing ones read as not answered", r.cells.size(), width),
         true);
  } else if (r.cells.size() > width) {
    std::vector<std::string> extra;
    for (std::size_t c = width; c < r.cells.size(); ++c)
      if (!trim_cell(r.cells[c]).empty()) extra.push_back(quoted(trim_cell(r.cells[c])));
    if (!extra.empty())
      flag(s, "ragged", fmt::format("{} cells where the header has {}: the extra ones are not read: {}", r.cells.size(), width,
                                    fmt::join(extra, ", ")),
           true);
  }

  if (s.sheet_text.empty()) {
    flag(s, "no_sheet", "no sheet id: the row cannot be marked", true);
  } else {
    const SheetLookup found = find_sheet(key_, s.sheet_text);
    if (!found.sheet) {
      std::string message = found.why;
      if (!found.nearest.empty())
        message += fmt::format("; the nearest sheet of this key is {} ({} character{} away)", found.nearest, found.distance,
                               found.distance == 1 ? "" : "s");
      flag(s, "unknown_sheet", std::move(message), true);
    } else {
      s.sheet = found.sheet;
    }
  }

  if (s.sheet) {
    const SheetKey& sheet = *s.sheet;
    // With a large key every row is another sheet's, whose questions are not in cache: ask for
    // all of them at once, so that their misses overlap instead of coming one by one as marking
    // walks the exercises (a hint only: nothing depends on it but the time).
    for (const ExerciseKey& ex : sheet.exercises) {
      const auto* p = reinterpret_cast<const char*>(ex.hot.data());
      const auto* end = reinterpret_cast<const char*>(ex.hot.data() + ex.hot.size());
      for (; p < end; p += 64) __builtin_prefetch(p);
    }
    const SheetColumns& cols = columns_for(sheet);
    // two submissions of one sheet: both marked, both flagged
    const std::size_t index = key_.index_of(sheet);
    const int count = counts_[index];
    const int first = first_line_[index];
    if (first == 0) first_line_[index] = r.line;
    if (count > 1 || first != 0) {
      auto& [lines, more] = duplicate_lines_[sheet.id];
      if (lines.empty() && first != 0 && count <= 1) lines.push_back(first);
      // the first few lines are named; the rest are counted, so memory does not grow with rows
      if (lines.size() < kNamedLines) lines.push_back(r.line);
      else ++more;
      s.flags.push_back({"duplicate", count > 1 ? fmt::format("sheet {} is submitted {} times: every one is marked", sheet.id, count)
                                                : fmt::format("sheet {} was already submitted on line {}: both are marked",
                                                              sheet.id, first)});
    }
    marks_.resize(sheet.exercises.size());
    std::string unreadable;
    for (std::size_t e = 0; e < sheet.exercises.size(); ++e) {
      const ExerciseKey& ex = sheet.exercises[e];
      cells_.clear();
      for (int c : cols.column[e]) cells_.push_back(cell(c));
      mark_exercise(ex, cells_, marking_, marks_[e]);
      for (std::size_t q = 0; q < ex.questions.size(); ++q) {
        const QuestionMark& m = marks_[e][q];
        s.score += m.points;
        if (m.verdict == Verdict::unreadable) {
          if (!unreadable.empty()) unreadable += "; ";
          unreadable += fmt::format("{} {} {}", ex.questions[q].id, quoted(m.given.raw), why_unreadable(m.given.why));
        }
      }
    }
    s.max = sheet.max_points;
    s.marks = marks_;
    s.report_index = cols.report_index;
    if (!unreadable.empty()) flag(s, "unreadable", fmt::format("unreadable, marked wrong: {}", unreadable), true);
    // answers in columns of questions this sheet does not ask
    std::string stray;
    for (std::size_t c = 0; c < r.cells.size() && c < width; ++c) {
      if (column_question_[c] < 0 || cols.asked[c]) continue;
      const auto v = trim_cell(r.cells[c]);
      if (v.empty()) continue;
      if (!stray.empty()) stray += ", ";
      stray += fmt::format("{} {}", key_.question_ids()[static_cast<std::size_t>(column_question_[c])], quoted(v));
    }
    if (!stray.empty())
      flag(s, "not_asked", fmt::format("answers to questions sheet {} does not ask, not marked: {}", sheet.id, stray), true);
    ++outcome_.marked;
  }
  stats_.add(s);
  for (auto* sink : sinks_) sink->submission(s);
}

const Outcome& GradingSession::finish(const SourceInfo& source) {
  outcome_.source = source;
  if (!source.stopped.empty()) problem(0, fmt::format("reading stopped: {}", source.stopped), true, "stopped");
  if (header_line_ == 0 && names_.empty() && source.format != "json" && source.format != "jsonl")
    problem(0, "the file is empty: no header row, no answers", true, "empty");
  else if (outcome_.rows == 0)
    problem(0, "no answers: the file has a header but no rows", true, "empty");
  for (auto& [id, seen] : duplicate_lines_) {
    const auto& [lines, more] = seen;
    std::vector<std::string> at;
    for (int l : lines) at.push_back(std::to_string(l));
    if (more > 0) at.push_back(fmt::format("and {} more", more));
    problem(0, fmt::format("sheet {} is submitted {} times (lines {}): every submission is marked and flagged", id,
                           lines.size() + more, fmt::join(at, ", ")),
            false, "duplicate_summary");
    outcome_.duplicates.emplace_back(id, lines);
  }
  if (outcome_.empty_rows > 0)
    problem(0, fmt::format("{} empty row{} skipped (every cell blank)", outcome_.empty_rows, outcome_.empty_rows == 1 ? "" : "s"),
            false, "empty_rows");
  for (auto* sink : sinks_) sink->finish(stats_, outcome_);
  return outcome_;
}

}  // namespace epure::grading
