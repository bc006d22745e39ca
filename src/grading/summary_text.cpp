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

std::string padded_left(std::string_view s, std::size_t w) {
  std::string out;
  for (std::size_t n = width(s); n < w; ++n) out.push_back(' ');
  return out + std::string(s);
}

}  // namespace

TextSummary::TextSummary(std::FILE* out, const AnswerKey& key, const FeedbackText& text, bool rows)
    : out_(out), key_(key), text_(text), rows_(rows) {}

std::string TextSummary::score(double x) const { return text_.points(std::round(x * 100) / 100); }

std::string TextSummary::percent(double x) const {
  return text_.texts().format("grading.summary.percent", {{"value", text_.points(std::round(x * 10) / 10)}});
}

void TextSummary::submission(const Submission& s) {
  if (!rows_) return;
  const Texts& T = text_.texts();
  if (!header_done_) {
    fmt::print(out_, "{}  {}  {}  {}  {}\n", padded_left(T.get("grading.summary.line"), 6),
               padded(T.get("grading.summary.sheet"), 14), padded(T.get("grading.summary.student"), 24),
               padded_left(T.get("grading.summary.score"), 13), T.get("grading.summary.wrong"));
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
        detail += '(';
        if (m.verdict == Verdict::follow_through) detail += T.get("grading.summary.follow_through");
        else if (m.verdict == Verdict::unanswered) detail += T.get("grading.summary.blank");
        else if (m.verdict == Verdict::unreadable) detail += T.get("grading.summary.unreadable");
        if (!m.mistake.empty()) detail += fmt::format("{}{}", detail.back() == '(' ? "" : " ", m.mistake);
        if (detail.back() == '(') detail.pop_back();
        else detail += ')';
      }
  }
  for (const auto& f : s.flags)
    if (f.code != "unreadable") detail += fmt::format("{}[{}]", detail.empty() ? "" : " ", f.code);
  std::string sc = s.marked() ? fmt::format("{} / {}", score(s.score), score(s.max)) : std::string("—");
  if (s.marked() && key_.info.scale && s.max > 0)
    sc += fmt::format(" = {} / {}", score(s.score / s.max * *key_.info.scale), score(*key_.info.scale));
  fmt::print(out_, "{:>6}  {}  {}  {}  {}\n", s.line, padded(s.sheet ? std::string_view(s.sheet->id) : s.sheet_text, 14),
             padded(student, 24), padded_left(sc, 13), detail);
}

void TextSummary::finish(const ClassStatistics& stats, const Outcome& outcome) {
  const Texts& T = text_.texts();
  if (rows_ && header_done_) fmt::print(out_, "\n");
  fmt::print(out_, "{}\n",
             T.format(outcome.follow_through ? "grading.summary.run_on" : "grading.summary.run_off",
                      {{"rows", std::to_string(outcome.rows)},
                       {"answers", outcome.answers},
                       {"format", outcome.source.format},
                       {"marked", std::to_string(outcome.marked)},
                       {"key", key_.info.source},
                       {"seed", std::to_string(key_.info.seed)}}));
  if (stats.marked() > 0) {
    // in percent of the maximum, so that the class is compared on one scale
    fmt::print(out_, "{}\n",
               T.format("grading.summary.scores", {{"max", score(stats.max_points())},
                                                   {"mean", percent(stats.mean_percent())},
                                                   {"median", percent(stats.median_percent())},
                                                   {"min", percent(stats.min_percent())},
                                                   {"highest", percent(stats.max_percent())}}));
    if (key_.info.scale) {
      const double scale = *key_.info.scale;
      fmt::print(out_, "{}\n",
                 T.format("grading.summary.scale", {{"scale", score(scale)},
                                                    {"mean", score(stats.mean_percent() / 100 * scale)},
                                                    {"median", score(stats.median_percent() / 100 * scale)}}));
    }
    std::string rates;
    int shown = 0;
    for (const auto& q : stats.questions()) {
      if (q.asked == 0) continue;
      rates += fmt::format("{}{} {}", shown % 8 == 0 ? "\n  " : "   ", q.id, percent(std::round(100 * q.rate())));
      ++shown;
    }
    fmt::print(out_, "{}{}\n", T.get("grading.summary.rates"), rates);
    const auto top = stats.mistakes(8);
    if (!top.empty()) {
      fmt::print(out_, "{}\n", T.get("grading.summary.mistakes"));
      for (const auto& m : top)
        fmt::print(out_, "  {}\n",
                   T.format("grading.summary.mistake_line",
                            {{"count", padded_left(std::to_string(m.count), 4)}, {"code", std::string(m.code)}, {"question", m.question}}));
    }
  }
  fmt::print(out_, "{}\n",
             T.format(outcome.errors + outcome.warnings > 0 ? "grading.summary.counts_stderr" : "grading.summary.counts",
                      {{"errors", std::to_string(outcome.errors)}, {"warnings", std::to_string(outcome.warnings)}}));
}

}  // namespace epure::grading
