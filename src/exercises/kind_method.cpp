#include "exercises/kind_method.h"

#include "support/agrees.h"
#include "exercises/kinds/space_common.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace epure::method {

std::optional<exact::Rational> rational_of(double x) {
  double scale = 1;
  for (int k = 0; k <= 6; ++k, scale *= 10) {
    const double scaled = x * scale;
    if (std::abs(scaled) > 9e15) return std::nullopt;
    const double whole = std::nearbyint(scaled);
    // the datum was written with k decimals exactly when scaling lands on an integer (to
    // rounding of the scaling itself)
    if (agrees(whole, scaled))
      return exact::Rational(static_cast<std::int64_t>(whole), static_cast<std::int64_t>(scale));
  }
  return std::nullopt;
}

}  // namespace epure::method

namespace epure::kinds {

using method::AnswerType;

// ---- schema

void SchemaReader::operator()(std::string_view field, double& x) {
  auto it = j_.find(field);
  if (it == j_.end() || !it->is_number()) throw std::runtime_error(fmt::format("field '{}': expected a number", field));
  x = it->get<double>();
  if (!std::isfinite(x)) throw std::runtime_error(fmt::format("field '{}': not a finite number", field));
}

std::pair<double, double> SchemaReader::pair(std::string_view field) {
  auto it = j_.find(field);
  if (it == j_.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number())
    throw std::runtime_error(fmt::format("field '{}': expected [x, y]", field));
  const double a = (*it)[0].get<double>(), b = (*it)[1].get<double>();
  if (!std::isfinite(a) || !std::isfinite(b))
    throw std::runtime_error(fmt::format("field '{}': not finite numbers", field));
  return {a, b};
}

void SchemaReader::operator()(std::string_view field, geo::Point2& p) {
  const auto [x, y] = pair(field);
  p = {x, y};
}
void SchemaReader::operator()(std::string_view field, geo::Vec2& v) {
  const auto [x, y] = pair(field);
  v = {x, y};
}
std::array<double, 3> SchemaReader::triple(std::string_view field) {
  auto it = j_.find(field);
  if (it == j_.end() || !it->is_array() || it->size() != 3 || !(*it)[0].is_number() || !(*it)[1].is_number() ||
      !(*it)[2].is_number())
    throw std::runtime_error(fmt::format("field '{}': expected [x, y, z]", field));
  const std::array<double, 3> v = {(*it)[0].get<double>(), (*it)[1].get<double>(), (*it)[2].get<double>()};
  for (double x : v)
    if (!std::isfinite(x)) throw std::runtime_error(fmt::format("field '{}': not finite numbers", field));
  return v;
}
void SchemaReader::operator()(std::string_view field, geo::Point3& p) {
  const auto v = triple(field);
  p = {v[0], v[1], v[2]};
}
void SchemaReader::operator()(std::string_view field, geo::Vec3& p) {
  const auto v = triple(field);
  p = {v[0], v[1], v[2]};
}
void SchemaReader::operator()(std::string_view field, Pair& p) {
  const auto [a, b] = pair(field);
  p = {a, b};
}

// ---- the core's answers

CoreAnswers& CoreAnswers::number(std::string_view field, double x) {
  answers_.push_back(method::Recorded<double>(field, AnswerType::number, x));
  return *this;
}
CoreAnswers& CoreAnswers::point(std::string_view field, geo::Point2 p) {
  answers_.push_back(method::Recorded<double>(field, AnswerType::point, p.x, p.y));
  return *this;
}
CoreAnswers& CoreAnswers::boolean(std::string_view field, bool b) {
  method::Recorded<double> r(field, AnswerType::boolean);
  r.boolean = b;
  answers_.push_back(r);
  return *this;
}
CoreAnswers& CoreAnswers::choice(std::string_view field, std::string_view word) {
  method::Recorded<double> r(field, AnswerType::choice);
  r.word = word;
  answers_.push_back(r);
  return *this;
}
CoreAnswers& CoreAnswers::faces(std::string_view field, method::FaceMask bits) {
  method::Recorded<double> r(field, AnswerType::faces);
  r.faces = bits;
  answers_.push_back(r);
  return *this;
}
const method::Recorded<double>* CoreAnswers::find(std::string_view field) const {
  for (const auto& a : answers_)
    if (a.id == field) return &a;
  return nullptr;
}

// ---- the key's values

namespace {
const method::Recorded<method::Exact>& step_of(const KeySolution& s, std::string_view id) {
  const auto* r = s.run.step(id);
  if (!r) throw std::logic_error(fmt::format("method: no step '{}'", id));
  return *r;
}
}  // namespace

double KeySolution::value(std::string_view id) const {
  if (const auto* c = core.find(id); c && c->type == AnswerType::number) return c->x;
  return step_of(*this, id).x.v;
}
std::optional<exact::Surd> KeySolution::exact(std::string_view id) const { return step_of(*this, id).x.e; }
geo::Point2 KeySolution::point(std::string_view id) const {
  if (const auto* c = core.find(id); c && c->type == AnswerType::point) return {c->x, c->y};
  const auto& r = step_of(*this, id);
  return {r.x.v, r.y.v};
}
std::optional<exact::Surd> KeySolution::exact_x(std::string_view id) const { return step_of(*this, id).x.e; }
std::optional<exact::Surd> KeySolution::exact_y(std::string_view id) const { return step_of(*this, id).y.e; }

namespace {

// A value a worked step shows, as `how` says (method.h: Shown).
std::string shown_value(const ExerciseContext& ctx, const KeySolution& key, const method::Shows& s) {
  using method::Shown;
  switch (s.how) {
    case Shown::value: return step_value(ctx, key.value(s.id), key.exact(s.id));
    case Shown::equals: return equals_value(ctx, key.value(s.id), key.exact(s.id));
    case Shown::datum: return ctx.numbers.datum(key.value(s.id));
    case Shown::text: return std::string(s.id);
    case Shown::face: return face_label(s.id);
    case Shown::faces: {
      const auto* r = key.run.step(s.id);
      std::string list;
      for (int bit = 0; bit < 6; ++bit)
        if (r && (r->faces & (1u << bit)))
          list += fmt::format("{}{}", list.empty() ? "" : ", ", face_label(geo::kFaceNames[static_cast<std::size_t>(bit)]));
      return list;
    }
    case Shown::point:
    case Shown::shown:
    case Shown::data: break;
  }
  // a point: in the plane one step; in space three, named by its group (u_hat.x, u_hat.y, …)
  const auto* flat = key.run.step(s.id);
  if (flat && flat->type == AnswerType::point) {
    const geo::Point2 p = key.point(s.id);
    if (s.how == Shown::data) return ctx.numbers.point(p.x, p.y);
    if (s.how == Shown::shown) return shown_point(ctx, p, key.exact_x(s.id), key.exact_y(s.id));
    return step_point(ctx, p, key.exact_x(s.id), key.exact_y(s.id));
  }
  const method::CoordinateName x = method::coordinate_name(s.id, 'x'), y = method::coordinate_name(s.id, 'y'),
                               z = method::coordinate_name(s.id, 'z');
  if (s.how == Shown::data) return ctx.numbers.point(key.value(x), key.value(y), key.value(z));
  return space::shown_point3(ctx, {key.value(x), key.value(y), key.value(z)}, key.exact(x), key.exact(y), key.exact(z));
}

}  // namespace

void replay_steps(render::Section& section, const ExerciseContext& ctx, const KeySolution& key, std::string_view kind) {
  for (const method::Told& told : key.run.told()) {
    TextVars vars;
    for (const method::Shows& s : told.shows) vars.emplace_back(std::string(s.var), shown_value(ctx, key, s));
    section.add(render::Paragraph{ctx.texts.format(fmt::format("{}.step.{}", kind, told.text), vars)});
  }
}

namespace detail {

namespace {

[[noreturn]] void disagree(std::string_view kind, std::string_view field, std::string_view what,
                           const std::string& mine, const std::string& core) {
  throw std::logic_error(fmt::format("{}: the method's {} of '{}' is {} where the core gives {}", kind, what, field,
                                     mine, core));
}

void check_number(std::string_view kind, std::string_view field, const method::Exact& mine, double core) {
  if (!agrees(mine.v, core)) disagree(kind, field, "value", fmt::format("{}", mine.v), fmt::format("{}", core));
  if (mine.e && !agrees(mine.e->value(), core))
    disagree(kind, field, "exact form", fmt::format("{}", mine.e->value()), fmt::format("{}", core));
}

}  // namespace

void check_against_core(std::string_view kind, const method::Run<method::Exact>& run, const CoreAnswers& core) {
  for (const auto& c : core.answers()) {
    const auto* mine = run.answer(c.id);
    if (!mine || mine->type != c.type) disagree(kind, c.id, "answer", "missing", "one");
    switch (c.type) {
      case AnswerType::number: check_number(kind, c.id, mine->x, c.x); break;
      case AnswerType::point:
        check_number(kind, c.id, mine->x, c.x);
        check_number(kind, c.id, mine->y, c.y);
        break;
      case AnswerType::boolean:
        if (mine->boolean != c.boolean) disagree(kind, c.id, "decision", fmt::format("{}", mine->boolean), fmt::format("{}", c.boolean));
        break;
      case AnswerType::choice:
        if (mine->word != c.word) disagree(kind, c.id, "word", std::string(mine->word), std::string(c.word));
        break;
      case AnswerType::faces:
        if (mine->faces != c.faces) disagree(kind, c.id, "faces", fmt::format("{}", mine->faces), fmt::format("{}", c.faces));
        break;
    }
  }
  // and the method asks nothing the core does not answer
  for (const auto& a : run.answers())
    if (!core.find(a.id)) disagree(kind, a.id, "answer", "one", "none");
}

Questions make_questions(const ExerciseContext& ctx, std::span<const method::QuestionDecl> decls,
                         const method::Run<method::Exact>& run, const method::Run<method::Dual>* dual,
                         const CoreAnswers& core) {
  // the tolerance of each numeric answer coordinate, by field (zero without the dual run)
  const std::vector<double> tol = dual ? method::tolerances(*dual) : std::vector<double>{};
  const std::vector<double> follow = dual ? method::tolerances(*dual, true) : std::vector<double>{};
  auto tolerance_in = [&](const std::vector<double>& of, std::string_view field) -> std::pair<double, double> {
    if (!dual) return {0.0, 0.0};
    std::size_t k = 0;
    for (const auto& a : dual->answers()) {
      if (a.id == field) return {of.at(k), a.type == AnswerType::point ? of.at(k + 1) : 0.0};
      k += a.type == AnswerType::point ? 2 : a.type == AnswerType::number ? 1 : 0;
    }
    throw std::logic_error(fmt::format("method: no tolerance for '{}'", field));
  };
  auto tolerance_of = [&](std::string_view field) { return tolerance_in(tol, field); };
  Questions q(ctx);
  for (const auto& d : decls) q.default_weight(d.field, d.weight);
  // in the sheet's order: the kind's declaration, not the method's
  for (const auto& d : decls) {
    const auto* c = core.find(d.field);
    if (!c) continue;
    const auto* mine = run.answer(d.field);
    switch (d.type) {
      case AnswerType::number:
        q.number(d.field, c->x, tolerance_of(d.field).first, mine->x.e);
        if (dual) q.follow(d.field, tolerance_in(follow, d.field).first);
        break;
      case AnswerType::point: {
        const auto [tx, ty] = tolerance_of(d.field);
        q.point(d.field, {c->x, c->y}, tx, ty, mine->x.e, mine->y.e);
        if (dual) {
          const auto [fx, fy] = tolerance_in(follow, d.field);
          q.follow(method::coordinate_name(d.field, 'x'), fx);
          q.follow(method::coordinate_name(d.field, 'y'), fy);
        }
        break;
      }
      case AnswerType::boolean: q.boolean(d.field, c->boolean); break;
      case AnswerType::choice: {
        std::vector<std::string> choices(d.choices.begin(), d.choices.end());
        q.choice(d.field, c->word, choices);
        break;
      }
      case AnswerType::faces: {
        std::vector<std::string> value, all(d.choices.begin(), d.choices.end());
        for (const auto& name : d.choices) {
          const std::string_view n = name;
          const int axis = n[1] - 'x';
          const int bit = axis + (n[0] == '+' ? 0 : 3);
          if (c->faces & (1u << bit)) value.emplace_back(n);
        }
        q.faces(d.field, value, all);
        break;
      }
    }
  }
  return q;
}

std::vector<SheetField> sheet_fields_of(std::span<const method::QuestionDecl> decls) {
  using K = render::AnswerField::Kind;
  std::vector<SheetField> out;
  for (const auto& d : decls) {
    K kind = K::number;
    switch (d.type) {
      case AnswerType::number: kind = K::number; break;
      case AnswerType::point: kind = K::point; break;
      case AnswerType::boolean: kind = K::boolean; break;
      case AnswerType::choice: kind = K::choice; break;
      case AnswerType::faces: kind = K::faces; break;
    }
    out.push_back({std::string(d.field), kind, std::vector<std::string>(d.choices.begin(), d.choices.end())});
  }
  return out;
}

std::vector<std::string> fields_of(std::span<const method::QuestionDecl> decls) {
  std::vector<std::string> out;
  for (const auto& d : decls) out.emplace_back(d.field);
  return out;
}

}  // namespace detail

}  // namespace epure::kinds
