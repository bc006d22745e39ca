// The spec TOML and its semantic checks (src/exercises/spec.cpp): a SpecError naming the file
// (and line and key where there is one), never another exception; a spec read is one a
// WorksheetSet could draw from: known kinds, weights ≥ 0, at most kMaxExercises exercises; and
// the first sheet drawn from it (its constraints applied) has every exercise, its points shared
// out exactly, and an instance whose solve output is the solution it carries — or a SpecError.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "exercises/exercise.h"
#include "exercises/spec.h"
#include "exercises/worksheet.h"
#include "fuzz_support.h"
#include "solve/solve.h"

using namespace epure;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  WorksheetSpec spec;
  try {
    spec = parse_spec(text, "fuzz.toml");
  } catch (const SpecError& e) {
    const std::string_view what = e.what();
    fuzz::check(fuzz::starts_with(what, "fuzz.toml:") && what.size() > 11, "a spec error does not name the file", what);
    return 0;
  }
  fuzz::check(spec.text == text, "the spec's text is not the file's");
  fuzz::check(!spec.exercises.empty() && spec.exercises.size() <= kMaxExercises,
              "a spec read with no exercise or more than kMaxExercises");
  fuzz::check(spec.decimals >= 0 && spec.decimals <= 6, "decimals out of range");
  fuzz::check(!spec.scale || (*spec.scale > 0 && std::isfinite(*spec.scale)), "scale not positive");
  for (const auto& e : spec.exercises) {
    const ExerciseKind* kind = find_kind(e.kind);
    fuzz::check(kind != nullptr, "a spec read with an unknown kind", e.kind);
    double total = 0;
    for (const auto& [name, w] : e.branches) {
      fuzz::check(w >= 0 && std::isfinite(w), "a branch weight < 0 or not finite", name);
      total += w;
    }
    fuzz::check(e.branches.empty() || total > 0, "branches given, none with a positive weight");
    fuzz::check(!e.points || (*e.points >= 0 && std::isfinite(*e.points)), "points < 0");
    for (const auto& [name, q] : e.questions) {
      fuzz::check(!q.points || *q.points >= 0, "question points < 0", name);
      fuzz::check(!q.rel || *q.rel >= 0, "rel < 0", name);
      fuzz::check(!q.abs || *q.abs >= 0, "abs < 0", name);
    }
  }
  // Read again from its own text: the same spec (parsing is a function of the text).
  const WorksheetSpec again = parse_spec(spec.text, "fuzz.toml");
  fuzz::check(again.exercises.size() == spec.exercises.size() && again.title == spec.title &&
                  again.language == spec.language,
              "the same text read twice gives two specs");
  // The first sheet of a set drawn from it, under a seed taken from the text.
  std::uint64_t seed = 1469598103934665603ull;
  for (unsigned char c : text) seed = (seed ^ c) * 1099511628211ull;
  seed &= kMaxSeed;
  Sheet sheet;
  double sheet_points = 0;
  try {
    WorksheetSet set(spec, seed);
    sheet = set.next();
    sheet_points = set.sheet_points();
  } catch (const SpecError& e) {
    fuzz::check(std::string_view(e.what()).size() > 0, "an empty spec error");
    return 0;
  }
  fuzz::check(sheet.exercises.size() == spec.exercises.size(), "a sheet lost an exercise");
  // Work-fair points (points.h): an exercise with `points` in the spec is worth exactly that;
  // the others share the rest of the sheet's total by work, so only the sheet's sum is fixed.
  double sheet_total = 0;
  for (std::size_t i = 0; i < sheet.exercises.size(); ++i) {
    const ExerciseInstance& ex = sheet.exercises[i];
    const ExerciseSpec& es = spec.exercises[i];
    fuzz::check(ex.kind == es.kind && ex.n == static_cast<int>(i) + 1, "a sheet's exercise is not the spec's", ex.kind);
    double total = 0;
    for (const auto& q : ex.questions) {
      fuzz::check(q.points >= 0 && std::isfinite(q.points), "a question's points < 0", ex.kind);
      total += q.points;
    }
    sheet_total += total;
    if (es.points)
      fuzz::check(std::fabs(total - *es.points) <= 1e-9 * std::max(1.0, *es.points),
                  "the questions' points do not add up to the exercise's fixed points",
                  fmt::format("{}: {} vs {}", ex.kind, total, *es.points));
    fmt::memory_buffer out;
    const std::string error = solve::solve_line(ex.instance, out);
    fuzz::check(error.empty(), "a drawn instance is not a valid solve input", ex.instance + "\n" + error);
    fuzz::check(std::string_view(out.data(), out.size()) == ex.solution, "an instance's solution is not its solve output",
                ex.instance + "\n" + ex.solution + "\n" + std::string(out.data(), out.size()));
  }
  fuzz::check(std::fabs(sheet_total - sheet_points) <= 1e-9 * std::max(1.0, sheet_points),
              "the questions' points do not add up to the sheet's", fmt::format("{} vs {}", sheet_total, sheet_points));
  return 0;
}
