#include "grading/session.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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

// Points as the language writes them, without trailing zeros ("1,5").
std::string points_text(double x, bool decimal_comma) {
  std::string s = fmt::format("{}", std::round(x * 1000) / 1000);
  if (decimal_comma)
    for (char& c : s)
      if (c == '.') c = ',';
  return s;
}

bool looks_like_question(std::string_view name) {
  return !name.empty() && name[0] >= '0' && name[0] <= '9' && name.find('.') != std::string_view::npos;
}

}  // namespace

GradingSession::GradingSession(const AnswerKey& key, SessionOptions options)
    : key_(key),
      options_(std::move(options)),
      texts_(Texts::builtin(options_.language.empty() ? key.info.language : options_.language)),
      stats_(key.question_ids()) {
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
  if (options_.corrections) take_corrections(*options_.corrections);
}

// Each correction resolved against the key: its sheet (as a row's sheet id is: any case, the
// nearest id named when it is not one), its question (one the sheet asks, or the student
// number). A correction that cannot be placed is said with its entry and left out; the others
// are applied to their sheet's rows.
void GradingSession::take_corrections(const Corrections& corrections) {
  const std::string_view file = corrections.source;
  for (const auto& p : corrections.problems) problem(0, describe(p, texts_), true, "corrections", file);
  if (!corrections.readable) return;
  int last = 0;
  for (const auto& c : corrections.entries) last = std::max(last, c.entry);
  correction_used_.assign(static_cast<std::size_t>(last) + 1, 0);
  const auto& ids = key_.question_ids();
  auto refuse = [&](const Correction& c, std::string_view code, TextVars vars) {
    vars.emplace_back("sheet", c.sheet);
    vars.emplace_back("question", c.question);
    problem(0,
            describe(CorrectionsProblem{c.entry, std::string(code), std::move(vars)}, texts_), true,
            "corrections", file);
  };
  for (std::size_t k = 0; k < corrections.entries.size(); ++k) {
    const Correction& c = corrections.entries[k];
    const SheetLookup found = find_sheet(key_, trim_cell(c.sheet), texts_);
    if (!found.sheet) {
      correction_used_[static_cast<std::size_t>(c.entry)] = 1;  // said once, here
      refuse(c, "unknown_sheet", {{"why", found.why}});
      continue;
    }
    int question = kStudentNumber;
    if (const auto w = read_word(c.question); !(w && *w == "student_number")) {
      question = -2;
      for (const auto& e : found.sheet->exercises)
        for (const auto& q : e.questions)
          if (q.id == c.question || (q.id.size() == c.question.size() &&
                                     std::equal(q.id.begin(), q.id.end(), c.question.begin(), [](char a, char b) {
                                       return std::tolower(static_cast<unsigned char>(a)) ==
                                              std::tolower(static_cast<unsigned char>(b));
                                     })))
            question = static_cast<int>(std::find(ids.begin(), ids.end(), q.id) - ids.begin());
      if (question == -2) {
        correction_used_[static_cast<std::size_t>(c.entry)] = 1;
        refuse(c, "not_asked", {{"id", found.sheet->id}});
        continue;
      }
    }
    auto& list = corrections_[key_.index_of(*found.sheet)];
    bool replaced = false;
    for (auto& earlier : list)
      if (earlier.question == question) {
        problem(0,
                describe(CorrectionsProblem{c.entry, "repeated", {{"first", std::to_string(earlier.entry)}, {"sheet", found.sheet->id}, {"question", c.question}}},
                         texts_),
                false, "corrections", file);
        correction_used_[static_cast<std::size_t>(earlier.entry)] = 1;  // said here
        earlier = {question, c.value, c.entry};
        replaced = true;
      }
    if (!replaced) list.push_back({question, c.value, c.entry});
  }
}

void GradingSession::problem(int line, std::string message, bool error, std::string_view kind, std::string_view file) {
  message = one_line(message);
  (error ? outcome_.errors : outcome_.warnings)++;
  int& printed = printed_[std::string(kind)];
  if (options_.log) {
    const std::string_view name = file.empty() ? std::string_view(options_.answers_name) : file;
    const std::string where = line > 0 ? fmt::format("{}:{}", name, line) : std::string(name);
    if (printed < kPrintedPerKind) {
      fmt::print(options_.log, "{}: {}: {}\n", where, texts_.get(error ? "grading.problem.error" : "grading.problem.warning"),
                 message);
    } else if (printed == kPrintedPerKind) {
      fmt::print(options_.log, "{}: {}\n", options_.answers_name, texts_.get("grading.problem.more_not_printed"));
    }
  }
  ++printed;
  if (outcome_.problems.size() < kKeptProblems) outcome_.problems.push_back({line, std::move(message), error, std::string(file)});
  else ++outcome_.problems_not_kept;
}

void GradingSession::header(const std::vector<std::string>& names, int line) {
  names_ = names;
  for (auto& n : names_)
    if (!valid_utf8(n)) n = cp1252_to_utf8(n);
  if (line > 0) header_line_ = line;
  columns_.assign(key_.sheets().size(), nullptr);
  layouts_.clear();
  sheet_column_ = student_column_ = student_number_column_ = -1;
  const auto& ids = key_.question_ids();
  question_column_.assign(ids.size(), -1);
  point_column_.assign(ids.size(), -1);
  column_question_.assign(names_.size(), -1);
  // "2.P" names the point whose first coordinate is "2.P.x"
  const auto point_of = [&](std::string_view name) -> int {
    for (std::size_t q = 0; q < ids.size(); ++q) {
      const std::string& id = ids[q];
      if (!id.ends_with(".x") || id.size() != name.size() + 2) continue;
      if (std::equal(name.begin(), name.end(), id.begin(), [](char a, char b) {
            return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
          }))
        return static_cast<int>(q);
    }
    return -1;
  };
  // a header naming a question by its place on the sheet where it now has a number of its own
  // ("1.dot" for P.dot) was written for the set's sheets as numbered before: read it by place
  bool by_place = false;
  for (const auto& n : names_) by_place = by_place || key_.only_by_place(trim_cell(n));
  if (by_place) problem(header_line_, texts_.get("grading.problem.columns_by_place"), false, "column");
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
    if (word && *word == "student_number" && student_number_column_ < 0) {
      student_number_column_ = static_cast<int>(c);
      continue;
    }
    // by place, "2.P" is the point whose first coordinate was "2.P.x"
    std::string point_name(name);
    if (by_place)
      if (const std::string* id = key_.id_of_place_name(point_name + ".x")) point_name = id->substr(0, id->size() - 2);
    if (const int x = point_of(point_name); x >= 0 && looks_like_question(name) && point_column_[static_cast<std::size_t>(x)] < 0) {
      point_column_[static_cast<std::size_t>(x)] = static_cast<int>(c);
      continue;
    }
    auto it = ids.end();
    // "6.t": a header written before exercises had numbers of their own, every column by place
    if (by_place)
      if (const std::string* id = key_.id_of_place_name(name)) it = std::find(ids.begin(), ids.end(), *id);
    if (it == ids.end()) it = std::find(ids.begin(), ids.end(), name);
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
        problem(header_line_,
                texts_.format("grading.problem.column_repeat", {{"column", std::to_string(c + 1)},
                                                                {"id", *it},
                                                                {"first", std::to_string(question_column_[q] + 1)}}),
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
    const TextVars vars{{"column", std::to_string(c + 1)}, {"name", std::string(name)}};
    if (looks_like_question(name) ||
        (name.find('.') != std::string_view::npos && key_.has_number(name.substr(0, name.find('.')))))
      problem(header_line_, texts_.format("grading.problem.column_not_in_key", vars), true, "column");
    else
      problem(header_line_, texts_.format("grading.problem.column_ignored", vars), false, "column");
  }
  if (sheet_column_ < 0)
    throw std::runtime_error(fmt::format(
        "{}:{}: {}", options_.answers_name, std::max(header_line_, 1),
        texts_.format("grading.problem.no_sheet_column", {{"names", one_line(fmt::format("{}", fmt::join(names_, ", ")))}})));
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
      problem(r.line, texts_.get("grading.problem.encoding"), false, "encoding");
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
  s.score = s.max = s.held = 0;
  s.to_check = 0;
  s.flags.clear();
  s.sheet_text = trim_cell(cell(sheet_column_));
  s.student.assign(trim_cell(cell(student_column_)));
  s.student_number.assign(trim_cell(cell(student_number_column_)));

  if (r.problem == "unclosed_quote")
    flag(s, "malformed",
         texts_.format("grading.flag.unclosed_quote", {{"from", std::to_string(r.line)}, {"to", std::to_string(r.last_line)}}),
         true);
  else if (r.problem == "text_after_quote" || r.problem == "not_an_object" || r.problem == "too_many_names")
    flag(s, "malformed", texts_.get(fmt::format("grading.flag.{}", r.problem)), true);

  const TextVars widths{{"cells", std::to_string(r.cells.size())}, {"width", std::to_string(width)}};
  if (r.cells.size() < width && r.problem.empty()) {
    flag(s, "ragged", texts_.format("grading.flag.ragged_short", widths), true);
  } else if (r.cells.size() > width) {
    std::vector<std::string> extra;
    for (std::size_t c = width; c < r.cells.size(); ++c)
      if (!trim_cell(r.cells[c]).empty()) extra.push_back(quoted(trim_cell(r.cells[c])));
    if (!extra.empty()) {
      TextVars vars = widths;
      vars.emplace_back("extra", fmt::format("{}", fmt::join(extra, ", ")));
      flag(s, "ragged", texts_.format("grading.flag.ragged_long", vars), true);
    }
  }

  if (s.sheet_text.empty()) {
    flag(s, "no_sheet", texts_.get("grading.flag.no_sheet"), true);
  } else {
    const SheetLookup found = find_sheet(key_, s.sheet_text, texts_);
    if (!found.sheet) {
      std::string message = found.why;
      if (!found.nearest.empty())
        message = texts_.format(found.distance == 1 ? "grading.flag.nearest_one" : "grading.flag.nearest_many",
                                {{"why", message}, {"nearest", found.nearest}, {"distance", std::to_string(found.distance)}});
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
      s.flags.push_back({"duplicate", count > 1 ? texts_.format("grading.flag.submitted_times",
                                                                {{"sheet", sheet.id}, {"count", std::to_string(count)}})
                                                : texts_.format("grading.flag.submitted_before",
                                                                {{"sheet", sheet.id}, {"first", std::to_string(first)}})});
    }
    marks_.resize(sheet.exercises.size());
    const std::vector<SheetCorrection>* fixes = nullptr;
    if (!corrections_.empty())
      if (auto it = corrections_.find(index); it != corrections_.end()) fixes = &it->second;
    if (fixes)
      for (const auto& f : *fixes)
        if (f.question == kStudentNumber) {
          s.student_number.assign(trim_cell(f.value));
          correction_used_[static_cast<std::size_t>(f.entry)] = 1;
          ++outcome_.corrections_applied;
        }
    std::string to_check, swapped;
    for (std::size_t e = 0; e < sheet.exercises.size(); ++e) {
      const ExerciseKey& ex = sheet.exercises[e];
      const auto& report = cols.report_index[e];
      cells_.clear();
      for (std::size_t q = 0; q < cols.column[e].size(); ++q) {
        std::string_view text = cell(cols.column[e][q]);
        // a point typed under its own name ("2.P"), when its first coordinate's cell is empty
        if (trim_cell(text).empty()) {
          const int point = point_column_[static_cast<std::size_t>(report[q])];
          if (point >= 0) text = cell(point);
        }
        cells_.push_back(text);
      }
      std::size_t corrected_here = 0;
      if (fixes)
        for (const auto& f : *fixes)
          for (std::size_t q = 0; q < report.size(); ++q)
            if (report[q] == f.question) {
              cells_[q] = f.value;
              corrected_here |= std::size_t(1) << std::min<std::size_t>(q, 63);
              correction_used_[static_cast<std::size_t>(f.entry)] = 1;
              ++outcome_.corrections_applied;
            }
      mark_exercise(ex, cells_, marking_, marks_[e]);
      for (std::size_t q = 0; q < ex.questions.size(); ++q) {
        QuestionMark& m = marks_[e][q];
        if (corrected_here && q < 64 && (corrected_here >> q & 1)) m.corrected = true;
        s.score += m.points;
        if (m.verdict == Verdict::to_check) {
          s.held += ex.hot[q].points;
          ++s.to_check;
          if (!to_check.empty()) to_check += "; ";
          to_check += texts_.format("grading.flag.to_check_item",
                                    {{"id", ex.questions[q].id},
                                     {"value", quoted(m.given.raw)},
                                     {"why", texts_.get(fmt::format("grading.why.{}", m.given.why))}});
        }
        if (m.note == "swapped_cells" && q + 1 < ex.questions.size() && marks_[e][q + 1].note == "swapped_cells" &&
            marks_[e][q + 1].note_field == ex.questions[q].id) {
          if (!swapped.empty()) swapped += "; ";
          swapped += texts_.format("grading.flag.swapped_item", {{"a", ex.questions[q].id}, {"b", ex.questions[q + 1].id}});
        }
      }
    }
    s.max = sheet.max_points;
    s.marks = marks_;
    s.report_index = cols.report_index;
    if (!to_check.empty()) {
      flag(s, "to_check",
           texts_.format("grading.flag.to_check", {{"list", to_check}, {"points", points_text(s.held, marking_.numbers.decimal_comma)}}),
           true);
      ++outcome_.to_check_rows;
      outcome_.to_check += s.to_check;
    }
    if (!swapped.empty()) flag(s, "swapped_cells", texts_.format("grading.flag.swapped_cells", {{"list", swapped}}), false);
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
      flag(s, "not_asked", texts_.format("grading.flag.not_asked", {{"sheet", sheet.id}, {"list", stray}}), true);
    ++outcome_.marked;
  }
  stats_.add(s);
  for (auto* sink : sinks_) sink->submission(s);
}

const Outcome& GradingSession::finish(const SourceInfo& source) {
  outcome_.source = source;
  if (!source.stopped.empty()) problem(0, texts_.format("grading.problem.stopped", {{"why", source.stopped}}), true, "stopped");
  if (header_line_ == 0 && names_.empty() && source.format != "json" && source.format != "jsonl")
    problem(0, texts_.get("grading.problem.empty_file"), true, "empty");
  else if (outcome_.rows == 0)
    problem(0, texts_.get("grading.problem.no_rows"), true, "empty");
  for (auto& [id, seen] : duplicate_lines_) {
    const auto& [lines, more] = seen;
    std::vector<std::string> at;
    for (int l : lines) at.push_back(std::to_string(l));
    if (more > 0) at.push_back(texts_.format("grading.problem.and_more", {{"count", std::to_string(more)}}));
    problem(0,
            texts_.format("grading.problem.duplicate_summary", {{"sheet", id},
                                                                {"count", std::to_string(lines.size() + more)},
                                                                {"lines", fmt::format("{}", fmt::join(at, ", "))}}),
            false, "duplicate_summary");
    outcome_.duplicates.emplace_back(id, lines);
  }
  if (options_.corrections)
    for (const auto& c : options_.corrections->entries)
      if (!correction_used_[static_cast<std::size_t>(c.entry)])
        problem(0,
                describe(CorrectionsProblem{c.entry, "unused", {{"sheet", c.sheet}, {"answers", options_.answers_name}}},
                         texts_),
                false, "corrections", options_.corrections->source);
  if (outcome_.empty_rows > 0)
    problem(0,
            texts_.format(outcome_.empty_rows == 1 ? "grading.problem.empty_rows_one" : "grading.problem.empty_rows_many",
                          {{"count", std::to_string(outcome_.empty_rows)}}),
            false, "empty_rows");
  for (auto* sink : sinks_) sink->finish(stats_, outcome_);
  return outcome_;
}

}  // namespace epure::grading
