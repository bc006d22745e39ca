#include "export/variant_builder.h"

#include <memory>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "exercises/kind_support.h"
#include "geometry/box_faces.h"
#include "grading/review.h"
#include "render/markup_escape.h"
#include "render/pdf_document.h"
#include "render/svg_scene.h"
#include "support/agrees.h"

namespace epure::exporting {

namespace {

using grading::AnswerType;
using grading::QuestionKey;
using method::Recorded;
using method::Traced;

// A diagram's width on the page (points) and on screen (CSS pixels at 96 per inch), and the
// PNG's resolution: twice the screen's, sharp on a high-density display.
constexpr double kFigureWidthPt = 360;
constexpr double kFigureWidthPx = kFigureWidthPt * 96.0 / 72.0;
constexpr double kPngDpi = 144;

// Equal but for the last bits (as grading decides that a mistake leaves an answer unchanged).
bool unchanged(double a, double b) { return agrees(b, a); }

const Recorded<Traced>* find_answer(const std::vector<Recorded<Traced>>& run, std::string_view id) {
  for (const auto& a : run)
    if (a.id == id) return &a;
  return nullptr;
}

// The value a run gives for a question of the key: a number, or one coordinate of a point.
std::optional<double> number_in(const std::vector<Recorded<Traced>>& run, const QuestionKey& q) {
  if (!q.point.empty()) {
    const std::string group = q.field.substr(0, q.field.size() - 2);
    const auto* a = find_answer(run, group);
    if (!a || a->type != method::AnswerType::point) return std::nullopt;
    return q.field.back() == 'x' ? a->x.v : a->y.v;
  }
  const auto* a = find_answer(run, q.field);
  if (!a || a->type != method::AnswerType::number) return std::nullopt;
  return a->x.v;
}

std::vector<std::string> face_names(method::FaceMask bits) {
  std::vector<std::string> out;
  for (int i = 0; i < 6; ++i)
    if (bits & (1u << i)) out.emplace_back(geo::kFaceNames[static_cast<std::size_t>(i)]);
  if (out.empty()) out.emplace_back("none");
  return out;
}

const method::QuestionDecl* decl_of(const ExerciseKind* kind, std::string_view field) {
  if (!kind) return nullptr;
  for (const auto& d : kind->questions())
    if (d.field == field) return &d;
  return nullptr;
}

// Whether a run's answer to q differs from the key run's.
bool changes(const std::vector<Recorded<Traced>>& run, const std::vector<Recorded<Traced>>& key,
                   const QuestionKey& q) {
  if (q.type == AnswerType::number) {
    const auto a = number_in(run, q), b = number_in(key, q);
    return a && b && !unchanged(*a, *b);
  }
  const auto* a = find_answer(run, q.field);
  const auto* b = find_answer(key, q.field);
  if (!a || !b) return false;
  return a->boolean != b->boolean || a->word != b->word || a->faces != b->faces;
}

}  // namespace

struct VariantBuilder::Runs {
  // A named mistake's run on one of the method's roads, and the right run on that road (what
  // the mistake is measured from: the roads differ by the rounding of their steps).
  struct Mistake {
    std::string_view code;
    std::vector<Recorded<Traced>> run;
    std::shared_ptr<const std::vector<Recorded<Traced>>> right;
  };
  std::vector<Recorded<Traced>> key;
  std::vector<Mistake> mistakes;
};

Variant VariantBuilder::build(const grading::SheetKey& sheet, const grading::ExerciseKey& ex, const ExerciseInstance& inst,
              const std::string& title) const {
  Variant v;
  v.sheet_id = sheet.id;
  v.name = fmt::format("{} \u2014 {}", title, sheet.id);
  const ExerciseKind* kind = find_kind(ex.kind);
  const Runs runs = evaluate(kind, ex);
  // where each mistake first shows, in the key's order of questions
  std::vector<std::size_t> origin(runs.mistakes.size(), ex.questions.size());
  for (std::size_t k = 0; k < runs.mistakes.size(); ++k)
    for (std::size_t i = 0; i < ex.questions.size() && origin[k] == ex.questions.size(); ++i)
      if (changes(runs.mistakes[k].run, *runs.mistakes[k].right, ex.questions[i])) origin[k] = i;
  for (std::size_t i = 0; i < ex.questions.size(); ++i) {
    // the mistakes first made on this answer before those carried from an earlier one:
    // grading tries each mistake on the student's own earlier answers first, so that for a
    // student whose earlier answers are right, a mistake made upstream explains nothing here
    Runs ordered{runs.key, {}};
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t k = 0; k < runs.mistakes.size(); ++k)
        if ((origin[k] == i) == (pass == 0)) ordered.mistakes.push_back(runs.mistakes[k]);
    v.parts.push_back(part(kind, ex.questions[i], ordered));
    v.points += ex.questions[i].points;
  }
  std::vector<bool> used(v.parts.size(), false);
  for (const auto& block : inst.sheet.blocks) {
    if (const auto* p = std::get_if<render::Paragraph>(&block)) {
      const std::string html = html_of(p->text);
      v.blocks.push_back({Block::Kind::text, p->emphasis ? "<em>" + html + "</em>" : html, -1, {}, false});
    } else if (const auto* f = std::get_if<render::Figure>(&block)) {
      v.blocks.push_back({Block::Kind::image, {}, static_cast<int>(v.images.size()), {}, false});
      v.images.push_back(image(f->scene, fmt::format("{}-{}-{}", sheet.id, ex.n, v.images.size() + 1)));
    } else if (const auto* a = std::get_if<render::AnswerField>(&block)) {
      Block b{Block::Kind::field, html_of(a->prompt), -1, {}, false};
      const bool point = a->kind == render::AnswerField::Kind::point || a->kind == render::AnswerField::Kind::point3;
      // the field's id as the key numbers it: the same unless the key was written before
      // exercises had numbers of their own (its ids then start with the place, "6.t")
      const std::string field_id = ex.number + a->question_id.substr(std::min(inst.number.size(), a->question_id.size()));
      const std::vector<std::string> ids =
          point ? std::vector<std::string>{field_id + ".x", field_id + ".y", field_id + ".z"}
                : std::vector<std::string>{field_id};
      for (const auto& id : ids)
        for (std::size_t i = 0; i < v.parts.size(); ++i)
          if (v.parts[i].question_id == id && !used[i]) {
            b.parts.push_back(static_cast<int>(i));
            used[i] = true;
          }
      // a field this case does not ask (the sheet prints every field of the kind): shown as
      // the sheet shows it, marked for nothing
      if (b.parts.empty())
        for (const auto& id : point ? std::vector<std::string>(ids.begin(), ids.begin() + (a->kind == render::AnswerField::Kind::point3 ? 3 : 2))
                                    : ids) {
          b.parts.push_back(static_cast<int>(v.parts.size()));
          v.parts.push_back(not_asked(kind, *a, id, ex.number));
          used.push_back(true);
        }
      b.point = point && b.parts.size() > 1;
      b.whole_point = b.point && v.parts[static_cast<std::size_t>(b.parts.front())].radius > 0;
      v.blocks.push_back(std::move(b));
    }
  }
  // the key's worked solution, as the paper key sets it (its heading is the question's name)
  for (const auto& block : inst.key.blocks) {
    using K = SolutionBlock::Kind;
    if (const auto* h = std::get_if<render::Heading>(&block)) {
      if (h->level > 1) v.solution.push_back({K::heading, html_of(h->text), {}, -1});
    } else if (const auto* p = std::get_if<render::Paragraph>(&block)) {
      const std::string html = html_of(p->text);
      v.solution.push_back({K::text, p->emphasis ? "<em>" + html + "</em>" : html, {}, -1});
    } else if (const auto* f = std::get_if<render::Figure>(&block)) {
      v.solution.push_back({K::image, {}, {}, static_cast<int>(v.solution_images.size())});
      v.solution_images.push_back(
          image(f->scene, fmt::format("{}-{}-key-{}", sheet.id, ex.n, v.solution_images.size() + 1)));
    } else if (const auto* a = std::get_if<render::AnswerLine>(&block)) {
      v.solution.push_back({K::answer, html_of(a->prompt), html_of(a->answer), -1});
    }
  }
  // a question the sheet has no field for: asked all the same, under its id
  for (std::size_t i = 0; i < v.parts.size(); ++i)
    if (!used[i])
      v.blocks.push_back({Block::Kind::field, render::markup_escaped(v.parts[i].question_id), -1, {static_cast<int>(i)}, false});
  return v;
}


VariantBuilder::Runs VariantBuilder::evaluate(const ExerciseKind* kind, const grading::ExerciseKey& ex) const {
  Runs r;
  if (!kind || kind->questions().empty()) return r;
  const std::any data = kind->read_instance(ex.instance);
  r.key = kind->evaluate(data, nullptr, {}, decimals_);
  // each mistake on the usual road, then on each other right road the kind declares (as
  // grading tries them: û left unnormalised, then d² by the course's cross product)
  std::vector<std::string_view> roads{""};
  for (auto road : kind->roads()) roads.push_back(road);
  for (auto road : roads) {
    auto right = std::make_shared<const std::vector<Recorded<Traced>>>(kind->evaluate(data, nullptr, {"", road}, decimals_));
    for (std::string_view code : kind->mistakes())
      r.mistakes.push_back({code, kind->evaluate(data, nullptr, {code, road}, decimals_), right});
  }
  return r;
}

// The sentence the paper feedback prints for this mistake on this answer.
std::string VariantBuilder::sentence(const QuestionKey& q, std::string_view code, double value) const {
  grading::QuestionMark m;
  const std::string raw = std::isfinite(value) ? feedback_.number(value) : std::string();
  m.verdict = grading::Verdict::wrong;
  m.mistake = code;
  m.value = value;
  m.given.state = grading::Given::State::value;
  m.given.number = value;
  m.given.raw = raw;
  return html_of(feedback_.explanation(q, m));
}

// A field the sheet prints and this case does not ask: its options as the sheet's.
Part VariantBuilder::not_asked(const ExerciseKind* kind, const render::AnswerField& field, const std::string& id,
                              const std::string& number) const {
  Part p;
  p.question_id = id;
  p.asked = false;
  p.points = 0;
  using Kind = render::AnswerField::Kind;
  const std::string field_name = id.substr(number.size() + 1);
  switch (field.kind) {
    case Kind::number:
    case Kind::point:
    case Kind::point3: p.type = Part::Type::number; break;
    case Kind::boolean:
      p.type = Part::Type::choice;
      p.options = yes_no();
      break;
    case Kind::choice:
      p.type = Part::Type::choice;
      p.options = choice_options(kind, field_name);
      if (p.options.empty())
        throw ExportError(fmt::format("question {}: a field of kind {} without its choices", id,
                                      kind ? kind->name() : std::string_view("?")));
      break;
    case Kind::faces:
      p.type = Part::Type::faces;
      p.options = side_options(kind, field_name);
      break;
  }
  return p;
}

// A list's options as the sheet prints them, none marked right yet.
std::vector<Option> VariantBuilder::yes_no() const {
  return {{"yes", html_of(feedback_.texts().get("common.yes")), false},
          {"no", html_of(feedback_.texts().get("common.no")), false}};
}
std::vector<Option> VariantBuilder::choice_options(const ExerciseKind* kind, std::string_view field) const {
  std::vector<Option> out;
  if (const auto* d = decl_of(kind, field))
    for (auto w : d->choices) out.push_back({std::string(w), wording(w), false});
  return out;
}
// The kind's sides or faces (the square's when the kind is unknown), then "none": the candidates
// may be none (a ray from inside), offered on every variant so that the list does not tell the case.
std::vector<Option> VariantBuilder::side_options(const ExerciseKind* kind, std::string_view field) const {
  std::vector<std::string> names;
  if (const auto* d = decl_of(kind, field))
    for (auto w : d->choices) names.emplace_back(w);
  else
    for (const geo::Face f : {geo::Face{0, +1}, geo::Face{1, +1}, geo::Face{0, -1}, geo::Face{1, -1}})
      names.emplace_back(geo::face_name(f));
  std::vector<Option> out;
  for (const auto& f : names) out.push_back({f, render::markup_escaped(kinds::face_label(f)), false});
  out.push_back({"none", html_of(feedback_.texts().get("common.none")), false});
  return out;
}

std::string VariantBuilder::wording(std::string_view word) const {
  const std::string key = fmt::format("choice.{}", word);
  return feedback_.texts().has(key) ? html_of(feedback_.texts().get(key)) : render::markup_escaped(word);
}

Part VariantBuilder::part(const ExerciseKind* kind, const QuestionKey& q, const Runs& runs) const {
  Part p;
  p.question_id = q.id;
  p.points = q.points;
  switch (q.type) {
    case AnswerType::point:  // never a key's question: read as the number it would be
    case AnswerType::number: {
      p.type = Part::Type::number;
      p.value = q.number;
      const double right = rule_width(q.rule, q.number);
      p.width = conservative_width(right, q.number);
      if (q.rule.kind == ToleranceRule::Kind::distance) p.radius = conservative_width(q.rule.abs, q.number);
      for (const auto& [code, run, right] : runs.mistakes) {
        const auto value = number_in(run, q);
        const auto base = number_in(*right, q);
        // as grading does: a mistake that leaves the answer where its road has it says nothing
        // of it; every other one is listed, in grading's order, even where an earlier one (or
        // the right answer) already answers (a platform tries them in order, as grading does),
        // once for each value it gives (on another road it often gives the same, but for the
        // rounding of the road's steps)
        if (!value || !std::isfinite(*value) || (base && unchanged(*value, *base))) continue;
        bool known = false;
        for (const auto& m : p.mistakes) known = known || (m.code == code && std::fabs(m.value - *value) <= m.width);
        if (known) continue;
        MistakeAnswer m;
        m.code = std::string(code);
        m.value = *value;
        m.width = conservative_width(grading::kMatchFactor * rule_width(q.rule, *value), *value);
        m.feedback_html = sentence(q, code, *value);
        p.mistakes.push_back(std::move(m));
      }
      break;
    }
    case AnswerType::boolean: {
      // a yes/no answer is wrong, not diagnosed (as on paper)
      p.type = Part::Type::choice;
      p.options = yes_no();
      p.options[0].right = q.boolean;
      p.options[1].right = !q.boolean;
      break;
    }
    case AnswerType::choice: {
      p.type = Part::Type::choice;
      p.options = choice_options(kind, q.field);
      if (std::none_of(p.options.begin(), p.options.end(), [&](const Option& o) { return o.id == q.word; }))
        p.options.push_back({q.word, wording(q.word), false});
      for (auto& o : p.options) o.right = o.id == q.word;
      for (const auto& [code, run, right] : runs.mistakes) {
        const auto* a = find_answer(run, q.field);
        const auto* b = find_answer(*right, q.field);
        if (!a || a->type != method::AnswerType::choice || a->word == q.word || (b && a->word == b->word)) continue;
        bool known = false;
        for (const auto& m : p.mistakes) known = known || m.options.front() == a->word;
        if (known) continue;
        p.mistakes.push_back({std::string(code), 0, 0, {std::string(a->word)}, sentence(q, code, NAN)});
      }
      break;
    }
    case AnswerType::faces: {
      p.type = Part::Type::faces;
      p.options = side_options(kind, q.field);
      for (auto& o : p.options) o.right = o.id == "none" ? q.faces == 0 : (q.faces & grading::face_bit(o.id)) != 0;
      for (const auto& [code, run, right] : runs.mistakes) {
        const auto* a = find_answer(run, q.field);
        const auto* b = find_answer(*right, q.field);
        if (!a || a->type != method::AnswerType::faces || a->faces == q.faces || (b && a->faces == b->faces)) continue;
        bool known = false;
        const auto options = face_names(a->faces);
        for (const auto& m : p.mistakes) known = known || m.options == options;
        if (known) continue;
        p.mistakes.push_back({std::string(code), 0, 0, options, sentence(q, code, NAN)});
      }
      break;
    }
  }
  return p;
}

Image VariantBuilder::image(const render::Scene& scene, const std::string& stem) const {
  Image im;
  im.alt = scene.description.empty() ? scene.title : scene.description;
  im.width_px = kFigureWidthPx;
  if (images_ == ImageFormat::png) {
    im.name = stem + ".png";
    im.media_type = "image/png";
    im.bytes = render::scene_to_png(scene, kFigureWidthPt, kPngDpi);
  } else {
    im.name = stem + ".svg";
    im.media_type = "image/svg+xml";
    im.bytes = render::scene_to_svg(scene, kFigureWidthPt);
  }
  return im;
}

}  // namespace epure::exporting
