#pragma once
// An exercise kind is one unit: it draws a random, well-posed instance under the spec's
// constraints, solves it with the geometry core, and says what is asked (questions with their
// expected values, exact forms, tolerances and points), what the student sees (the sheet's
// section: statement, data diagram, answer fields) and what the key shows (worked steps, the
// construction diagram, the answers). Kinds know nothing of files or backends.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <variant>
#include <vector>

#include <any>
#include <span>

#include <nlohmann/json_fwd.hpp>

#include "exercises/data_field.h"
#include "exercises/method.h"
#include "exercises/numbers.h"
#include "exercises/rng.h"
#include "exercises/spec.h"
#include "exercises/texts.h"
#include "render/document.h"

namespace epure::solve {
class Fields;
class Result;
}  // namespace epure::solve

namespace epure {

// How close an answer must be to earn its points. Recorded per question in key.json, so that
// grading applies exactly the rule the generator derived.
struct ToleranceRule {
  enum class Kind {
    exact,    // strings, booleans, face sets: equal (sets in any order)
    isclose,  // |given − expected| ≤ max(rel·|expected|, abs)
    distance  // the point (group) given is within abs of the expected point, as a whole
  } kind = Kind::exact;
  double rel = 0;
  double abs = 0;
  // Follow-through: how far a value computed from the student's own earlier answers may lie from
  // what those answers give, as they are written (to `decimals` decimals) while the student went
  // on with 4 significant digits (method.h: follow_tolerances). 0: abs.
  double follow_abs = 0;
  std::string why;  // how the numbers were derived, for the key
};

using Expected = std::variant<double, bool, std::string, std::vector<std::string>>;

struct Question {
  std::string field;  // as in the solve contract, coordinates as .x/.y: "t", "P.x", "faces", "Ac.y"
  Expected expected;
  std::optional<std::string> exact;         // machine form ("1/4", "(5-2*sqrt(2))/3")
  std::optional<std::string> exact_pretty;  // for people ("(5 − 2√2)/3")
  ToleranceRule tolerance;
  double points = 1;
  std::string point_group;  // "P" for P.x and P.y: a point marked coordinate by coordinate,
                            // or as a whole when the rule is `distance`
};

struct ExerciseInstance {
  int n = 0;             // place on the sheet, 1-based
  std::string number;    // the exercise's number, starting its questions' ids (exercise_id)
  std::string kind;
  std::string branch;    // which case this instance shows ("between", "miss", …)
  std::string instance;  // the solve input, JSON text
  std::string solution;  // the solve output for it, JSON text
  std::vector<Question> questions;
  render::Section sheet;  // what the student gets
  render::Section key;    // the worked solution
  std::uint64_t fingerprint = 0;  // identity of the drawn data, for "no two sheets share one"
};

// What a kind needs to make one instance.
struct ExerciseContext {
  int n;                       // place on the sheet
  const ExerciseSpec& spec;    // kind, difficulty, branch weights, points, constraints
  const Texts& texts;
  NumberStyle numbers;
  int decimals;                // students round answers to this many decimals
  std::string branch;          // the branch to draw (chosen by the sheet schedule)
  // Fingerprints of the instances earlier sheets of the set hold, or nullptr: a drawn instance
  // found here comes back unbuilt (see already_taken), since the set will draw again anyway.
  const std::unordered_set<std::uint64_t>* taken = nullptr;
  // 0 for the usual ranges of data. When a large set has used up every instance a kind's usual
  // ranges hold (ray/square with integer data: about 4,000), the set asks again with 1, 2, …:
  // a kind with a small pool then draws from wider ranges. Sheets drawn before that point are
  // the same as without it.
  int widening = 0;
  // What the sheet calls it: "Exercise 2", or the spec's heading ("Preamble"). Empty: "Exercise n".
  std::string label{};
  // The exercise's number, starting its questions' ids ("3.3" asks 3.3.t). Empty: n.
  std::string number{};
  // Whether to build the sheet's section too; false for the explorer's views, which show the key
  // only (ExerciseInstance::sheet is then left empty, and its questions too: the key's answer
  // lines are all a view shows of them).
  bool sheet = true;
  // Whether to derive the questions' tolerances (the method's Dual run: how far each answer moves
  // when a student rounds an intermediate); false for the explorer's views, which mark nothing
  // (ExerciseInstance::questions then carry a zero tolerance; the key's text never shows one).
  bool tolerances = true;
  // Whether to build the instance at all past its identity and questions; false when only the
  // answers' values are wanted (the combs' reach: WorksheetSet::measure_combs draws every sheet
  // of the set once before the set is drawn for its pages). The instance then carries its
  // identity and its questions (their tolerances as `tolerances` says), no solution, no sections.
  bool sections = true;
};

// An answer field of the printed sheet: the same for every branch of a kind, so that the sheet
// never tells a student which case they have (a "why not?" field only on sheets that miss would).
struct SheetField {
  std::string field;  // "t", "I", "reason"
  render::AnswerField::Kind kind;
  std::vector<std::string> choices;  // contract words ("behind", "miss") or face names
};

// A point or vector answer that a feedback sheet draws on the key's diagram.
struct DrawnField {
  std::string_view group;   // "P", "I", "N", "Ac"
  int panel = 0;            // which panel of the key's scene (0: the world frame)
  std::string_view anchor;  // for a vector: the group of the point it is drawn from ("I")
  std::string_view name;    // as the key's figure names it ("\\vec{N}", "A_{c}"); empty: the group
};

class ExerciseKind {
 public:
  virtual ~ExerciseKind() = default;
  virtual std::string_view name() const = 0;
  // The solve contract's kind of its instances: its name, unless the contract says otherwise
  // (the preamble in space writes its instances as the contract's `vectors`, with three components).
  virtual std::string_view contract_kind() const { return name(); }
  // The branches the kind can draw, and their default weights: under the defaults a class set
  // of 30 shows every branch (the schedule spreads them across consecutive sheets).
  virtual std::vector<std::pair<std::string, double>> default_branches() const = 0;
  // The constraint names the spec may set for this kind, with their defaults.
  virtual std::map<std::string, double> default_constraints() const { return {}; }
  // What an exercise of this kind adds to the sheet's total when the spec does not set its
  // points (exercises/points.h): the sheet's questions share that total by their work, so the
  // exercise's own worth follows the branch drawn while every sheet of a set is worth the same.
  virtual double default_points() const = 0;
  // The question fields this kind can ask (for validating a spec's points table).
  virtual std::vector<std::string> fields() const = 0;
  // The sheet's answer fields, whatever the branch; empty: the fields asked (a kind whose
  // questions do not depend on the branch).
  virtual std::vector<SheetField> sheet_fields() const { return {}; }
  // Draws until the constraints hold (throws std::runtime_error after too many attempts, naming
  // the constraint that could not be met).
  virtual ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const = 0;

  // ---- the kind model (kind_method.h): what grading and the exports read from the kind's one
  // method.
  // The questions the kind can ask, in the sheet's order, with their default weights.
  virtual std::span<const method::QuestionDecl> questions() const { return {}; }
  // The named mistakes its method declares, in the order grading tries them.
  virtual std::span<const std::string_view> mistakes() const { return {}; }
  // The other right roads its method declares (method.h: Run::road), by name.
  virtual std::span<const std::string_view> roads() const { return {}; }
  // The point and vector answers a feedback sheet draws on the key's diagram.
  virtual std::vector<DrawnField> drawn() const { return {}; }
  // The instance read from a solve input (key.json's "instance"); throws std::runtime_error
  // naming the field.
  virtual std::any read_instance(const nlohmann::json& instance) const = 0;
  // The instance's data fields in the schema's order, each with its role (data_field.h): what
  // the explorer's handles hold and how a drag moves them.
  virtual std::vector<DataField> data_fields() const = 0;
  // The key of an instance given from outside (a solve input: key.json's "instance", the
  // explorer's dragged figure), in the branch its data falls in: statement, worked steps,
  // construction diagram and answers, as a sheet's key shows them. Throws std::runtime_error
  // (naming the field) for an instance the kind cannot read or solve.
  virtual ExerciseInstance key_of(const nlohmann::json& instance, const ExerciseContext& ctx) const = 0;
  // The solve contract (solve/solve.h) for a figure of contract_kind(): whether this kind is the
  // one that solves it (of two kinds sharing a contract kind, the one of the figure's dimension:
  // the preamble in space is the contract's `vectors` with u in ℝ³), and the figure read by the
  // kind's schema, solved by the geometry core, its result written. Throws solve::InputError
  // naming the field, or geo::DegenerateFigure.
  virtual bool solves(const solve::Fields& figure) const = 0;
  virtual void solve_figure(const solve::Fields& figure, solve::Result& result) const = 0;
  // The method run on an instance read by read_instance: with `given`, on the student's own
  // answers where they gave them; with a mistake switched on, making it; with a road, taking
  // that other right road (roads()). The answers in the order the method reaches them, each
  // with the answers it was computed from.
  virtual std::vector<method::Recorded<method::Traced>> evaluate(const std::any& data,
                                                                 const method::GivenAnswers* given,
                                                                 method::Switches switches, int decimals) const = 0;
  // The method as a student works it by the sheet's instruction: each step carried to
  // method::kCarriedDigits significant digits (the answers not yet rounded for writing), going
  // on from the student's own carried answers where `given` has them. What the tolerances (and
  // follow-through's) must accept; tests/exercises/tolerance_property_test.cpp and
  // tests/grading/kind_model_test.cpp hold them to it.
  virtual std::vector<method::Recorded<method::Traced>> evaluate_as_told(const std::any& data, int decimals,
                                                                         const method::GivenAnswers* given = nullptr) const = 0;
};

// All kinds, in the course's order; nullptr for an unknown name.
const ExerciseKind* find_kind(std::string_view name);
std::vector<const ExerciseKind*> all_kinds();

}  // namespace epure
