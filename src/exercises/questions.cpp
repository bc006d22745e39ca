#include "exercises/questions.h"

#include <fmt/format.h>

#include <cmath>

#include "exercises/instance_identity.h"
#include "support/portable.h"

namespace epure::kinds {

namespace {

// The question's exact form in both writings; `exact` dropped when it outgrows exact.h's machine
// form (answer_text then shows the rounding alone).
void take_exact(Question& q, std::optional<exact::Surd>& exact) {
  if (!exact) return;
  try {
    q.exact = exact->machine();
    q.exact_pretty = exact->pretty();
  } catch (const exact::ExactOverflow&) {
    exact.reset();
  }
}

}  // namespace

Questions::Questions(const ExerciseContext& ctx) : ctx_(ctx) {}

const QuestionSpec* Questions::spec_for(std::string_view field) const {
  // "P.x" is configured under "P"
  std::string base(field.substr(0, field.find('.')));
  auto it = ctx_.spec.questions.find(base);
  return it == ctx_.spec.questions.end() ? nullptr : &it->second;
}

// A weight, not points yet: the set shares the exercise's points among the questions asked
// (exercises/points.h), once this instance's questions are known.
double Questions::points_for(std::string_view field) const {
  const QuestionSpec* q = spec_for(field);
  if (q && q->points) return *q->points;
  // the kind's weight of the field as declared ("cross.x", a coordinate in space asked alone),
  // else of its point ("I" for I.x in the plane)
  const std::string_view base = field.substr(0, field.find('.'));
  for (const std::string_view name : {field, base})
    for (const auto& [declared, weight] : default_weights_)
      if (declared == name) return weight;
  return 1;
}

// Joined by hand rather than through fmt::format: every question of every draw asks both.
std::string Questions::id(std::string_view field) const {
  std::string id = number_of(ctx_);
  id += '.';
  id += field;
  return id;
}

std::string Questions::prompt(std::string_view field) const {
  std::string key;
  key.reserve(ctx_.spec.kind.size() + 3 + field.size());
  key += ctx_.spec.kind;
  key += ".q.";
  key += field;
  return ctx_.texts.get(key);
}

std::string Questions::answer_text(double value, const std::optional<exact::Surd>& exact) const {
  // The key's answer column follows a prompt that ends in "=": a value without an exact form is
  // its rounding alone; an exact form reads "5 − 2√2 ≈ 2.17", or "1/4 = 0.25" when it stops.
  const std::string rounded = ctx_.numbers.rounded(value, ctx_.decimals);
  if (!exact) return rounded;
  std::string pretty;
  try {
    pretty = ctx_.numbers.localise(exact->pretty());
  } catch (const exact::ExactOverflow&) {
    return rounded;
  }
  // a long exact form (hard data) helps nobody: the rounding says it all
  if (pretty.size() > 24) return rounded;
  if (!exact->is_rational()) return fmt::format("{} ≈ {}", pretty, rounded);
  const std::int64_t den = exact->a().den();
  if (den == 1) return pretty;
  std::int64_t pow10 = 1;
  for (int i = 0; i < ctx_.decimals; ++i) pow10 *= 10;
  if (pow10 % den == 0) return fmt::format("{} = {}", pretty, ctx_.numbers.datum(value, ctx_.decimals));
  return fmt::format("{} ≈ {}", pretty, rounded);
}

void Questions::number(std::string_view field, double value, double abs_tolerance,
                       std::optional<exact::Surd> exact) {
  // (an exact form too long for exact.h's machine form is too long for its pretty one: either
  // way answer_text shows the rounding alone)
  if (marking()) {
    Question q;
    q.field = std::string(field);
    q.expected = value;
    take_exact(q, exact);
    const QuestionSpec* spec = spec_for(field);
    q.tolerance = isclose_rule(abs_tolerance, ctx_.decimals, spec);
    if (q.tolerance.kind == ToleranceRule::Kind::distance) q.tolerance.kind = ToleranceRule::Kind::isclose;
    q.points = points_for(field);
    questions_.push_back(q);
    fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::number, {}});
  }
  lines_.push_back({id(field), prompt(field), answer_text(value, exact)});
}

void Questions::follow(std::string_view field, double follow_abs) {
  for (auto& q : questions_)
    if (q.field == field) {
      const std::string_view group = q.point_group.empty() ? std::string_view(q.field) : std::string_view(q.point_group);
      const QuestionSpec* spec = spec_for(group);
      if (spec && spec->abs) return;
      if (q.tolerance.kind == ToleranceRule::Kind::isclose && follow_abs > q.tolerance.abs)
        q.tolerance.follow_abs = follow_abs;
      return;
    }
}

void Questions::point(std::string_view field, geo::Point2 value, double abs_x, double abs_y,
                      std::optional<exact::Surd> exact_x, std::optional<exact::Surd> exact_y) {
  const QuestionSpec* spec = spec_for(field);
  const double coords[2] = {value.x, value.y};
  const double tols[2] = {abs_x, abs_y};
  const std::optional<exact::Surd> exacts[2] = {exact_x, exact_y};
  std::string shown[2];
  for (int i = 0; i < 2; ++i) {
    if (!marking()) {
      shown[i] = answer_text(coords[i], exacts[i]);  // as number's
      continue;
    }
    Question q;
    q.field = fmt::format("{}.{}", field, i == 0 ? "x" : "y");
    q.expected = coords[i];
    q.point_group = std::string(field);
    std::optional<exact::Surd> e = exacts[i];
    take_exact(q, e);
    q.tolerance = isclose_rule(tols[i], ctx_.decimals, spec);
    if (q.tolerance.kind == ToleranceRule::Kind::distance) {
      // as a whole: within the distance that both coordinates' tolerances allow together
      q.tolerance.abs = spec && spec->abs ? *spec->abs : portable::hypot(tols[0], tols[1]);
      q.tolerance.rel = 0;
      q.tolerance.why = "the point is marked as a whole, by its distance to the expected point";
    }
    q.points = points_for(field) / 2;
    questions_.push_back(q);
    shown[i] = answer_text(coords[i], e);
  }
  if (marking()) fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::point, {}});
  lines_.push_back({id(field), prompt(field),
                    fmt::format("({}{} {})", shown[0], ctx_.numbers.decimal_comma ? "\u00a0;" : ",", shown[1])});
}

void Questions::ask_exactly(std::string_view field, Expected value) {
  Question q;
  q.field = std::string(field);
  q.expected = std::move(value);
  q.tolerance = exact_rule();
  q.points = points_for(field);
  questions_.push_back(std::move(q));
}

void Questions::boolean(std::string_view field, bool value) {
  ask_exactly(field, value);
  fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::boolean,
                     {ctx_.texts.get("common.yes"), ctx_.texts.get("common.no")}});
  lines_.push_back({id(field), prompt(field), ctx_.texts.get(value ? "common.yes" : "common.no")});
}

std::string face_label(std::string_view name) {
  // The contract's "-x" is printed with the minus sign, as in the statement's "x = −1 (−x)".
  if (!name.empty() && name.front() == '-') return fmt::format("\u2212{}", name.substr(1));
  return std::string(name);
}

std::vector<std::string> face_options(const ExerciseContext& ctx, const std::vector<std::string>& names) {
  std::vector<std::string> shown;
  for (const auto& n : names) shown.push_back(face_label(n));
  // A candidate set may be empty (A inside): the student needs a box to say so.
  shown.push_back(ctx.texts.get("common.none"));
  return shown;
}

std::vector<std::string> face_values(const std::vector<std::string>& names) {
  std::vector<std::string> values = names;
  values.push_back("none");  // as face_options adds its box
  return values;
}

void Questions::choice(std::string_view field, std::string_view value,
                       const std::vector<std::string>& choices) {
  ask_exactly(field, std::string(value));
  std::vector<std::string> shown;
  for (const auto& c : choices) shown.push_back(ctx_.texts.get(fmt::format("choice.{}", c)));
  fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::choice, shown, false, 0, 0, choices});
  lines_.push_back({id(field), prompt(field), ctx_.texts.get(fmt::format("choice.{}", value))});
}

void Questions::faces(std::string_view field, const std::vector<std::string>& value,
                      const std::vector<std::string>& all) {
  ask_exactly(field, value);
  fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::faces, face_options(ctx_, all), true, 0, 0,
                     face_values(all)});
  std::string shown;
  for (const auto& f : value) shown += fmt::format("{}{}", shown.empty() ? "" : ", ", face_label(f));
  if (shown.empty()) shown = ctx_.texts.get("common.none");
  lines_.push_back({id(field), prompt(field), shown});
}

void add_fields(render::Section& s, const Questions& q) {
  const ExerciseContext& ctx = q.context();
  const auto layout = find_kind(ctx.spec.kind)->sheet_fields();
  if (layout.empty()) {
    for (const auto& f : q.fields()) s.add(f);
    return;
  }
  for (const auto& f : layout) {
    std::vector<std::string> shown;
    using Kind = render::AnswerField::Kind;
    if (f.kind == Kind::choice)
      for (const auto& c : f.choices) shown.push_back(ctx.texts.get(fmt::format("choice.{}", c)));
    else if (f.kind == Kind::boolean)
      shown = {ctx.texts.get("common.yes"), ctx.texts.get("common.no")};
    else if (f.kind == Kind::faces)
      shown = face_options(ctx, f.choices);
    else
      shown = f.choices;
    std::vector<std::string> values;
    if (f.kind == Kind::choice) values = f.choices;
    if (f.kind == Kind::faces) values = face_values(f.choices);
    s.add(render::AnswerField{fmt::format("{}.{}", number_of(ctx), f.field),
                              ctx.texts.get(fmt::format("{}.q.{}", ctx.spec.kind, f.field)), f.kind, shown,
                              f.kind == Kind::faces, 0, 0, std::move(values)});
  }
}

void add_lines(render::Section& s, const Questions& q) {
  for (const auto& l : q.lines()) s.add(l);
}

}  // namespace epure::kinds
