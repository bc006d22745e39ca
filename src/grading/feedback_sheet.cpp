#include "grading/feedback_sheet.h"

#include <fmt/format.h>

#include <cmath>

#include "grading/histogram.h"
#include "grading/kind_grader.h"
#include "output/atomic_file.h"
#include "render/layout.h"
#include "render/pdf_document.h"
#include "render/svg_page.h"

namespace epure::grading {

namespace {

std::optional<double> given_number(const ExerciseKey& ex, const ExerciseMarks& marks, const std::string& field) {
  const int i = ex.find(field);
  if (i < 0 || !marks[static_cast<std::size_t>(i)].given.readable()) return std::nullopt;
  return marks[static_cast<std::size_t>(i)].given.number;
}

// Whether any coordinate of a group was not given full credit.
bool group_wrong(const ExerciseKey& ex, const ExerciseMarks& marks, std::string_view group) {
  for (char axis : {'x', 'y'}) {
    const int i = ex.find(fmt::format("{}.{}", group, axis));
    if (i < 0) return false;
    const auto v = marks[static_cast<std::size_t>(i)].verdict;
    if (v != Verdict::right) return true;
  }
  return false;
}

}  // namespace

bool make_room(render::Panel& panel, render::P2 p) {
  render::Box& v = panel.view;
  const double w = v.width(), h = v.height();
  if (p.x < v.x_min - 2 * w || p.x > v.x_max + 2 * w || p.y < v.y_min - 2 * h || p.y > v.y_max + 2 * h) return false;
  v.x_min = std::min(v.x_min, std::floor(p.x - 0.5));
  v.x_max = std::max(v.x_max, std::ceil(p.x + 0.5));
  v.y_min = std::min(v.y_min, std::floor(p.y - 0.5));
  v.y_max = std::max(v.y_max, std::ceil(p.y + 0.5));
  return true;
}

void overlay_answers(render::Scene& scene, const ExerciseKey& ex, const ExerciseMarks& marks, const FeedbackText& text) {
  if (!ex.grader) return;
  const std::string& yours = text.texts().get("grading.sheet.yours_label");
  for (const DrawnField& d : ex.grader->drawn()) {
    if (d.panel >= static_cast<int>(scene.panels.size())) continue;
    if (!group_wrong(ex, marks, d.group)) continue;
    const std::string g(d.group);
    const auto x = given_number(ex, marks, g + ".x"), y = given_number(ex, marks, g + ".y");
    if (!x || !y) continue;
    render::Panel& panel = scene.panels[static_cast<std::size_t>(d.panel)];
    // named as the key's figure names it: "N⃗ (you)", not "N (you)" beside the key's N⃗
    const std::string label = fmt::format("{} ({})", d.name.empty() ? d.group : d.name, yours);
    if (d.anchor.empty()) {
      const render::P2 at{*x, *y};
      if (!make_room(panel, at)) continue;
      panel.add(render::PointMark{at, render::Role::given, render::Label{label, at, render::Side::auto_, render::Role::given}});
      continue;
    }
    // a vector: drawn from where the key puts its anchor point
    const std::string a(d.anchor);
    const int ax = ex.find(a + ".x"), ay = ex.find(a + ".y");
    if (ax < 0 || ay < 0) continue;
    const render::P2 from{ex.questions[static_cast<std::size_t>(ax)].number, ex.questions[static_cast<std::size_t>(ay)].number};
    const render::P2 to{from.x + *x, from.y + *y};
    if (!make_room(panel, to)) continue;
    panel.add(render::Arrow{from, to, render::Role::given});
    panel.add(render::Label{label, to, render::Side::auto_, render::Role::given});
  }
}

render::Document feedback_document(const Submission& s, const AnswerKey& key, const FeedbackText& text,
                                   KeyDiagrams* diagrams, const MarkScale& scale, const ScannedCrops* crops) {
  const Texts& T = text.texts();
  render::Document doc;
  doc.title = T.format("grading.sheet.title", {{"title", key.info.title}});
  doc.sheet_id = s.sheet ? s.sheet->id : std::string(s.sheet_text);
  doc.language = T.language().empty() ? std::string("en") : T.language();
  doc.words.yes = T.get("common.yes");
  doc.words.no = T.get("common.no");
  doc.words.page = T.get("common.page_word");
  std::string note = rich_escape(s.student);
  if (s.marked()) {
    if (!note.empty()) note += " — ";
    if (scale.out_of && s.max > 0)
      note += T.format("grading.sheet.score_scaled",
                       {{"score", text.points(s.score)},
                        {"max", text.points(s.max)},
                        {"mark", text.points(scale.mark(s.score, s.max))},
                        {"scale", text.points(*scale.out_of)}});
    else
      note += T.format("grading.sheet.score", {{"score", text.points(s.score)}, {"max", text.points(s.max)}});
    if (s.to_check > 0) note += " " + T.format("grading.sheet.held", {{"points", text.points(s.held)}});
  }
  doc.header_note = note;

  render::Section intro;
  if (!s.marked()) {
    std::string why;
    for (const auto& f : s.flags) why += (why.empty() ? "" : "; ") + f.message;
    intro.add(render::Paragraph{T.format("grading.sheet.not_marked", {{"why", rich_escape(why)}}), true});
    doc.sections.push_back(std::move(intro));
    return doc;
  }
  intro.add(render::Paragraph{T.get("grading.sheet.legend")});
  std::string flags;
  for (const auto& f : s.flags)
    // (answers to check and cells swapped are said at each answer, in the student's words)
    if (f.code == "duplicate" || f.code == "ragged" || f.code == "not_asked") flags += (flags.empty() ? "" : "; ") + f.message;
  if (!flags.empty()) intro.add(render::Paragraph{T.format("grading.sheet.flags", {{"flags", rich_escape(flags)}}), true});
  doc.sections.push_back(std::move(intro));

  for (std::size_t e = 0; e < s.marks.size(); ++e) {
    const ExerciseKey& ex = s.sheet->exercises[e];
    const ExerciseMarks& marks = s.marks[e];
    render::Section section;
    const std::string title_key = ex.kind + ".title";
    const std::string title = T.has(title_key) ? T.get(title_key) : ex.kind;
    // The sheet's own heading ("Preamble", "Exercise 1"), from the spec the key carries.
    const WorksheetSpec* spec = diagrams ? diagrams->spec() : nullptr;
    const std::string label = spec && e < spec->exercises.size() && spec->exercises[e].kind == ex.kind
                                  ? exercise_label(*spec, e, T)
                                  : T.format("common.exercise_label", {{"n", ex.number}});
    section.add(render::Heading{T.format("common.exercise_heading", {{"label", label}, {"title", title}}), 1});
    if (diagrams) {
      // As large as the key draws it: the student's wrong points are read against the key's.
      if (auto figure = diagrams->figure(*s.sheet, e)) {
        overlay_answers(figure->scene, ex, marks, text);
        section.add(std::move(*figure));
      }
    }
    for (std::size_t q = 0; q < marks.size(); ++q) {
      const QuestionKey& qk = ex.questions[q];
      const QuestionMark& m = marks[q];
      const std::string prompt_key = fmt::format("{}.q.{}", ex.kind, qk.field);
      const std::string prompt = T.has(prompt_key) ? T.get(prompt_key) : qk.field;
      const bool right = m.verdict == Verdict::right;
      const char* sign = right                                  ? "\u2713"
                         : m.verdict == Verdict::follow_through ? "\u2197"
                         : m.verdict == Verdict::to_check       ? "?"
                                                                : "\u2717";
      std::string answer = fmt::format("{} {}", sign,
                                       m.given.raw.empty() ? std::string("—") : rich_escape(text.given_shown(qk, m)));
      answer += fmt::format("  ({}/{})", text.points(m.points), text.points(qk.points));
      if (!right) answer += fmt::format(" — {} {}", T.get("grading.sheet.expected"), text.expected(qk));
      if (const std::string why = text.explanation(qk, m); !why.empty()) answer += (right ? " — " : ". ") + why;
      render::AnswerLine line{qk.id, prompt, answer};
      if (crops && s.sheet) line.shown = crops->crop(s.sheet->id, qk.id);
      section.add(std::move(line));
    }
    doc.sections.push_back(std::move(section));
  }
  return doc;
}

FeedbackSheets::FeedbackSheets(std::filesystem::path dir, const AnswerKey& key, const FeedbackText& text, MarkScale scale,
                               ScannedCrops crops)
    : dir_(std::move(dir)), key_(key), text_(text), scale_(scale), diagrams_(key, text.texts().language()), crops_(std::move(crops)),
      pdf_date_(render::source_date_epoch()) {
  std::filesystem::create_directories(dir_);
}

void FeedbackSheets::submission(const Submission& s) {
  std::string name;
  if (!s.marked()) name = fmt::format("line{}", s.line);
  else if (s.flagged("duplicate")) name = fmt::format("{}-line{}", s.sheet->id, s.line);
  else name = s.sheet->id;
  const render::Document doc = feedback_document(s, key_, text_, &diagrams_, scale_, crops_.any() ? &crops_ : nullptr);
  // Laid out once, drawn twice: the SVG for a screen, the PDF to print or hand back.
  const std::vector<render::LaidOutPage> pages = render::layout_document(doc);
  output::write_file_atomically(dir_ / (name + ".svg"), render::pages_to_svg(pages, doc));
  render::PdfMetadata metadata;
  metadata.title = doc.title;
  metadata.subject = doc.course;
  metadata.creator = "epure";
  metadata.date = pdf_date_;
  output::write_file_atomically(dir_ / (name + ".pdf"), render::pages_to_pdf(pages, doc.sheet_id, metadata));
  ++written_;
}

void FeedbackSheets::finish(const ClassStatistics& stats, const Outcome&) {
  output::write_file_atomically(dir_ / "class.svg", histogram_svg(stats, text_));
}

}  // namespace epure::grading
