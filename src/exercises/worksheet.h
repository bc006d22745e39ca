#pragma once
// A set of worksheets: the spec, a seed, and sheet after sheet its exercises, each drawn from
// (seed, sheet index, exercise slot, attempt) alone. A sheet never repeats an instance an earlier
// sheet of the set drew for the same exercise (a collision, rare, moves to the next attempt), so
// sheet i depends on sheets 0..i−1 only through those fingerprints: rebuilding a sheet from its
// id replays them, and generating in parallel draws attempt 0 everywhere first, then settles the
// collisions in index order — the same sheets either way.
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "exercises/exercise.h"
#include "exercises/schedule.h"
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

  // The branch exercise `slot` of sheet `index` draws (the schedule is sequential: cheap for
  // increasing indices).
  std::string branch(int index, int slot) { return schedules_[slot].at(index); }
  // One exercise of one sheet at one attempt: a pure function of its arguments (thread-safe).
  // An instance whose fingerprint is in `taken` comes back unbuilt (identity only).
  ExerciseInstance draw(int index, int slot, int attempt, const std::string& branch,
                        const std::unordered_set<std::uint64_t>* taken = nullptr, int widening = 0) const;

  // The next sheet of the set, in index order, with collisions settled. `first_attempts`, when
  // given, holds attempt 0 of each slot already drawn (in parallel) for this index.
  Sheet next(std::vector<ExerciseInstance>* first_attempts = nullptr);
  int next_index() const { return next_index_; }

  // Rebuilds the sheet a given id names: refuses an id of another draw version or seed.
  Sheet rebuild(const SheetId& id);

  // The printed documents of a sheet: the student's sheet and its answer key.
  render::Document sheet_document(const Sheet& sheet) const;
  render::Document key_document(const Sheet& sheet) const;

 private:
  ExerciseContext context(int slot, int n, const std::string& branch) const;

  WorksheetSpec spec_;
  std::uint64_t seed_;
  std::string language_;
  std::vector<BranchSchedule> schedules_;
  std::vector<std::unordered_set<std::uint64_t>> used_;  // fingerprints per slot
  int next_index_ = 0;
};

}  // namespace epure
