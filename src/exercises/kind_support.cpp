#include "exercises/kind_support.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "solve/json_out.h"
#include "solve/solve.h"
#include "support/portable.h"

namespace epure::kinds {

InstanceWriter::InstanceWriter(std::string_view kind) {
  fmt::memory_buffer buf;
  JsonWriter(buf).begin_object().field("kind", kind);
  text_.assign(buf.data(), buf.size());  // "{"kind":"…"" — closed by finish()
}

namespace {
std::string number_text(double x) {
  if (x == 0) x = 0;  // one spelling for ±0
  return fmt::format("{}", x);
}

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

InstanceWriter& InstanceWriter::number(std::string_view field, double x) {
  text_ += fmt::format(",\"{}\":{}", field, number_text(x));
  return *this;
}
InstanceWriter& InstanceWriter::pair(std::string_view field, double a, double b) {
  text_ += fmt::format(",\"{}\":[{},{}]", field, number_text(a), number_text(b));
  return *this;
}
InstanceWriter& InstanceWriter::triple(std::string_view field, double a, double b, double c) {
  text_ += fmt::format(",\"{}\":[{},{},{}]", field, number_text(a), number_text(b), number_text(c));
  return *this;
}
InstanceWriter& InstanceWriter::point(std::string_view field, geo::Point2 p) { return pair(field, p.x, p.y); }
InstanceWriter& InstanceWriter::vec(std::string_view field, geo::Vec2 v) { return pair(field, v.x, v.y); }
std::string InstanceWriter::finish() { return text_ + "}"; }

std::string solve_instance(std::string_view instance) {
  fmt::memory_buffer out;
  std::string error = solve::solve_line(instance, out);
  if (!error.empty())
    throw std::logic_error(fmt::format("generated instance refused by solve: {} ({})", error, instance));
  return std::string(out.data(), out.size());
}

std::optional<ExerciseInstance> already_taken(const ExerciseContext& ctx, std::string instance) {
  const std::uint64_t f = fingerprint(instance);
  if (!ctx.taken || !ctx.taken->contains(f)) return std::nullopt;
  ExerciseInstance inst;
  inst.n = ctx.n;
  inst.branch = ctx.branch;
  inst.instance = std::move(instance);
  inst.fingerprint = f;
  return inst;
}

std::uint64_t fingerprint(std::string_view text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

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
  const std::string_view base = field.substr(0, field.find('.'));
  for (const auto& [name, weight] : default_weights_)
    if (name == base) return weight;
  return 1;
}

std::string Questions::id(std::string_view field) const { return fmt::format("{}.{}", ctx_.n, field); }

std::string Questions::prompt(std::string_view field) const {
  return ctx_.texts.get(fmt::format("{}.q.{}", ctx_.spec.kind, field));
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

void Questions::boolean(std::string_view field, bool value) {
  Question q;
  q.field = std::string(field);
  q.expected = value;
  q.tolerance = exact_rule();
  q.points = points_for(field);
  questions_.push_back(q);
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

void Questions::choice(std::string_view field, std::string_view value,
                       const std::vector<std::string>& choices) {
  Question q;
  q.field = std::string(field);
  q.expected = std::string(value);
  q.tolerance = exact_rule();
  q.points = points_for(field);
  questions_.push_back(q);
  std::vector<std::string> shown;
  for (const auto& c : choices) shown.push_back(ctx_.texts.get(fmt::format("choice.{}", c)));
  fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::choice, shown});
  lines_.push_back({id(field), prompt(field), ctx_.texts.get(fmt::format("choice.{}", value))});
}

void Questions::faces(std::string_view field, const std::vector<std::string>& value,
                      const std::vector<std::string>& all) {
  Question q;
  q.field = std::string(field);
  q.expected = value;
  q.tolerance = exact_rule();
  q.points = points_for(field);
  questions_.push_back(q);
  fields_.push_back({id(field), prompt(field), render::AnswerField::Kind::faces, face_options(ctx_, all), true});
  std::string shown;
  for (const auto& f : value) shown += fmt::format("{}{}", shown.empty() ? "" : ", ", face_label(f));
  if (shown.empty()) shown = ctx_.texts.get("common.none");
  lines_.push_back({id(field), prompt(field), shown});
}

render::Box view_around(const std::vector<render::P2>& points, double margin, double min_size,
                        double step) {
  double x0 = points.front().x, x1 = x0, y0 = points.front().y, y1 = y0;
  for (const auto& p : points) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  x0 -= margin, x1 += margin, y0 -= margin, y1 += margin;
  if (x1 - x0 < min_size) {
    const double grow = (min_size - (x1 - x0)) / 2;
    x0 -= grow, x1 += grow;
  }
  if (y1 - y0 < min_size) {
    const double grow = (min_size - (y1 - y0)) / 2;
    y0 -= grow, y1 += grow;
  }
  return {std::floor(x0 / step) * step, std::floor(y0 / step) * step, std::ceil(x1 / step) * step,
          std::ceil(y1 / step) * step};
}

namespace {
render::Section begin_section(const ExerciseContext& ctx, std::string_view title_key) {
  const std::string label = !ctx.label.empty()
                                ? ctx.label
                                : ctx.texts.format("common.exercise_label", {{"n", std::to_string(ctx.n)}});
  render::Section s;
  s.add(render::Heading{ctx.texts.format("common.exercise_heading", {{"label", label}, {"title", ctx.texts.get(title_key)}}), 1});
  return s;
}
}  // namespace

render::Section begin_sheet_section(const ExerciseContext& ctx, std::string_view title_key) {
  return begin_section(ctx, title_key);
}

render::Section begin_key_section(const ExerciseContext& ctx, std::string_view title_key) {
  return begin_section(ctx, title_key);
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
    s.add(render::AnswerField{fmt::format("{}.{}", ctx.n, f.field),
                              ctx.texts.get(fmt::format("{}.q.{}", ctx.spec.kind, f.field)), f.kind, shown,
                              f.kind == Kind::faces});
  }
}

void add_lines(render::Section& s, const Questions& q) {
  for (const auto& l : q.lines()) s.add(l);
}

double constraint(const ExerciseContext& ctx, const ExerciseKind& kind, const std::string& name) {
  auto it = ctx.spec.constraints.find(name);
  if (it != ctx.spec.constraints.end()) return it->second;
  return kind.default_constraints().at(name);
}

}  // namespace epure::kinds

namespace epure::kinds {

std::string step_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& e) {
  const std::string rounded = ctx.numbers.rounded(value, ctx.decimals);
  if (!e) return rounded;
  try {
    const std::string pretty = e->pretty();
    if (pretty.size() > 16 || e->a().den() > 1000 || e->b().den() > 1000) return rounded;
    const std::string exact = ctx.numbers.localise(pretty);
    if (!e->is_rational()) return fmt::format("{} ≈ {}", exact, rounded);
    const std::int64_t den = e->a().den();
    if (den == 1) return exact;
    std::int64_t pow10 = 1;
    for (int i = 0; i < ctx.decimals; ++i) pow10 *= 10;
    if (pow10 % den == 0) return fmt::format("{} = {}", exact, ctx.numbers.datum(value, ctx.decimals));
    return fmt::format("{} ≈ {}", exact, rounded);
  } catch (const exact::ExactOverflow&) {
    return rounded;
  }
}

std::string step_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                       const std::optional<exact::Surd>& ey) {
  return fmt::format("({}{} {})", step_value(ctx, p.x, ex), ctx.numbers.decimal_comma ? "\u00a0;" : ",",
                     step_value(ctx, p.y, ey));
}

std::string shown(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact) {
  if (exact) {
    try {
      const std::string pretty = exact->pretty();
      if (pretty.size() <= 16) return ctx.numbers.localise(pretty);
    } catch (const exact::ExactOverflow&) {
    }
  }
  return ctx.numbers.rounded(value, ctx.decimals);
}

std::string shown_point(const ExerciseContext& ctx, geo::Point2 p,
                        const std::optional<exact::Surd>& ex, const std::optional<exact::Surd>& ey) {
  return fmt::format("({}{} {})", shown(ctx, p.x, ex), ctx.numbers.decimal_comma ? "\u00a0;" : ",",
                     shown(ctx, p.y, ey));
}

double grid_value(Rng& rng, double lo, double hi, Difficulty d) {
  if (d == Difficulty::hard)
    return static_cast<double>(rng.integer(static_cast<std::int64_t>(std::ceil(lo * 10)),
                                           static_cast<std::int64_t>(std::floor(hi * 10)))) / 10.0;
  return static_cast<double>(rng.integer(static_cast<std::int64_t>(std::ceil(lo)),
                                         static_cast<std::int64_t>(std::floor(hi))));
}

std::string equals_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact) {
  const std::string rounded = ctx.numbers.rounded(value, ctx.decimals);
  std::string pretty;
  if (exact) {
    try {
      pretty = exact->pretty();
    } catch (const exact::ExactOverflow&) {
    }
  }
  // the same length limit as shown(): a longer exact form does not help a reader
  if (pretty.empty() || pretty.size() > 16) return fmt::format("≈ {}", rounded);
  pretty = ctx.numbers.localise(pretty);
  if (!exact->is_rational()) return fmt::format("= {} ≈ {}", pretty, rounded);
  if (exact->a().is_integer()) return fmt::format("= {}", pretty);
  // a fraction that stops within the asked decimals is written out exactly
  if (terminates_within(exact, ctx.decimals))
    return fmt::format("= {} = {}", pretty, ctx.numbers.datum(value, ctx.decimals));
  return fmt::format("= {} ≈ {}", pretty, rounded);
}

bool terminates_within(const std::optional<exact::Surd>& exact, int decimals) {
  if (!exact || !exact->is_rational()) return false;
  std::int64_t pow10 = 1;
  for (int i = 0; i < decimals; ++i) pow10 *= 10;
  return pow10 % exact->a().den() == 0;
}

std::string equals_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                         const std::optional<exact::Surd>& ey) {
  if (terminates_within(ex, ctx.decimals) && terminates_within(ey, ctx.decimals))
    return fmt::format("= {}", ctx.numbers.point(p.x, p.y, ctx.decimals));
  return fmt::format("≈ {}", ctx.numbers.rounded_point(p.x, p.y, ctx.decimals));
}

}  // namespace epure::kinds
