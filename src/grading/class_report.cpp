#include "grading/class_report.h"

#include <fmt/format.h>

#include <cmath>

#include "grading/class_plots.h"
#include "grading/item_analysis.h"
#include "grading/session.h"
#include "grading/statistics.h"
#include "output/atomic_file.h"
#include "render/layout.h"
#include "render/pdf_document.h"
#include "render/svg_scene.h"
#include "render/svg_writer.h"

namespace epure::grading {

namespace {

std::string escaped(std::string_view s) {
  std::string out;
  render::append_escaped(out, s, true);
  return out;
}

// The page's styles: system fonts, tables that read in print too.
constexpr std::string_view kStyle = R"(body{font-family:"DejaVu Sans",sans-serif;max-width:52em;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}
h1{font-size:1.5em}h2{font-size:1.2em;margin-top:2em;border-bottom:1px solid #ccc}h3{font-size:1.05em}
table{border-collapse:collapse;margin:.6em 0 1.2em;font-size:.9em}th,td{padding:.2em .6em;border-bottom:1px solid #e4e4e4;text-align:left}
td.n{text-align:right;font-variant-numeric:tabular-nums}tr.flag td{color:#b45309;font-weight:bold}
figure{margin:1em 0}figure svg{max-width:100%;height:auto}figcaption{font-size:.9em;color:#444}
.note{background:#fff7e6;border-left:4px solid #d97706;padding:.5em 1em}.method{font-size:.9em;color:#333})";

}  // namespace

ClassReport::ClassReport(std::filesystem::path dir, const AnswerKey& key, const FeedbackText& text, MarkScale scale)
    : dir_(std::move(dir)), key_(key), text_(text), words_(key, text.texts()), scale_(scale) {}

void ClassReport::submission(const Submission& s) {
  Row r;
  r.line = s.line;
  r.sheet = s.sheet ? s.sheet->id : std::string(s.sheet_text);
  r.student = s.student;
  r.marked = s.marked();
  r.score = s.score;
  r.max = s.max;
  r.held = s.held;
  r.mark = s.marked() ? scale_.mark(s.score, s.max) : 0;
  const Texts& T = text_.texts();
  for (std::size_t e = 0; e < s.marks.size(); ++e)
    for (std::size_t q = 0; q < s.marks[e].size(); ++q) {
      const QuestionMark& m = s.marks[e][q];
      if (m.verdict != Verdict::to_check) continue;
      r.to_check.push_back(T.format("grading.flag.to_check_item",
                                    {{"id", s.sheet->exercises[e].questions[q].id},
                                     {"value", T.format("grading.report.quoted", {{"text", std::string(m.given.raw)}})},
                                     {"why", T.get(fmt::format("grading.why.{}", m.given.why))}}));
    }
  for (const auto& f : s.flags) r.flags.push_back(words_.flag(f.code));
  rows_.push_back(std::move(r));
}

void ClassReport::finish(const ClassStatistics& stats, const Outcome& outcome) {
  build(stats, outcome);
  std::filesystem::create_directories(dir_);
  output::write_file_atomically(dir_ / "class-report.html", html_);
  const std::vector<render::LaidOutPage> pages = render::layout_document(doc_);
  render::PdfMetadata metadata;
  metadata.title = doc_.title;
  metadata.subject = doc_.course;
  metadata.creator = "epure";
  metadata.date = render::source_date_epoch();
  output::write_file_atomically(dir_ / "class-report.pdf", render::pages_to_pdf(pages, doc_.sheet_id, metadata));
}

void ClassReport::build(const ClassStatistics& stats, const Outcome& outcome) {
  const Texts& T = text_.texts();
  const ItemAnalysis items = stats.items();
  const auto pct = [&](double share) {
    return T.format("grading.summary.percent", {{"value", text_.points(std::round(100 * share))}});
  };
  const auto num2 = [&](double x) { return text_.numbers().rounded(x, 2); };
  const auto mark_of = [&](double score, double max) {
    std::string s = fmt::format("{} / {}", text_.points(score), text_.points(max));
    if (scale_.out_of) s += fmt::format(" = {} / {}", text_.points(scale_.mark(score, max)), text_.points(*scale_.out_of));
    return s;
  };

  doc_ = render::Document{};
  doc_.title = T.format("grading.report.title", {{"title", key_.info.title}});
  doc_.course = key_.info.title;
  doc_.sheet_id = T.format("grading.report.header_id", {{"seed", std::to_string(key_.info.seed)}});
  doc_.language = T.language();
  doc_.words.yes = T.get("common.yes");
  doc_.words.no = T.get("common.no");
  doc_.words.page = T.get("common.page_word");

  std::string html = fmt::format("<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n<style>{}</style>\n</head>\n<body>\n<h1>{}</h1>\n",
                                 escaped(T.language()), escaped(doc_.title), kStyle, escaped(doc_.title));
  auto para = [&](render::Section& sec, const std::string& text, bool emphasis = false) {
    sec.add(render::Paragraph{rich_escape(text), emphasis});
    html += fmt::format("<p{}>{}</p>\n", emphasis ? " class=\"note\"" : "", escaped(text));
  };
  auto figure = [&](render::Section& sec, render::Scene scene) {
    // the description under the figure, unless a panel already says it
    bool said = false;
    for (const auto& p : scene.panels) said = said || p.caption == scene.description;
    html += fmt::format("<figure>{}{}</figure>\n", render::scene_to_svg(scene, plot_width(scene)),
                        said ? std::string() : fmt::format("<figcaption>{}</figcaption>", escaped(scene.description)));
    const double fraction = plot_width(scene) / kPlotWidth;
    sec.add(render::Figure{std::move(scene), fraction});
  };
  auto heading = [&](render::Section& sec, const std::string& text) {
    sec.add(render::Heading{rich_escape(text), 1});
    html += fmt::format("<h2>{}</h2>\n", escaped(text));
  };

  // the class
  render::Section summary;
  heading(summary, T.get("grading.report.summary"));
  para(summary, T.format("grading.report.counts", {{"rows", std::to_string(outcome.rows)},
                                                    {"marked", std::to_string(stats.marked())},
                                                    {"answers", outcome.answers},
                                                    {"seed", std::to_string(key_.info.seed)}}));
  if (stats.marked() > 0) {
    const double top = scale_.out_of.value_or(stats.max_points());
    para(summary, T.format("grading.report.marks", {{"out_of", text_.points(top)},
                                                     {"mean", text_.points(scale_.round(stats.mean_percent() / 100 * top))},
                                                     {"median", text_.points(scale_.round(stats.median_percent() / 100 * top))},
                                                     {"min", text_.points(scale_.round(stats.min_percent() / 100 * top))},
                                                     {"max", text_.points(scale_.round(stats.max_percent() / 100 * top))},
                                                     {"step", text_.points(scale_.step)}}));
    if (outcome.to_check > 0)
      para(summary, T.format("grading.report.to_check", {{"answers", std::to_string(outcome.to_check)},
                                                          {"rows", std::to_string(outcome.to_check_rows)}}),
           true);
    para(summary, items.alpha ? T.format("grading.summary.alpha", {{"alpha", num2(*items.alpha)}, {"k", std::to_string(items.alpha_items)}})
                              : T.get("grading.summary.alpha_none"));
    para(summary, T.format("grading.report.follow_through", {{"answers", std::to_string(items.follow_through)},
                                                              {"points", text_.points(items.follow_through_points)}}));
    figure(summary, marks_plot(stats, scale_, text_));
  }
  doc_.sections.push_back(std::move(summary));

  // each exercise
  for (std::size_t e = 0; e < items.exercises.size(); ++e) {
    const ExerciseItem& ex = items.exercises[e];
    render::Section sec;
    heading(sec, T.format("common.exercise_heading", {{"label", words_.exercise(ex.n)}, {"title", words_.title(ex.kind)}}));
    para(sec, T.format("grading.report.exercise", {{"facility", pct(ex.facility)},
                                                    {"points", text_.points(ex.max_points)},
                                                    {"follow", std::to_string(ex.follow_through)},
                                                    {"follow_points", text_.points(ex.follow_through_points)}}));
    for (const auto& b : items.branches)
      if (b.exercise == e && b.harder)
        para(sec,
             T.format("grading.summary.branch_harder",
                      {{"exercise", words_.exercise(ex.n)},
                       {"branch", words_.branch(b.branch)},
                       {"facility", pct(b.facility)},
                       {"others", pct(b.others_facility.value_or(0))},
                       {"n", std::to_string(b.submissions)},
                       {"t", num2(b.t.value_or(0))},
                       {"p", text_.numbers().rounded(b.p.value_or(1), 4)},
                       {"threshold", text_.numbers().rounded(kBranchAlpha / b.tested, 4)}}),
             true);
    figure(sec, questions_plot(items, e, text_));
    if (auto scene = branches_plot(items, e, words_, text_)) figure(sec, std::move(*scene));
    // the full tables, in the page only
    html += fmt::format("<table><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>\n",
                        escaped(T.get("grading.report.col_question")), escaped(T.get("grading.report.col_answers")),
                        escaped(T.get("grading.report.col_facility")), escaped(T.get("grading.report.col_discrimination")),
                        escaped(T.get("grading.report.col_follow")), escaped(T.get("grading.report.col_to_check")));
    for (const auto& q : items.questions) {
      if (q.exercise != ex.index) continue;
      html += fmt::format(
          "<tr{}><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n",
          q.discrimination && *q.discrimination < 0.2 ? " class=\"flag\"" : "", escaped(q.id), q.answers, escaped(pct(q.facility)),
          escaped(q.discrimination ? num2(*q.discrimination) : "—"), q.follow_through, q.to_check);
    }
    html += "</table>\n";
    html += fmt::format("<table><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>\n",
                        escaped(T.get("grading.report.col_branch")), escaped(T.get("grading.report.col_sheets")),
                        escaped(T.get("grading.report.col_facility")), escaped(T.get("grading.report.col_others")),
                        escaped(T.get("grading.report.col_welch")), escaped(T.get("grading.report.col_harder")));
    for (const auto& b : items.branches) {
      if (b.exercise != e) continue;
      const std::string welch = b.p ? fmt::format("t = {}, ν = {}, p = {}", num2(*b.t), text_.numbers().rounded(*b.df, 1),
                                                  text_.numbers().rounded(*b.p, 4))
                                    : std::string("—");
      html += fmt::format(
          "<tr{}><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td><td>{}</td></tr>\n",
          b.harder ? " class=\"flag\"" : "", escaped(words_.branch(b.branch)), b.submissions, escaped(pct(b.facility)),
          escaped(b.others_facility ? pct(*b.others_facility) : "—"), escaped(welch),
          escaped(b.harder ? T.get("common.yes") : b.p ? T.get("common.no") : "—"));
    }
    html += "</table>\n";
    if (!ex.mistakes.empty()) {
      html += fmt::format("<table><tr><th>{}</th><th>{}</th></tr>\n", escaped(T.get("grading.report.col_mistake")),
                          escaped(T.get("grading.report.col_count")));
      std::vector<std::pair<std::string_view, int>> ms(ex.mistakes.begin(), ex.mistakes.end());
      std::stable_sort(ms.begin(), ms.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
      for (const auto& [code, count] : ms)
        html += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td></tr>\n", escaped(words_.mistake(code)), count);
      html += "</table>\n";
    }
    doc_.sections.push_back(std::move(sec));
  }

  // what is still to check
  bool any_to_check = false;
  for (const Row& r : rows_) any_to_check = any_to_check || !r.to_check.empty();
  if (any_to_check) {
    render::Section sec;
    heading(sec, T.get("grading.report.to_check_heading"));
    para(sec, T.get("grading.report.to_check_how"));
    html += "<table>\n";
    for (const Row& r : rows_) {
      if (r.to_check.empty()) continue;
      const std::string list = fmt::format("{}", fmt::join(r.to_check, " ; "));
      sec.add(render::AnswerLine{r.sheet, rich_escape(r.student), rich_escape(list)});
      html += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", escaped(r.sheet), escaped(r.student), escaped(list));
    }
    html += "</table>\n";
    doc_.sections.push_back(std::move(sec));
  }

  // every student's mark
  {
    render::Section sec;
    heading(sec, T.get("grading.report.marks_heading"));
    html += fmt::format("<table><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>\n", escaped(T.get("grading.report.line")),
                        escaped(T.get("grading.report.sheet")), escaped(T.get("grading.report.student")),
                        escaped(T.get("grading.report.score")));
    for (const Row& r : rows_) {
      std::string m = r.marked ? mark_of(r.score, r.max) : T.get("grading.gradebook.status_not_marked");
      if (r.held > 0) m += " " + T.format("grading.summary.held", {{"points", text_.points(r.held)}});
      if (!r.flags.empty()) m += fmt::format(" — {}", fmt::join(r.flags, ", "));
      sec.add(render::AnswerLine{r.sheet, rich_escape(r.student), rich_escape(m)});
      html += fmt::format("<tr><td class=\"n\">{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", r.line, escaped(r.sheet),
                          escaped(r.student), escaped(m));
    }
    html += "</table>\n";
    doc_.sections.push_back(std::move(sec));
  }

  // how the figures are computed
  {
    render::Section sec;
    heading(sec, T.get("grading.report.method_heading"));
    html += "<div class=\"method\">\n";
    for (const char* k : {"method_facility", "method_discrimination", "method_alpha", "method_branches", "method_marks"})
      para(sec, T.format(fmt::format("grading.report.{}", k), {{"step", text_.points(scale_.step)}}));
    html += "</div>\n";
    doc_.sections.push_back(std::move(sec));
  }
  html += "</body>\n</html>\n";
  html_ = std::move(html);
}

}  // namespace epure::grading
