#pragma once
// What every exercise kind does the same way: writing its solve input, asking the contract for
// the solution, turning answers into questions (with exact forms and derived tolerances),
// answer fields for the sheet and answer lines for the key. A kind only says what is specific
// to it: how to draw, the method, the texts, the diagrams.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exercises/exact.h"
#include "exercises/exercise.h"
#include "exercises/method.h"
#include "exercises/tolerance.h"
#include "geometry/box_faces.h"
#include "geometry/vec.h"
#include "render/scene.h"

namespace epure::kinds {

// The instance as a solve input, written field by field in the contract's names.
class InstanceWriter {
 public:
  explicit InstanceWriter(std::string_view kind);
  InstanceWriter& number(std::string_view field, double x);
  InstanceWriter& point(std::string_view field, geo::Point2 p);
  InstanceWriter& vec(std::string_view field, geo::Vec2 v);
  InstanceWriter& pair(std::string_view field, double a, double b);
  InstanceWriter& triple(std::string_view field, double a, double b, double c);
  std::string finish();

 private:
  std::string text_;
  bool first_ = true;
};

// The solve output for an instance: the one `epure solve` prints for it. Throws
// std::logic_error if the contract refuses the instance (a generator bug).
std::string solve_instance(std::string_view instance);

// 64-bit FNV-1a of the instance text: equal data, equal fingerprint.
std::uint64_t fingerprint(std::string_view text);

// The set's collision check, made before the costly part of an instance (solution, exact forms,
// texts, scenes): when an earlier sheet already holds this instance (ctx.taken), only its
// identity (instance text and fingerprint) comes back, and the set draws again. Nothing else
// changes: the random draws are the same, so are the sheets.
std::optional<ExerciseInstance> already_taken(const ExerciseContext& ctx, std::string instance);

// Collects the questions of one instance together with the sheet's answer fields and the key's
// answer lines, in the order they are asked.
class Questions {
 public:
  explicit Questions(const ExerciseContext& ctx);

  // A numeric answer; `exact` when the instance has an exact form of it.
  void number(std::string_view field, double value, double abs_tolerance,
              std::optional<exact::Surd> exact = std::nullopt);
  // A 2D point asked as .x and .y (marked separately, or as a whole when the spec says so).
  void point(std::string_view field, geo::Point2 value, double abs_x, double abs_y,
             std::optional<exact::Surd> exact_x = std::nullopt,
             std::optional<exact::Surd> exact_y = std::nullopt);
  void vector(std::string_view field, geo::Vec2 value, double abs_x, double abs_y,
              std::optional<exact::Surd> exact_x = std::nullopt,
              std::optional<exact::Surd> exact_y = std::nullopt) {
    point(field, {value.x, value.y}, abs_x, abs_y, exact_x, exact_y);
  }
  void boolean(std::string_view field, bool value);
  // One of `choices` (contract words: "before", "miss", …), shown localised.
  void choice(std::string_view field, std::string_view value, const std::vector<std::string>& choices);
  // A set of face names ("+x", "-y"), to tick among `all`.
  void faces(std::string_view field, const std::vector<std::string>& value,
             const std::vector<std::string>& all);

  // The kind's own weight of a question (its QuestionDecl), when the spec does not set one.
  void default_weight(std::string_view field, double weight) { default_weights_.emplace_back(field, weight); }

  std::vector<Question> take_questions() { return std::move(questions_); }
  // Fields for the sheet and lines for the key, in order.
  const std::vector<render::AnswerField>& fields() const { return fields_; }
  const std::vector<render::AnswerLine>& lines() const { return lines_; }
  const ExerciseContext& context() const { return ctx_; }

 private:
  // Whether the questions and the sheet's fields are wanted, or (the explorer's views, which
  // show the key only) the key's answer lines alone.
  bool marking() const { return ctx_.sheet; }
  const QuestionSpec* spec_for(std::string_view field) const;
  double points_for(std::string_view field) const;
  std::string id(std::string_view field) const;
  std::string prompt(std::string_view field) const;
  std::string answer_text(double value, const std::optional<exact::Surd>& exact) const;

  const ExerciseContext& ctx_;
  std::vector<std::pair<std::string_view, double>> default_weights_;
  std::vector<Question> questions_;
  std::vector<render::AnswerField> fields_;
  std::vector<render::AnswerLine> lines_;
};

// The conversion every kind needs between the core's points and the scene's.
inline render::P2 p2(geo::Point2 p) { return {p.x, p.y}; }
inline render::P2 p2(geo::Vec2 v) { return {v.x, v.y}; }

// A view box around the given points with a margin, at least `min_size` wide and high, snapped
// outward to whole grid steps.
render::Box view_around(const std::vector<render::P2>& points, double margin, double min_size = 4,
                        double step = 1);

// Draws until `ok` accepts or `attempts` run out; throws std::runtime_error naming `what`.
template <class Draw>
auto draw_until(int attempts, std::string_view what, Draw&& draw) {
  for (int i = 0; i < attempts; ++i)
    if (auto instance = draw()) return *instance;
  throw std::runtime_error(std::string("could not draw an instance meeting the constraints: ") +
                           std::string(what));
}

// The two sections every exercise has, begun with their headings.
render::Section begin_sheet_section(const ExerciseContext& ctx, std::string_view title_key);
render::Section begin_key_section(const ExerciseContext& ctx, std::string_view title_key);

// Adds the answer fields (sheet: the kind's sheet_fields() when it has them, the same for every
// branch) or the answer lines (key: what this instance asks).
void add_fields(render::Section& s, const Questions& q);

// A side or face as printed ("−x" with U+2212), and the tick options of a candidate-sides field:
// every name, then "none".
std::string face_label(std::string_view name);
std::vector<std::string> face_options(const ExerciseContext& ctx, const std::vector<std::string>& names);
void add_lines(render::Section& s, const Questions& q);

// A constraint's value: the spec's override or the kind's default.
double constraint(const ExerciseContext& ctx, const ExerciseKind& kind, const std::string& name);

}  // namespace epure::kinds

namespace epure::kinds {

// The exact rational a datum denotes, when it has at most 6 decimals (data on a grid always do).
using method::rational_of;

// A value as a worked step shows it: its exact form when short, with its decimal value when that
// is not the same number written otherwise ("37/5 = 7.4", "−6√5/5 ≈ −2.68"); the decimal alone
// when the exact form is long (one-decimal data give fractions like 376996/25925).
std::string step_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& e);
std::string step_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                       const std::optional<exact::Surd>& ey);

// A value as the key's worked steps show it: its exact form when it has a short one, else
// rounded ("1/4", "5 − 2√2", "≈ 2.17" → "2.17").
std::string shown(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact);
std::string shown_point(const ExerciseContext& ctx, geo::Point2 p,
                        const std::optional<exact::Surd>& ex, const std::optional<exact::Surd>& ey);

// A random coordinate on the difficulty's grid: integers for easy and standard, one decimal for
// hard.
double grid_value(Rng& rng, double lo, double hi, Difficulty d);

// A worked step's result with its relation sign, as the key writes it after a formula: "= 5",
// "= 1/4 = 0.25", "= √13 ≈ 3.61", or "≈ 2.17" when there is no short exact form.
std::string equals_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact);

// Whether the value is exactly a decimal of at most `decimals` places (per its exact form): a
// student writes it out, and does not round it on the way. Without an exact form, false.
bool terminates_within(const std::optional<exact::Surd>& exact, int decimals);

// A worked step's point with its relation sign: "= (1.5, 2)" when both coordinates stop within
// the asked decimals, else "≈ (1.43, 2.17)".
std::string equals_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                         const std::optional<exact::Surd>& ey);

}  // namespace epure::kinds
