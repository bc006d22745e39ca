#include "grading/gradebook.h"

#include <fmt/format.h>

#include <map>

#include "output/atomic_file.h"

namespace epure::grading {

namespace {

// One CSV cell, quoted when it holds the delimiter, a quote or a line break.
void put_cell(std::string& out, std::string_view s, char delimiter, bool first) {
  if (!first) out.push_back(delimiter);
  if (s.find_first_of(std::string{delimiter, '"', '\n', '\r'}) == std::string_view::npos) {
    out += s;
    return;
  }
  out.push_back('"');
  for (const char c : s) {
    if (c == '"') out.push_back('"');
    out.push_back(c);
  }
  out.push_back('"');
}

// A mark with the step's decimals at most, trailing zeros dropped ("14.5", "14,25").
std::string mark_text(double x, bool comma) {
  std::string s = fmt::format("{:.2f}", x);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (comma)
    for (char& c : s)
      if (c == '.') c = ',';
  return s;
}

}  // namespace

Gradebook::Gradebook(std::filesystem::path path, GradebookFormat format, const AnswerKey& key, const Texts& texts,
                     MarkScale scale, const Roster* roster, Report report)
    : path_(std::move(path)), format_(format), key_(key), words_(key, texts), scale_(scale), roster_(roster),
      report_(std::move(report)) {}

void Gradebook::submission(const Submission& s) {
  Row r;
  r.line = s.line;
  r.sheet = s.sheet ? s.sheet->id : std::string(s.sheet_text);
  r.student = s.student;
  r.number = s.student_number;
  r.marked = s.marked();
  r.to_check = s.to_check;
  r.score = s.score;
  r.max = s.max;
  r.mark = s.marked() ? scale_.mark(s.score, s.max) : 0;
  rows_.push_back(std::move(r));
}

void Gradebook::finish(const ClassStatistics&, const Outcome&) {
  const Texts& T = words_.texts();
  const auto who = [&](const Row& r) {
    return r.student.empty() ? (r.number.empty() ? r.sheet : r.number) : r.student;
  };
  // each row's student: the roster's entry, or the answers' own number without a roster
  std::vector<const RosterEntry*> entry(rows_.size(), nullptr);
  std::vector<std::string> number(rows_.size());
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const Row& r = rows_[i];
    if (roster_) {
      const RosterEntry* e = nullptr;
      if (!r.number.empty()) e = roster_->by_number(r.number);
      if (!e && !r.student.empty()) e = r.student.find('@') != std::string::npos ? roster_->by_email(r.student) : roster_->by_name(r.student);
      entry[i] = e;
      if (e) number[i] = e->number;
    } else {
      number[i] = r.number;
    }
  }
  // one mark per student: the later marked row
  std::map<std::string, std::size_t> kept;  // number key → row
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const Row& r = rows_[i];
    if (!r.marked) {
      report_(r.line, T.format("grading.roster.not_marked", {{"line", std::to_string(r.line)}, {"who", who(r)}}), false);
      continue;
    }
    if (number[i].empty()) {
      if (roster_)
        report_(r.line,
                T.format("grading.roster.not_found", {{"line", std::to_string(r.line)}, {"who", who(r)}, {"roster", roster_->source}}),
                true);
      else
        report_(r.line, T.format("grading.roster.no_id", {{"line", std::to_string(r.line)}, {"who", who(r)}}), true);
      continue;
    }
    auto [it, fresh] = kept.emplace(roster_number_key(number[i]), i);
    if (!fresh) {
      report_(r.line,
              T.format("grading.roster.twice", {{"who", who(r)}, {"first", std::to_string(rows_[it->second].line)}, {"line", std::to_string(r.line)}}),
              false);
      it->second = i;
    }
  }
  const bool moodle = format_ == GradebookFormat::moodle;
  const bool french = T.language() == "fr";
  const char delimiter = moodle || !french ? ',' : ';';
  const bool comma = !moodle && french;
  std::string out;
  if (!moodle && french) out += "\xef\xbb\xbf";  // Excel reads a French CSV as UTF-8 only with a BOM
  const std::string mark_header =
      scale_.out_of ? T.format("grading.gradebook.mark", {{"title", key_.info.title}, {"out_of", mark_text(*scale_.out_of, comma)}})
                    : T.format("grading.gradebook.points", {{"title", key_.info.title}});
  auto line_end = [&] { out += moodle ? "\n" : "\r\n"; };
  if (moodle) {
    put_cell(out, T.get("grading.gradebook.id_number"), delimiter, true);
    put_cell(out, T.get("grading.gradebook.email"), delimiter, false);
    put_cell(out, T.get("grading.gradebook.name"), delimiter, false);
    put_cell(out, mark_header, delimiter, false);
  } else {
    bool first = true;
    for (const char* h : {"id_number", "name", "email", "sheet", "score", "max"}) {
      put_cell(out, T.get(fmt::format("grading.gradebook.{}", h)), delimiter, first);
      first = false;
    }
    put_cell(out, mark_header, delimiter, false);
    put_cell(out, T.get("grading.gradebook.status"), delimiter, false);
  }
  line_end();
  const auto status = [&](std::string_view s) { return T.get(fmt::format("grading.gradebook.status_{}", s)); };
  auto write_row = [&](const Row* r, const RosterEntry* e, std::string_view num) {
    const std::string name = e && !e->name.empty() ? e->name : r ? r->student : std::string();
    const std::string email = e ? e->email : std::string();
    if (moodle) {
      put_cell(out, num, delimiter, true);
      put_cell(out, email, delimiter, false);
      put_cell(out, name, delimiter, false);
      put_cell(out, mark_text(r->mark, false), delimiter, false);
    } else {
      put_cell(out, num, delimiter, true);
      put_cell(out, name, delimiter, false);
      put_cell(out, email, delimiter, false);
      put_cell(out, r ? std::string_view(r->sheet) : std::string_view(), delimiter, false);
      const bool marked = r && r->marked;
      put_cell(out, marked ? mark_text(r->score, comma) : std::string(), delimiter, false);
      put_cell(out, marked ? mark_text(r->max, comma) : std::string(), delimiter, false);
      put_cell(out, marked ? mark_text(r->mark, comma) : std::string(), delimiter, false);
      put_cell(out,
               !r                  ? status("absent")
               : !r->marked        ? status("not_marked")
               : r->to_check > 0   ? status("to_check")
               : roster_ && !e     ? status("not_in_roster")
                                   : status("marked"),
               delimiter, false);
    }
    line_end();
    ++written_;
  };
  // the roster's order when there is one (the order of the school's list), else the answers'
  std::vector<char> row_written(rows_.size(), 0);
  int absent = 0;
  if (roster_) {
    for (const RosterEntry& e : roster_->students) {
      const auto it = kept.find(roster_number_key(e.number));
      if (it == kept.end()) {
        ++absent;
        if (!moodle) write_row(nullptr, &e, e.number);
        continue;
      }
      const Row& r = rows_[it->second];
      row_written[it->second] = 1;
      if (moodle && r.to_check > 0) {
        report_(r.line, T.format("grading.roster.to_check", {{"line", std::to_string(r.line)}, {"who", who(r)}}), false);
        continue;
      }
      write_row(&r, &e, e.number);
    }
  } else {
    for (const auto& [k, i] : kept) row_written[i] = 1;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (!row_written[i]) continue;
      const Row& r = rows_[i];
      if (moodle && r.to_check > 0) {
        report_(r.line, T.format("grading.roster.to_check", {{"line", std::to_string(r.line)}, {"who", who(r)}}), false);
        continue;
      }
      write_row(&r, nullptr, number[i]);
    }
  }
  // the csv lists every row, those left out of the marks included
  if (!moodle)
    for (std::size_t i = 0; i < rows_.size(); ++i)
      if (!row_written[i]) write_row(&rows_[i], entry[i], number[i]);
  if (absent > 0) report_(0, T.format("grading.roster.absent", {{"count", std::to_string(absent)}}), false);
  output::write_file_atomically(path_, out);
}

}  // namespace epure::grading
