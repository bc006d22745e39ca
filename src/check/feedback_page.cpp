#include "check/feedback_page.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "check/judge.h"
#include "check/report_json.h"
#include "exercises/exercise.h"
#include "exercises/kinds/space_common.h"
#include "exercises/texts.h"
#include "grading/feedback_sheet.h"
#include "grading/feedback_text.h"
#include "output/atomic_file.h"
#include "render/layout.h"
#include "render/pdf_document.h"
#include "render/svg_scene.h"
#include "render/svg_writer.h"
#include "render/text.h"

namespace epure::check {

namespace {

constexpr std::size_t kDrawnPerFunction = 3;
constexpr double kFigureWidth = 460;  // points, in the HTML

std::string number(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{}", x);
}

std::string values_text(const std::vector<NamedValue>& values) {
  std::string out;
  for (const auto& v : values) {
    if (!out.empty()) out += ", ";
    out += v.name + " = ";
    if (v.values.size() == 1) {
      out += number(v.values[0]);
      continue;
    }
    out += "(";
    for (std::size_t i = 0; i < v.values.size(); ++i) out += (i ? ", " : "") + number(v.values[i]);
    out += ")";
  }
  return out;
}

std::string outcome_text(Fn fn, const std::optional<Outcome>& o, const Texts& T) {
  if (!o) return "—";
  if (info(fn).returns_bool && !o->hit) return T.get("check.page.no_hit");
  std::string out = values_text(named_outputs(fn, *o));
  for (std::size_t i = 0; i < static_cast<std::size_t>(2 * info(fn).dimension); ++i)
    if (std::isnan(o->out[i])) return out + " (" + T.get("check.page.not_set") + ")";
  return out;
}

// The case as the exercise kind's solve input (the canonical circle is the circle of centre O
// and radius 1; an ellipse's and a rectangle's angle is in degrees, as the function's).
nlohmann::json instance_of(Fn fn, const Inputs& in) {
  using nlohmann::json;
  auto pair = [&](int i) { return json::array({in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1]}); };
  auto triple = [&](int i) {
    return json::array({in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1], in[static_cast<std::size_t>(i) + 2]});
  };
  json j{{"kind", std::string(info(fn).kind)}};
  switch (fn) {
    case Fn::projection: j["A"] = pair(0), j["B"] = pair(2), j["C"] = pair(4); break;
    case Fn::segments: j["A"] = pair(0), j["B"] = pair(2), j["C"] = pair(4), j["D"] = pair(6); break;
    case Fn::circle: j["A"] = pair(0), j["u"] = pair(2), j["C"] = pair(4), j["r"] = in[6]; break;
    case Fn::circle_canonical: j["A"] = pair(0), j["u"] = pair(2), j["C"] = json::array({0, 0}), j["r"] = 1; break;
    case Fn::square_canonical: j["A"] = pair(0), j["u"] = pair(2); break;
    case Fn::ellipse: j["A"] = pair(0), j["u"] = pair(2), j["C"] = pair(4), j["radii"] = pair(6), j["angle"] = in[8]; break;
    case Fn::rectangle: j["A"] = pair(0), j["u"] = pair(2), j["C"] = pair(4), j["half"] = pair(6), j["angle"] = in[8]; break;
    case Fn::sphere: j["A"] = triple(0), j["u"] = triple(3), j["C"] = triple(6), j["r"] = in[9]; break;
    case Fn::cube_canonical: j["A"] = triple(0), j["u"] = triple(3); break;
  }
  return j;
}

std::string label_of(Fn fn) { return fn == Fn::projection ? "P" : fn == Fn::segments ? "I" : "J"; }

// The student's point (and normal) on the key's world panel.
void overlay(render::Scene& scene, Fn fn, const Outcome& got, const Texts& T) {
  if (scene.panels.empty()) return;
  render::Panel& panel = scene.panels.front();
  const FunctionInfo& f = info(fn);
  const std::string label = fmt::format("{} ({})", label_of(fn), T.get("check.page.figure_yours"));
  render::P2 J, tip;
  if (f.dimension == 3) {
    const render::Camera cam = kinds::space::camera();
    J = cam.project({got.out[0], got.out[1], got.out[2]});
    tip = cam.project({got.out[0] + got.out[3], got.out[1] + got.out[4], got.out[2] + got.out[5]});
  } else {
    J = {got.out[0], got.out[1]};
    tip = {got.out[0] + got.out[2], got.out[1] + got.out[3]};
  }
  if (!std::isfinite(J.x) || !std::isfinite(J.y) || !grading::make_room(panel, J)) return;
  panel.add(render::PointMark{J, render::Role::given, render::Label{label, J, render::Side::auto_, render::Role::given}});
  if (f.has_normal && std::isfinite(tip.x) && std::isfinite(tip.y) && grading::make_room(panel, tip))
    panel.add(render::Arrow{J, tip, render::Role::given});
}

std::string category_text(Category c, const Texts& T) { return T.get("check.category." + std::string(category_name(c))); }

std::string verdict_text(Verdict v, const Texts& T) { return T.get("check.verdict." + std::string(verdict_name(v))); }

// The failing cases worth a figure: the first of each category, the student's sheet first.
std::vector<const FailedCase*> drawn_cases(const FunctionReport& r) {
  std::vector<const FailedCase*> out;
  std::vector<Category> seen;
  std::vector<const FailedCase*> order;
  for (const auto& c : r.failures)
    if (c.category == Category::sheet) order.push_back(&c);
  for (const auto& c : r.failures)
    if (c.category != Category::sheet) order.push_back(&c);
  for (const FailedCase* c : order) {
    if (out.size() >= kDrawnPerFunction) break;
    if (std::find(seen.begin(), seen.end(), c->category) != seen.end()) continue;
    seen.push_back(c->category);
    out.push_back(c);
  }
  return out;
}

// One function's part of the page, as blocks the PDF lays out and the HTML writes.
struct CaseView {
  std::string data, expected, got;
  std::optional<render::Scene> figure;
  std::string not_drawn;
  Category category;
};
struct FunctionView {
  std::string heading;
  std::vector<std::string> paragraphs;  // RichText
  std::vector<CaseView> cases;
};

FunctionView function_view(const FunctionReport& r, const std::string& language, const Texts& T) {
  FunctionView v;
  v.heading = fmt::format("{} — {} ({}/{})", info(r.fn).name, verdict_text(r.verdict, T), r.passed, r.cases);
  for (Bug b : r.bugs) v.paragraphs.push_back(T.get("check.bug." + std::string(bug_code(b))));
  // why a run stopped (not why a file did not build: the page says that above)
  if (!r.reason.empty() && r.stopped_running()) {
    std::string why = r.reason;
    if (why.back() != '?' && why.back() != '.') why += '.';
    v.paragraphs.push_back(T.format("check.page.stopped", {{"why", grading::rich_escape(why)}}));
  }
  if (!r.failed_by_category.empty() && r.verdict != Verdict::compile_error && r.verdict != Verdict::refused) {
    std::string list;
    for (const auto& [c, n] : r.failed_by_category) list += (list.empty() ? "" : ", ") + fmt::format("{} ({})", category_text(c, T), n);
    v.paragraphs.push_back(T.format("check.page.by_category", {{"list", list}}));
  }
  if (r.output_bytes > 0) {
    std::string shown = r.output.substr(0, 300);
    if (r.output_bytes > shown.size()) shown += "…";
    v.paragraphs.push_back(T.format("check.page.printed", {{"output", grading::rich_escape(shown)}}));
  }
  for (const FailedCase* c : drawn_cases(r)) {
    CaseView cv;
    cv.category = c->category;
    const Case k{r.fn, c->category, c->in};
    cv.data = values_text(named_inputs(k));
    cv.expected = outcome_text(r.fn, c->expected, T);
    cv.got = outcome_text(r.fn, c->got, T);
    cv.figure = case_figure(r.fn, *c, language, cv.not_drawn);
    v.cases.push_back(std::move(cv));
  }
  return v;
}

std::string header_line(const FileReport& file, const Texts& T) {
  std::string s = fmt::format("{} {} — {} {}", T.get("check.page.student"), file.student, T.get("check.page.file"), file.name);
  if (!file.sheet.empty()) s += fmt::format(" — {} {}", T.get("check.page.sheet"), file.sheet);
  return s;
}

std::string legend(const Texts& T) {
  std::string categories;
  for (Category c : {Category::near_parallel, Category::tangent, Category::on_boundary, Category::inside, Category::corner,
                     Category::huge, Category::non_unit})
    categories += (categories.empty() ? "" : ", ") + category_text(c, T);
  return T.format("check.page.legend", {{"categories", categories}, {"tolerance", "10^{−6}"}});
}

// ---- HTML ------------------------------------------------------------------------------------
void html_text(std::string& out, std::string_view s) { render::append_escaped(out, s, false); }

void html_rich(std::string& out, std::string_view rich) {
  for (const render::TextRun& run : render::parse_rich_text(rich)) {
    const char* tag = run.shift == render::Shift::sub ? "sub" : run.shift == render::Shift::super ? "sup" : nullptr;
    if (tag) out += fmt::format("<{}>", tag);
    html_text(out, run.text);
    if (tag) out += fmt::format("</{}>", tag);
  }
}

}  // namespace

std::optional<render::Scene> case_figure(Fn fn, const FailedCase& c, const std::string& language, std::string& why_not) {
  const Case k{fn, c.category, c.in};
  const double S = data_scale(k);
  if (!(S >= 1.0 / 64 && S <= 1000)) {
    why_not = fmt::format("a figure at the scale {:.0e}", S);
    return std::nullopt;
  }
  const ExerciseKind* kind = find_kind(info(fn).kind);
  if (!kind) {
    why_not = "no figure for this exercise";
    return std::nullopt;
  }
  try {
    ExerciseSpec spec;
    spec.kind = std::string(info(fn).kind);
    const Texts& texts = Texts::builtin(language);
    ExerciseContext ctx{1, spec, texts, NumberStyle::for_language(language), 2, ""};
    ctx.sheet = false;
    ctx.tolerances = false;
    ExerciseInstance key = kind->key_of(instance_of(fn, c.in), ctx);
    for (auto& block : key.key.blocks)
      if (auto* figure = std::get_if<render::Figure>(&block)) {
        render::Scene scene = std::move(figure->scene);
        if (c.got && (!info(fn).returns_bool || c.got->hit)) overlay(scene, fn, *c.got, texts);
        return scene;
      }
    why_not = "the key has no figure";
  } catch (const std::exception& e) {
    why_not = e.what();
  }
  return std::nullopt;
}

render::Document feedback_document(const FileReport& file, const CheckOptions& options) {
  const Texts& T = Texts::builtin(options.language);
  render::Document doc;
  doc.title = T.get("check.page.title");
  doc.sheet_id = file.sheet.empty() ? file.name : file.sheet;
  doc.language = options.language;
  doc.words.page = T.get("common.page_word");
  doc.header_note = grading::rich_escape(header_line(file, T)) +
                    fmt::format(" — {} {}", T.get("check.page.total"), fmt::format("{:.2f}", file.total));
  render::Section intro;
  intro.add(render::Paragraph{legend(T)});
  if (file.refusal)
    intro.add(render::Paragraph{T.format("check.page.refused_file", {{"line", std::to_string(file.refusal->line)},
                                                                     {"detail", grading::rich_escape(file.refusal->detail)}}),
                                true});
  if (file.status == Verdict::compile_error) {
    intro.add(render::Paragraph{T.get("check.page.compile_error"), true});
    for (const auto& m : file.compiler)
      if (m.severity == "error") intro.add(render::Paragraph{grading::rich_escape(m.rendered.substr(0, m.rendered.find('\n')))});
  }
  if (!file.not_written.empty()) {
    std::string names;
    for (Fn fn : file.not_written) names += (names.empty() ? "" : ", ") + std::string(info(fn).name);
    intro.add(render::Paragraph{T.format("check.page.not_written", {{"names", names}})});
  }
  if (!file.notes.empty()) {
    std::string notes;
    for (const auto& n : file.notes) notes += (notes.empty() ? "" : "; ") + n;
    intro.add(render::Paragraph{T.format("check.page.notes", {{"notes", grading::rich_escape(notes)}})});
  }
  doc.sections.push_back(std::move(intro));
  for (const FunctionReport& r : file.functions) {
    FunctionView v = function_view(r, options.language, T);
    render::Section s;
    s.add(render::Heading{grading::rich_escape(v.heading), 1});
    for (std::size_t i = 0; i < v.paragraphs.size(); ++i) s.add(render::Paragraph{v.paragraphs[i], i < r.bugs.size()});
    for (auto& c : v.cases) {
      s.add(render::Paragraph{grading::rich_escape(fmt::format("{} — {} {}. {} {}. {} {}.", category_text(c.category, T),
                                                               T.get("check.page.input"), c.data, T.get("check.page.expected"),
                                                               c.expected, T.get("check.page.got"), c.got))});
      if (c.figure) {
        // (the width read before the scene moves: a brace list evaluates left to right)
        const double width = c.figure->panels.size() > 1 ? 0.8 : 0.5;
        s.add(render::Figure{std::move(*c.figure), width});
      }
      else s.add(render::Paragraph{grading::rich_escape(T.format("check.page.figure_not_drawn", {{"why", c.not_drawn}}))});
    }
    doc.sections.push_back(std::move(s));
  }
  return doc;
}

std::string feedback_html(const FileReport& file, const CheckOptions& options) {
  const Texts& T = Texts::builtin(options.language);
  std::string out = "<!DOCTYPE html>\n<html lang=\"" + options.language + "\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  html_text(out, T.get("check.page.title") + " — " + file.student);
  out += "</title>\n<style>\n"
         "body{font-family:'DejaVu Sans',sans-serif;max-width:52em;margin:2em auto;padding:0 1em;color:#222}\n"
         "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:.25em .6em;text-align:left}\n"
         ".passed{color:#1a7f37}.wrong,.crashed,.timeout,.refused,.compile_error{color:#b3261e}\n"
         ".bug{background:#fff4e5;border-left:4px solid #e8a33d;padding:.5em .8em}\n"
         "pre{background:#f5f5f5;padding:.6em;overflow-x:auto}figure{margin:1em 0}svg{max-width:100%;height:auto}\n"
         "</style>\n</head>\n<body>\n<h1>";
  html_text(out, T.get("check.page.title"));
  out += "</h1>\n<p>";
  html_text(out, header_line(file, T));
  out += "</p>\n<p>";
  html_rich(out, legend(T));
  out += "</p>\n";
  if (file.refusal) {
    out += "<p class=\"bug\">";
    html_rich(out, T.format("check.page.refused_file", {{"line", std::to_string(file.refusal->line)},
                                                        {"detail", grading::rich_escape(file.refusal->detail)}}));
    out += "</p>\n";
  }
  if (!file.compiler.empty()) {
    out += "<p>";
    html_text(out, T.get(file.status == Verdict::compile_error ? "check.page.compile_error" : "check.page.warnings"));
    out += "</p>\n<pre>";
    for (const auto& m : file.compiler) {
      html_text(out, m.rendered);
      out += "\n";
    }
    out += "</pre>\n";
  }
  if (!file.not_written.empty()) {
    std::string names;
    for (Fn fn : file.not_written) names += (names.empty() ? "" : ", ") + std::string(info(fn).name);
    out += "<p>";
    html_text(out, T.format("check.page.not_written", {{"names", names}}));
    out += "</p>\n";
  }
  for (const auto& n : file.notes) {
    out += "<p>";
    html_text(out, n);
    out += "</p>\n";
  }
  // the table of functions
  out += "<table>\n<tr><th>";
  html_text(out, T.get("check.page.function"));
  out += "</th><th>";
  html_text(out, T.get("check.page.verdict"));
  out += "</th><th>";
  html_text(out, T.get("check.page.cases"));
  out += "</th><th>";
  html_text(out, T.get("check.page.mark"));
  out += "</th><th>";
  html_text(out, T.get("check.page.bug"));
  out += "</th></tr>\n";
  for (const FunctionReport& r : file.functions) {
    // a link to the function's part of the page: only a function that did not pass has one
    out += r.verdict == Verdict::passed ? fmt::format("<tr><td>{}</td>", info(r.fn).name)
                                        : fmt::format("<tr><td><a href=\"#{0}\">{0}</a></td>", info(r.fn).name);
    out += fmt::format("<td class=\"{}\">", verdict_name(r.verdict));
    html_text(out, verdict_text(r.verdict, T));
    out += fmt::format("</td><td>{}/{}</td><td>{:.2f}</td><td>", r.passed, r.cases, r.mark);
    for (std::size_t i = 0; i < r.bugs.size(); ++i) out += (i ? ", " : "") + std::string(bug_code(r.bugs[i]));
    if (r.bugs.empty() && r.verdict != Verdict::passed && r.verdict != Verdict::wrong) html_text(out, r.reason_code);
    out += "</td></tr>\n";
  }
  out += fmt::format("<tr><th colspan=\"3\">{}</th><th>{:.2f}</th><th></th></tr>\n</table>\n", T.get("check.page.total"), file.total);
  for (const FunctionReport& r : file.functions) {
    if (r.verdict == Verdict::passed) continue;
    const FunctionView v = function_view(r, options.language, T);
    out += fmt::format("<h2 id=\"{}\">", info(r.fn).name);
    html_text(out, v.heading);
    out += "</h2>\n";
    for (std::size_t i = 0; i < v.paragraphs.size(); ++i) {
      out += i < r.bugs.size() ? "<p class=\"bug\">" : "<p>";
      html_rich(out, v.paragraphs[i]);
      out += "</p>\n";
    }
    for (const auto& c : v.cases) {
      out += "<figure>\n<p><b>";
      html_text(out, category_text(c.category, T));
      out += "</b><br>";
      html_text(out, T.get("check.page.input") + " " + c.data);
      out += "<br>";
      html_text(out, T.get("check.page.expected") + " " + c.expected);
      out += "<br>";
      html_text(out, T.get("check.page.got") + " " + c.got);
      out += "</p>\n";
      if (c.figure) out += render::scene_to_svg(*c.figure, c.figure->panels.size() > 1 ? 2 * kFigureWidth : kFigureWidth);
      else html_text(out, T.format("check.page.figure_not_drawn", {{"why", c.not_drawn}}));
      out += "\n</figure>\n";
    }
  }
  out += "</body>\n</html>\n";
  return out;
}

void write_feedback_pages(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::optional<std::int64_t> date = render::source_date_epoch();
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next++;
      if (i >= result.files.size()) return;
      const FileReport& file = result.files[i];
      try {
        output::write_file_atomically(dir / (file.feedback + ".html"), feedback_html(file, options));
        const render::Document doc = feedback_document(file, options);
        const auto pages = render::layout_document(doc);
        render::PdfMetadata metadata;
        metadata.title = doc.title + " — " + file.student;
        metadata.creator = "epure";
        metadata.date = date;
        output::write_file_atomically(dir / (file.feedback + ".pdf"), render::pages_to_pdf(pages, doc.sheet_id, metadata));
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, options.jobs); ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace epure::check
