#include "grading/summary_text.h"

#include <fmt/format.h>

#include <cmath>

#include "grading/session.h"
#include "grading/statistics.h"

namespace epure::grading {

namespace {

// Display width of UTF-8 text (code points), for aligning names with accents.
std::size_t width(std::string_view s) {
  std::size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xc0) != 0x80;
  return n;
}

std::string padded(std::string_view s, std::size_t w) {
  std::string out(s);
  for (std::size_t n = width(s); n < w; ++n) out.push_back(' ');
  return out;
}

std::string score(double x) { return fmt::format("{}", std::round(x * 100) / 100); }

}  // namespace

TextSummary::TextSummary(std::FILE* out, const AnswerKey& key, const FeedbackText& text, bool rows)
    : out_(out), key_(key), text_(text), rows_(rows) {}

void TextSummary::submission(const Submission& s) {
  if (!rows_) return;
  if (!header_done_) {
    fmt::print(out_, "{:>6}  {:<14}  {}  {:>13}  {}\n", "line", "sheet", padded("student", 24), "score", "wrong (mistake)");
    header_done_ = true;
  }
  std::string student(s.student);
  if (width(student) > 24) {
    std::size_t cut = 0, n = 0;
    while (cut < student.size() && n < 23) {
      ++cut;
      while (cut < student.size() && (static_cast<unsigned char>(student[cut]) & 0xc0) == 0x80) ++cut;
      ++n;
    }
    student = student.substr(0, cut) + "…";
  }
  std::string detail;
  if (s.marked()) {
    for (std::size_t e = 0; e < s.marks.size(); ++e)
      for (std::size_t q = 0; q < s.marks[e].size(); ++q) {
        const auto& m = s.marks[e][q];
        if (m.verdict == Verdict::right) continue;
        if (!detail.empty()) detail += ' ';
        detail += s.sheet->exercises[e].questions[q].id;
        if (m.verdict == Verdict::follow_through) detail += "(ft";
        else if (m.verdict == Verdict::unanswered) detail += "(blank";
        else if (m.verdict == Verdict::unreadable) detail += "(unreadable";
        else detail += "(";
        if (!m.mistake.empty()) detail += fmt::format("{}{}", detail.back() == '(' ? "" : " ", m.mistake);
        if (detail.back() == '(') detail.pop_back();
        else detail += ')';
      }
  }
  for (const auto& f : s.flags)
    if (f.code != "unreadable") detail += fmt::format("{}[{}]", detail.empty() ? "" : " ", f.code);
  const std::string sc = s.marked() ? fmt::format("{} / {}", score(s.score), score(s.max)) : std::string("—");
  fmt::print(out_, "{:>6}  {:<14}  {}  {:>13}  {}\n", s.line,
             s.sheet ? std::string_view(s.sheet->id) : s.sheet_text, padded(student, 24), sc, detail);
}

void TextSummary::finish(const ClassStatistics& stats, const Outcome& outcome) {
  if (rows_ && header_done_) fmt::print(out_, "\n");
  fmt::print(out_, "{} rows read from {} ({}), {} marked against {} (seed {}); follow-through {}\n", outcome.rows,
             outcome.answers, outcome.source.format, outcome.marked, key_.info.source, key_.info.seed,
             outcome.follow_through ? "on" : "off");
  if (stats.marked() > 0) {
    fmt::print(out_, "scores out of {}: mean {}, median {}, lowest {}, highest {}\n", score(stats.max_points()),
               score(stats.mean()), score(stats.median()), score(stats.min()), score(stats.max()));
    std::string rates;
    int shown = 0;
    for (const auto& q : stats.questions()) {
      if (q.asked == 0) continue;
      rates += fmt::format("{}{} {:.0f}%", shown % 8 == 0 ? "\n  " : "   ", q.id, 100 * q.rate());
      ++shown;
    }
    fmt::print(out_, "success rate per question:{}\n", rates);
    const auto top = stats.mistakes(8);
    if (!top.empty()) {
      fmt::print(out_, "most frequent mistakes:\n");
      for (const auto& m : top) fmt::print(out_, "  {:>4} × {} on {}\n", m.count, m.code, m.question);
    }
  }
  fmt::print(out_, "{} error{}, {} warning{}{}\n", outcome.errors, outcome.errors == 1 ? "" : "s", outcome.warnings,
             outcome.warnings == 1 ? "" : "s", outcome.errors + outcome.warnings > 0 ? " (on stderr)" : "");
}

}  // namespace epure::grading
