#pragma once
// A set of worksheets: the spec, a seed, and sheet after sheet its exercises, each drawn from
// (seed, sheet index, exercise slot, attempt) alone. A sheet never repeats an instance an earlier
// sheet of the set drew for the same exercise (a collision, rare, moves to the next attempt), so
// sheet i depends on sheets 0..i−1 only through those fingerprints: rebuilding a sheet from its
// id replays them, and generating in parallel draws attempt 0 everywhere first, then settles the
// collisions in index order — the same sheets either way.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "exercises/exercise.h"
#include "exercises/balance.h"
#include "exercises/sheet_id.h"
#include "exercises/spec.h"
#include "render/document.h"

namespace epure {
class Texts;
// What the sheet calls the exercise in `slot`: the spec's heading for it in the texts' language,
// else "Exercise n" with n counted over the exercises that have no heading (spec.h).
std::string exercise_label(const WorksheetSpec& spec, std::size_t slot, const Texts& texts);
}  // namespace epure

namespace epure {

struct Sheet {
  SheetId id;
  std::vector<ExerciseInstance> exercises;
};

struct SetOptions {
  std::optional<std::string> language;     // overrides the spec's
  std::optional<Difficulty> difficulty;    // overrides every exercise's
  std::optional<std::string> page;         // "A4" or "letter": overrides the spec's
};

class WorksheetSet {
 public:
  // Draws tried for a branch before a collision-bound sheet turns to the kind's next branch.
  static constexpr int kAttemptsPerBranch = 64;
  static constexpr int kMaxWidening = 3;  // see ExerciseContext::widening

  // Throws SpecError for a seed out of range or an unknown language.
  WorksheetSet(WorksheetSpec spec, std::uint64_t seed, const SetOptions& options = {});

  const WorksheetSpec& spec() const { return spec_; }
  std::uint64_t seed() const { return seed_; }
  const std::string& language() const { return language_; }

  // The branch exercise `slot` of sheet `index` draws: the exercise's schedule, balanced so that
  // the sheets of a block ask about the same work (balance.h). Cheap for increasing indices.
  std::string branch(int index, int slot);
  // The work each branch of exercise `slot` asks (its questions' weights, measured on one
  // instance of each), in the order of the exercise's branch weights; empty for an exercise whose
  // spec fixes its points (its work earns nothing from the sheet's pool).
  const std::vector<std::pair<std::string, double>>& branch_work(int slot);
  // What the exercises whose spec does not fix their points share on every sheet: their kinds'
  // default points added up (points.h).
  double pool_points() const { return pool_; }
  // The sheet's total: the pool and every fixed exercise's points.
  double sheet_points() const;
  // One exercise of one sheet at one attempt: a pure function of its arguments (thread-safe).
  // An instance whose fingerprint is in `taken` comes back unbuilt (identity only). Its questions'
  // points are their weights: the sheet's points are shared once the sheet is drawn (next()).
  ExerciseInstance draw(int index, int slot, int attempt, const std::string& branch,
                        const std::unordered_set<std::uint64_t>* taken = nullptr, int widening = 0) const;

  // The next sheet of the set, in index order, with collisions settled. `first_attempts`, when
  // given, holds attempt 0 of each slot already drawn (in parallel) for this index.
  Sheet next(std::vector<ExerciseInstance>* first_attempts = nullptr);
  int next_index() const { return next_index_; }

  // Rebuilds the sheet a given id names: refuses an id of another draw version or seed.
  Sheet rebuild(const SheetId& id);

  // The combs of the sheets' number fields (one character per cell, a scan reads them): how many
  // integer cells each field has, by its id on the sheet ("2.t"; "3.P" for both coordinates of a
  // point). The same for every instance of a question, so that the comb does not give the answer
  // away: what the set's answers reach (comb_reach over its sheets), never one instance's value.
  // A field not in the map gets kDefaultIntegerCells.
  using CombCells = std::map<std::string, int, std::less<>>;
  static constexpr int kDefaultIntegerCells = 3;
  // Sheets drawn to measure the reach, at least: a small set's combs are those of its first 64
  // sheets, so they do not depend on --sheets (nor tell one instance's digits).
  static constexpr int kReachSheets = 64;
  // Widens `cells` to hold the integer digits of every number answer of `sheet`, as written
  // with the set's decimals.
  void comb_reach(const Sheet& sheet, CombCells& cells) const;
  void set_comb_cells(CombCells cells) { comb_cells_ = std::move(cells); }
  // The combs of a fresh set's first `sheets` sheets (at least kReachSheets), drawn on a copy
  // for their answers only (ExerciseContext::sections), set on this one, as `epure generate`
  // does.
  void measure_combs(int sheets = 0);

  // The printed documents of a sheet: the student's sheet and its answer key.
  render::Document sheet_document(const Sheet& sheet) const;
  render::Document key_document(const Sheet& sheet) const;

 private:
  ExerciseContext context(int slot, int n, const std::string& branch) const;
  void measure_work();

  WorksheetSpec spec_;
  std::uint64_t seed_;
  std::string language_;
  std::vector<BranchSchedule> schedules_;
  // measured at the first branch() (a set used to rebuild one exercise never pays for it)
  std::optional<std::vector<std::vector<std::pair<std::string, double>>>> work_;
  std::optional<BranchBalance> balance_;
  std::vector<std::optional<double>> fixed_points_;  // per slot: the spec's `points`
  double pool_ = 0;
  std::vector<std::unordered_set<std::uint64_t>> used_;  // fingerprints per slot
  int next_index_ = 0;
  CombCells comb_cells_;
  // draws instances with their identity and questions only (ExerciseContext::sections): the
  // probe set of measure_combs
  bool values_only_ = false;
};

}  // namespace epure
