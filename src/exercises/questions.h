#pragma once
// The questions of one instance, collected with the sheet's answer fields and the key's answer
// lines (exact forms, derived tolerances, points), and the fields and lines added to sections.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exercises/exact.h"
#include "exercises/exercise.h"
#include "exercises/tolerance.h"
#include "geometry/vec.h"
#include "render/scene.h"

namespace epure::kinds {

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
  // The follow-through tolerance of a numeric answer asked before ("t", "I.x"): kept where it is
  // wider than the answer's own and the spec does not set the tolerance.
  void follow(std::string_view field, double follow_abs);
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
  // A question whose answer is marked equal or not (a boolean, a choice, a set of faces).
  void ask_exactly(std::string_view field, Expected value);
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

// Adds the answer fields (sheet: the kind's sheet_fields() when it has them, the same for every
// branch) or the answer lines (key: what this instance asks).
void add_fields(render::Section& s, const Questions& q);

// A side or face as printed ("−x" with U+2212), and the tick options of a candidate-sides field:
// every name, then "none".
std::string face_label(std::string_view name);
std::vector<std::string> face_options(const ExerciseContext& ctx, const std::vector<std::string>& names);
// What each of face_options' boxes stands for in the answers spreadsheet: the names, then "none".
std::vector<std::string> face_values(const std::vector<std::string>& names);
void add_lines(render::Section& s, const Questions& q);

}  // namespace epure::kinds
