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

TextSummary::TextSummary(std::FILE* out, const AnswerKey& key, const FeedbackText& text, MarkScale scale, bool rows)
    : out_(out), key_(key), text_(text), words_(key, text.texts()), scale_(scale), rows_(rows) {}

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
               padded_left(T.get("grading.summary.score"), 21), T.get("grading.summary.wrong"));
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
        std::vector<std::string> why;
        if (m.verdict == Verdict::follow_through) why.push_back(T.get("grading.summary.follow_through"));
        else if (m.verdict == Verdict::unanswered) why.push_back(T.get("grading.summary.blank"));
        else if (m.verdict == Verdict::to_check) why.push_back(words_.flag("to_check"));
        if (!m.mistake.empty()) why.push_back(words_.mistake(m.mistake));
        if (m.note == "swapped_cells") why.push_back(words_.flag("swapped_cells"));
        if (m.verdict == Verdict::right && why.empty()) continue;
        if (!detail.empty()) detail += ' ';
        detail += s.sheet->exercises[e].questions[q].id;
        if (!why.empty()) detail += fmt::format(" ({})", fmt::join(why, ", "));
      }
  }
  for (const auto& f : s.flags)
    if (f.code != "to_check" && f.code != "swapped_cells")
      detail += fmt::format("{}[{}]", detail.empty() ? "" : " ", words_.flag(f.code));
  std::string sc = s.marked() ? fmt::format("{} / {}", score(s.score), score(s.max)) : std::string("—");
  if (s.marked() && scale_.out_of && s.max > 0)
    sc += fmt::format(" = {} / {}", score(scale_.mark(s.score, s.max)), score(*scale_.out_of));
  if (s.marked() && s.to_check > 0) sc += " " + T.format("grading.summary.held", {{"points", score(s.held)}});
  fmt::print(out_, "{:>6}  {}  {}  {}  {}\n", s.line, padded(s.sheet ? std::string_view(s.sheet->id) : s.sheet_text, 14),
             padded(student, 24), padded_left(sc, 21), detail);
}

void TextSummary::finish(const ClassStatistics& stats, const Outcome& outcome) {
  const Texts& T = text_.texts();
  // "1 answer", "3 answers"
  const auto count = [&](int n, std::string_view what) {
    return T.format(fmt::format("grading.summary.{}_{}", what, n == 1 ? "one" : "many"), {{"count", std::to_string(n)}});
  };
  if (rows_ && header_done_) fmt::print(out_, "\n");
  fmt::print(out_, "{}\n",
             T.format(outcome.follow_through ? "grading.summary.run_on" : "grading.summary.run_off",
                      {{"rows", std::to_string(outcome.rows)},
                       {"answers", outcome.answers},
                       {"format", outcome.source.format},
                       {"marked", std::to_string(outcome.marked)},
                       {"key", key_.info.source},
                       {"seed", std::to_string(key_.info.seed)}}));
  if (outcome.corrections_applied > 0)
    fmt::print(out_, "{}\n", T.format("grading.summary.corrections", {{"count", std::to_string(outcome.corrections_applied)}}));
  if (stats.marked() > 0) {
    // in percent of the maximum, so that the class is compared on one scale
    fmt::print(out_, "{}\n",
               T.format("grading.summary.scores", {{"max", score(stats.max_points())},
                                                   {"mean", percent(stats.mean_percent())},
                                                   {"median", percent(stats.median_percent())},
                                                   {"min", percent(stats.min_percent())},
                                                   {"highest", percent(stats.max_percent())}}));
    if (scale_.out_of) {
      const double n = *scale_.out_of;
      fmt::print(out_, "{}\n",
                 T.format("grading.summary.scale", {{"scale", score(n)},
                                                    {"step", text_.points(scale_.step)},
                                                    {"mean", score(scale_.round(stats.mean_percent() / 100 * n))},
                                                    {"median", score(scale_.round(stats.median_percent() / 100 * n))}}));
    }
    if (outcome.to_check > 0) {
      fmt::print(out_, "{}\n",
                 T.format("grading.summary.to_check", {{"answers", count(outcome.to_check, "answers")},
                                                       {"rows", count(outcome.to_check_rows, "sheets")}}));
    }
    const ItemAnalysis items = stats.items();
    // questions: facility and discrimination, three to a line
    fmt::print(out_, "{}", T.get("grading.summary.items"));
    int shown = 0;
    std::size_t id_width = 0;
    for (const auto& q : items.questions) id_width = std::max(id_width, width(q.id));
    for (const auto& q : items.questions) {
      if (q.answers == 0) continue;
      const std::string r = q.discrimination ? text_.numbers().rounded(*q.discrimination, 2) : std::string("—");
      fmt::print(out_, "{}{} {} {}", shown % 3 == 0 ? "\n  " : "   ", padded(q.id, id_width),
                 padded_left(percent(std::round(100 * q.facility)), 6), padded_left(r, 5));
      ++shown;
    }
    fmt::print(out_, "\n");
    if (items.alpha)
      fmt::print(out_, "{}\n", T.format("grading.summary.alpha", {{"alpha", text_.numbers().rounded(*items.alpha, 2)},
                                                                 {"k", std::to_string(items.alpha_items)}}));
    else
      fmt::print(out_, "{}\n", T.get("grading.summary.alpha_none"));
    bool any_harder = false;
    for (const auto& b : items.branches) {
      if (!b.harder) continue;
      any_harder = true;
      const auto& ex = items.exercises[b.exercise];
      fmt::print(out_, "{}\n",
                 T.format("grading.summary.branch_harder",
                          {{"exercise", words_.exercise(ex.n)},
                           {"branch", words_.branch(b.branch)},
                           {"facility", percent(std::round(100 * b.facility))},
                           {"others", percent(std::round(100 * b.others_facility.value_or(0)))},
                           {"n", std::to_string(b.submissions)},
                           {"t", text_.points(std::round(b.t.value_or(0) * 100) / 100)},
                           {"p", text_.points(std::round(b.p.value_or(1) * 10000) / 10000)},
                           {"threshold", text_.points(std::round(kBranchAlpha / b.tested * 10000) / 10000)}}));
    }
    if (!any_harder) fmt::print(out_, "{}\n", T.get("grading.summary.branches_none"));
    if (!items.mistakes.empty()) {
      fmt::print(out_, "{}\n", T.get("grading.summary.mistakes"));
      std::size_t shown_mistakes = 0;
      for (const auto& m : items.mistakes) {
        if (++shown_mistakes > 10) break;
        std::vector<std::string> where;
        for (const auto& [e, count] : m.by_exercise)
          where.push_back(fmt::format("{} × {}", count, words_.exercise(items.exercises[e].n)));
        fmt::print(out_, "  {}\n",
                   T.format("grading.summary.mistake_line", {{"count", padded_left(std::to_string(m.count), 4)},
                                                            {"name", words_.mistake(m.code)},
                                                            {"where", fmt::format("{}", fmt::join(where, ", "))}}));
      }
    }
    fmt::print(out_, "{}\n",
               T.format("grading.summary.follow_through_total", {{"answers", count(items.follow_through, "answers")},
                                                                 {"points", score(items.follow_through_points)}}));
  }
  fmt::print(out_, "{}\n",
             T.format(outcome.errors + outcome.warnings > 0 ? "grading.summary.counts_stderr" : "grading.summary.counts",
                      {{"errors", std::to_string(outcome.errors)}, {"warnings", std::to_string(outcome.warnings)}}));
}

}  // namespace epure::grading
