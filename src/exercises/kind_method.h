#pragma once
// The generic half of an exercise kind written as one method (method.h). A kind declares, once:
//
//   struct Data { … };                                   // the instance
//   static constexpr std::string_view kName = "…";
//   template <class V, class D> static void schema(V& v, D& d) {  // the data, each with its role
//     v("A", d.A); v("u", d.u, role::from("A")); …                // (data_field.h) where the type
//   }                                                              // does not say it all
//   static constexpr method::QuestionDecl kQuestions[] = {…};   // the sheet's questions, in order
//   static constexpr std::string_view kMistakes[] = {…};        // codes its method declares
//   static constexpr double kPoints = 7;                         // what the exercise is worth
//   template <class M> static void method(M& m, const Data& d);  // the course's method
//   static method::CoreAnswers core(const Data& d);              // the geometry core's answers
//
// and MethodKind<Kind> derives from it everything that used to be written again elsewhere: the
// instance as a solve input (key.json) and read back (grading), the sheet's answer fields and
// the question ids, the key's expected values (the core's, checked against the method's own
// double evaluation), exact forms, tolerances, and the student's evaluations for grading.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <any>
#include <optional>
#include <array>
#include <stdexcept>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "exercises/data_field.h"
#include "exercises/kind_support.h"
#include "exercises/method.h"
#include "solve/fields.h"
#include "solve/number_span.h"
#include "solve/result.h"

namespace epure::kinds {

// A pair of numbers that is not a point: an ellipse's radii [a, b], a rectangle's half sizes.
struct Pair {
  double a = 0, b = 0;
};

// The schema read for its values: a visitor below sees (field, value), the field's role aside
// (only FieldList reads roles).
template <class V>
struct ValuesOnly {
  V& visitor;
  template <class T>
  void operator()(std::string_view field, T&& value, Role = {}) {
    visitor(field, std::forward<T>(value));
  }
};

// The schema's visitor that lists the data fields with their roles (ExerciseKind::data_fields).
// A field whose role the schema does not state is what its type says: a point is a point, a
// vector a direction from the origin, a number or a pair of numbers a datum without a handle.
struct FieldList {
  std::vector<DataField> fields;
  template <class T>
  void operator()(std::string_view name, const T&, Role role = {}) {
    constexpr bool point = std::is_same_v<T, geo::Point2> || std::is_same_v<T, geo::Point3>;
    constexpr bool vector = std::is_same_v<T, geo::Vec2> || std::is_same_v<T, geo::Vec3>;
    constexpr int dim = std::is_same_v<T, geo::Point3> || std::is_same_v<T, geo::Vec3> ? 3
                        : std::is_same_v<T, double>                                    ? 1
                                                                                       : 2;
    if (!role.given) role.role = point ? FieldRole::point : vector ? FieldRole::direction : FieldRole::number;
    fields.push_back({name, dim, role});
  }
};

// The schema's visitor that writes an instance as a solve input.
class SchemaWriter {
 public:
  explicit SchemaWriter(std::string_view kind) : w_(kind) {}
  void operator()(std::string_view field, double x) { w_.number(field, x); }
  void operator()(std::string_view field, geo::Point2 p) { w_.point(field, p); }
  void operator()(std::string_view field, geo::Vec2 v) { w_.vec(field, v); }
  void operator()(std::string_view field, Pair p) { w_.pair(field, p.a, p.b); }
  void operator()(std::string_view field, geo::Point3 p) { w_.triple(field, p.x, p.y, p.z); }
  void operator()(std::string_view field, geo::Vec3 v) { w_.triple(field, v.x, v.y, v.z); }
  std::string finish() { return w_.finish(); }

 private:
  InstanceWriter w_;
};

// The schema's visitor that reads an instance back: throws std::runtime_error naming the field,
// as the solve contract would ("field 'r': expected a number").
class SchemaReader {
 public:
  explicit SchemaReader(const nlohmann::json& j) : j_(j) {}
  void operator()(std::string_view field, double& x);
  void operator()(std::string_view field, geo::Point2& p);
  void operator()(std::string_view field, geo::Vec2& v);
  void operator()(std::string_view field, Pair& p);
  void operator()(std::string_view field, geo::Point3& p);
  void operator()(std::string_view field, geo::Vec3& v);

 private:
  std::pair<double, double> pair(std::string_view field);
  std::array<double, 3> triple(std::string_view field);
  const nlohmann::json& j_;
};

// The schema's visitor that reads a solve figure's fields (the contract's own reading: the same
// errors as `epure solve` gives, "field 'u': expected 2 numbers, got 3").
class FigureReader {
 public:
  explicit FigureReader(const solve::Fields& f) : f_(f) {}
  void operator()(std::string_view field, double& x) { x = f_.number(field); }
  void operator()(std::string_view field, geo::Point2& p) { p = f_.point2(field); }
  void operator()(std::string_view field, geo::Vec2& v) { v = f_.vec2(field); }
  void operator()(std::string_view field, Pair& p) {
    const auto v = f_.numbers<2>(field);
    p = {v[0], v[1]};
  }
  void operator()(std::string_view field, geo::Point3& p) { p = f_.point3(field); }
  void operator()(std::string_view field, geo::Vec3& v) { v = f_.vec3(field); }

 private:
  const solve::Fields& f_;
};

// The schema's visitor that finds its first point or vector field and that field's dimension.
struct FirstPoint {
  std::string_view field;
  int dim = 0;
  template <class T>
  void operator()(std::string_view name, const T&) {
    if (dim) return;
    if constexpr (std::is_same_v<T, geo::Point2> || std::is_same_v<T, geo::Vec2>) field = name, dim = 2;
    if constexpr (std::is_same_v<T, geo::Point3> || std::is_same_v<T, geo::Vec3>) field = name, dim = 3;
  }
};

// The geometry core's answers for an instance, in the order of the kind's questions: what the
// key expects (method.h's own evaluation is checked against it).
class CoreAnswers {
 public:
  CoreAnswers& number(std::string_view field, double x);
  CoreAnswers& point(std::string_view field, geo::Point2 p);
  CoreAnswers& vec(std::string_view field, geo::Vec2 v) { return point(field, {v.x, v.y}); }
  // a point in space: three numbers under the given names ("I.x", "I.y", "I.z")
  CoreAnswers& point(const method::Names3& fields, geo::Point3 p) {
    return number(fields[0], p.x).number(fields[1], p.y).number(fields[2], p.z);
  }
  CoreAnswers& vec(const method::Names3& fields, geo::Vec3 v) { return point(fields, {v.x, v.y, v.z}); }
  CoreAnswers& boolean(std::string_view field, bool b);
  CoreAnswers& choice(std::string_view field, std::string_view word);
  CoreAnswers& faces(std::string_view field, method::FaceMask bits);
  const std::vector<method::Recorded<double>>& answers() const { return answers_; }
  const method::Recorded<double>* find(std::string_view field) const;

 private:
  std::vector<method::Recorded<double>> answers_;
};

// The key's side of an instance: the method's exact run (worked steps and exact forms) and the
// questions asked, with the core's values and the derived tolerances.
struct KeySolution {
  method::Run<method::Exact> run;
  CoreAnswers core;
  Questions questions;
  // A step's (or an answer's) value and exact form, as the key's text shows them: the core's
  // value for an answer the core gives, the method's for an intermediate step.
  double value(std::string_view id) const;
  std::optional<exact::Surd> exact(std::string_view id) const;
  geo::Point2 point(std::string_view id) const;
  std::optional<exact::Surd> exact_x(std::string_view id) const;
  std::optional<exact::Surd> exact_y(std::string_view id) const;
};

// The key's worked steps as the method told them (method.h: Run::tell), each the kind's text
// `<kind>.step.<text>` with the values the run recorded, appended to the key's section.
void replay_steps(render::Section& key_section, const ExerciseContext& ctx, const KeySolution& key,
                  std::string_view kind);

// The statement's data by the schema: a point or vector as "(1, −2)", a number as the datum.
class DataVars {
 public:
  explicit DataVars(const NumberStyle& n) : n_(n) {}
  void operator()(std::string_view field, double x) { vars_.emplace_back(std::string(field), n_.datum(x)); }
  void operator()(std::string_view field, geo::Point2 p) { vars_.emplace_back(std::string(field), n_.point(p.x, p.y)); }
  void operator()(std::string_view field, geo::Vec2 v) { vars_.emplace_back(std::string(field), n_.point(v.x, v.y)); }
  void operator()(std::string_view field, geo::Point3 p) { vars_.emplace_back(std::string(field), n_.point(p.x, p.y, p.z)); }
  void operator()(std::string_view field, geo::Vec3 v) { vars_.emplace_back(std::string(field), n_.point(v.x, v.y, v.z)); }
  TextVars take() { return std::move(vars_); }

 private:
  const NumberStyle& n_;
  TextVars vars_;
};

namespace detail {

// The checks and the questions, shared by every kind (kind_method.cpp).
void check_against_core(std::string_view kind, const method::Run<method::Exact>& run, const CoreAnswers& core);
Questions make_questions(const ExerciseContext& ctx, std::span<const method::QuestionDecl> decls,
                         const method::Run<method::Exact>& run, const method::Run<method::Dual>* dual,
                         const CoreAnswers& core);
std::vector<SheetField> sheet_fields_of(std::span<const method::QuestionDecl> decls);
std::vector<std::string> fields_of(std::span<const method::QuestionDecl> decls);

}  // namespace detail

template <class Kind>
class MethodKind : public ExerciseKind {
 public:
  using Data = typename Kind::Data;

  std::string_view name() const override { return Kind::kName; }
  std::string_view contract_kind() const override { return solve_kind(); }
  std::vector<std::string> fields() const override { return detail::fields_of(Kind::kQuestions); }
  std::vector<SheetField> sheet_fields() const override { return detail::sheet_fields_of(Kind::kQuestions); }
  std::span<const method::QuestionDecl> questions() const override { return Kind::kQuestions; }
  double default_points() const override { return Kind::kPoints; }
  std::span<const std::string_view> mistakes() const override { return Kind::kMistakes; }
  std::span<const std::string_view> roads() const override {
    if constexpr (requires { Kind::kRoads; }) return Kind::kRoads;
    else return {};
  }

  std::any read_instance(const nlohmann::json& instance) const override { return read(instance); }

  std::vector<DataField> data_fields() const override {
    FieldList list;
    const Data d{};
    Kind::schema(list, d);
    return std::move(list.fields);
  }

  // The schema read for its values by one of the visitors above.
  template <class V, class D>
  static void visit_schema(V& visitor, D& d) {
    ValuesOnly<V> values{visitor};
    Kind::schema(values, d);
  }

  // The solve contract: the figure read by the schema, solved and written by the kind's
  // `contract(const Data&, const solve::Fields&, solve::Result&)`; the fields give the numbers
  // as written (solve::Fields::decimal), which the decisions are exact for.
  bool solves(const solve::Fields& figure) const override {
    FirstPoint first;
    const Data d{};
    visit_schema(first, d);
    if (!first.dim) return true;
    const solve::Value* v = figure.find(first.field);
    const bool in_space = v && v->type == solve::Type::array && v->size == 3;
    return in_space == (first.dim == 3);
  }
  void solve_figure(const solve::Fields& figure, solve::Result& result) const override {
    Data d{};
    FigureReader reader(figure);
    visit_schema(reader, d);
    // A line beyond the kernels' exact arithmetic is refused, not answered (solve/number_span.h);
    // the kind's own refusals (a radius ≤ 0, a degenerate figure) say more, and come first.
    static const std::vector<DataField> fields = data_fields();
    double canonical_size = 0;
    if constexpr (requires { Kind::kCanonicalSize; }) canonical_size = Kind::kCanonicalSize;
    std::optional<solve::InputError> beyond;
    try {
      solve::check_number_span(figure.all(), figure, fields, canonical_size);
    } catch (const solve::InputError& e) {
      beyond = e;
    }
    Kind::contract(d, figure, result);
    if (beyond) throw *beyond;
  }

  // A kind's `ExerciseInstance build(const Data&, const ExerciseContext&) const` (the key of
  // drawn data, its branch that of the data) overrides this, and key_of follows from it.
  virtual ExerciseInstance build(const Data&, const ExerciseContext&) const {
    throw std::logic_error(fmt::format("{}: no key for given data", Kind::kName));
  }
  ExerciseInstance key_of(const nlohmann::json& instance, const ExerciseContext& ctx) const override {
    return build(read(instance), ctx);
  }
  // What make() gives for drawn data no earlier sheet holds: the instance built, or, when the
  // context asks for values only (ExerciseContext::sections), its identity and its questions,
  // which every kind takes from the key's solution as they are (key_solution), so that they are
  // the built instance's (tests/exercises/values_only_test.cpp).
  ExerciseInstance made(const Data& d, const ExerciseContext& ctx) const {
    if (ctx.sections) return build(d, ctx);
    ExerciseInstance inst = identity_of(d, ctx);
    inst.questions = key_solution(d, ctx).questions.take_questions();
    return inst;
  }

  std::vector<method::Recorded<method::Traced>> evaluate(const std::any& data, const method::GivenAnswers* given,
                                                         method::Switches switches, int decimals) const override {
    method::Run<method::Traced> run({Kind::kQuestions, decimals, switches, given});
    Kind::method(run, std::any_cast<const Data&>(data));
    return run.answers();
  }
  std::vector<method::Recorded<method::Traced>> evaluate_as_told(const std::any& data, int decimals,
                                                                 const method::GivenAnswers* given = nullptr) const override {
    method::RunOptions options{Kind::kQuestions, decimals, {}, given};
    options.carry_rounded = true;
    method::Run<method::Traced> run(options);
    Kind::method(run, std::any_cast<const Data&>(data));
    return run.answers();
  }

  // The contract's kind of the instance: the kind's own name, unless it says otherwise (the
  // preamble in space is the contract's `vectors` with three components).
  static constexpr std::string_view solve_kind() {
    if constexpr (requires { Kind::kSolveKind; }) return Kind::kSolveKind;
    else return Kind::kName;
  }
  static std::string write(const Data& d) {
    SchemaWriter w(solve_kind());
    visit_schema(w, d);
    return w.finish();
  }
  static Data read(const nlohmann::json& instance) {
    Data d{};
    SchemaReader r(instance);
    visit_schema(r, d);
    return d;
  }

  // Whether the student's carried steps keep every answer within its share (method.h:
  // carried_within): the draws of the long chains reject the data where they do not.
  static bool answers_well_conditioned(const Data& d, int decimals) {
    method::Run<method::Dual> dual({Kind::kQuestions, decimals});
    Kind::method(dual, d);
    return method::carried_within(dual);
  }

  // The method's exact run alone (cheap enough for a draw's constraints: "r² − d² a square").
  static method::Run<method::Exact> exact_run(const Data& d, int decimals = 2) {
    method::Run<method::Exact> exact({Kind::kQuestions, decimals});
    Kind::method(exact, d);
    return exact;
  }

  // Runs the method on the key's data: exact and dual evaluations (the dual one only for the
  // tolerances, when the context asks for them), checked against the core.
  static KeySolution key_solution(const Data& d, const ExerciseContext& ctx) {
    method::Run<method::Exact> exact({Kind::kQuestions, ctx.decimals});
    Kind::method(exact, d);
    std::optional<method::Run<method::Dual>> dual;
    if (ctx.tolerances) {
      dual.emplace(method::RunOptions{Kind::kQuestions, ctx.decimals});
      Kind::method(*dual, d);
    }
    const CoreAnswers core = Kind::core(d);
    detail::check_against_core(Kind::kName, exact, core);
    Questions q = detail::make_questions(ctx, Kind::kQuestions, exact, dual ? &*dual : nullptr, core);
    return KeySolution{std::move(exact), core, std::move(q)};
  }

  // An instance of drawn data begun as every figure kind begins it: its identity, the key's
  // solution (its questions taken into the instance), the sheet (title, statement with the data
  // by the schema, the question's figure, the answer fields) and the key's title and data.
  // `sheet_figure` makes the question's figure from the key's solution. The kind then adds its
  // worked steps, its figure and the answer lines (add_lines) to inst.key.
  struct Begun {
    ExerciseInstance inst;
    KeySolution key;
  };
  template <class SheetFigure>
  static Begun begin_sections(const Data& d, const ExerciseContext& ctx, SheetFigure&& sheet_figure) {
    const auto& T = ctx.texts;
    Begun b{begin_instance(d, ctx), key_solution(d, ctx)};
    b.inst.questions = b.key.questions.take_questions();
    DataVars vars(ctx.numbers);
    visit_schema(vars, d);
    const TextVars data = vars.take();
    const std::string kind(Kind::kName);
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      b.inst.sheet = begin_sheet_section(ctx, kind + ".title");
      b.inst.sheet.add(render::Paragraph{T.format(kind + ".statement", data)});
      b.inst.sheet.add(sheet_figure(b.key));
      add_fields(b.inst.sheet, b.key.questions);
    }
    b.inst.key = begin_key_section(ctx, kind + ".title");
    b.inst.key.add(render::Paragraph{T.format(kind + ".data", data)});
    return b;
  }

  // The instance of drawn data, its sections laid out as every figure kind lays them
  // (begin_sections), the key's worked steps those the method told, then `after` (more of the
  // kind's steps), the construction's figure and the answers. `sheet_figure` and `key_figure`
  // make the figures from the key's solution (the drawing reads the run's values).
  template <class SheetFigure, class KeyFigure>
  static ExerciseInstance assemble(const Data& d, const ExerciseContext& ctx, SheetFigure&& sheet_figure,
                                   KeyFigure&& key_figure, std::span<const std::string_view> after = {}) {
    Begun b = begin_sections(d, ctx, sheet_figure);
    replay_steps(b.inst.key, ctx, b.key, Kind::kName);
    for (std::string_view step : after)
      b.inst.key.add(render::Paragraph{ctx.texts.format(fmt::format("{}.step.{}", Kind::kName, step))});
    b.inst.key.add(key_figure(b.key));
    add_lines(b.inst.key, b.key.questions);
    return std::move(b.inst);
  }

  // The identity of a drawn instance and, unless an earlier sheet holds it, its key solution
  // and the common parts of the ExerciseInstance (the kind adds the sections).
  static ExerciseInstance begin_instance(const Data& d, const ExerciseContext& ctx) {
    ExerciseInstance inst = identity_of(d, ctx);
    inst.solution = solve_instance(inst.instance);
    return inst;
  }
  // A drawn instance's identity alone: its place, number, kind, branch, data (as a solve input)
  // and fingerprint.
  static ExerciseInstance identity_of(const Data& d, const ExerciseContext& ctx) {
    ExerciseInstance inst;
    inst.n = ctx.n;
    inst.number = number_of(ctx);
    inst.kind = std::string(Kind::kName);
    inst.branch = ctx.branch;
    inst.instance = write(d);
    inst.fingerprint = fingerprint(inst.instance);
    return inst;
  }
};

// The one instance of a kind's class, for its accessor in the registry (registry.cpp).
template <class KindClass>
const ExerciseKind& the_kind() {
  static const KindClass kind;
  return kind;
}

}  // namespace epure::kinds
