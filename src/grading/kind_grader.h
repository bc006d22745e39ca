#pragma once
// What marking asks of an exercise kind beyond the key's per-question rule: how its answers
// depend on one another (so that a later answer right from the student's own wrong earlier value
// earns follow-through credit, as on paper) and the classic mistakes of its method. Every kind
// is written as one method and graded by the method grader (method_grader.h), which reads both
// from the kind's method itself.
#include <nlohmann/json_fwd.hpp>

#include <any>
#include <string_view>
#include <vector>

#include "exercises/exercise.h"

namespace epure::grading {

class ExerciseReview;

class KindGrader {
 public:
  virtual ~KindGrader() = default;
  virtual std::string_view kind() const = 0;
  // Reads the instance once, when the key is loaded. Throws std::runtime_error naming the
  // field for an instance that is not a valid solve input of the kind.
  virtual std::any prepare(const nlohmann::json& instance) const = 0;
  // Called for an exercise with at least one wrong answer: credits follow-through and names
  // mistakes through `review`, in the order of the method.
  virtual void review(const std::any& prepared, ExerciseReview& review) const = 0;
  // The mistake codes this kind can name.
  virtual std::vector<std::string_view> mistakes() const = 0;
  // The point and vector answers a feedback sheet draws.
  virtual std::vector<DrawnField> drawn() const { return {}; }
};

// The grader of a kind, or null for an unknown kind (its answers are marked by the key's rules
// alone). Defined in method_grader.cpp.
const KindGrader* find_grader(std::string_view kind);
std::vector<const KindGrader*> all_graders();

}  // namespace epure::grading
