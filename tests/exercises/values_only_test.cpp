// An instance drawn for its values only (ExerciseContext::sections = false: what
// WorksheetSet::measure_combs draws to size the combs) is the built instance's identity and
// questions, for every kind, branch and difficulty: the combs it measures are those of the
// sheets printed.
#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <variant>

#include "exercises/exercise.h"
#include "exercises/kind_support.h"
#include "exercises/texts.h"

using namespace epure;

namespace {

// The same computation gives the same bits: a double is compared bit for bit, not within a
// tolerance.
bool same(const Expected& a, const Expected& b) {
  if (a.index() != b.index()) return false;
  if (const auto* x = std::get_if<double>(&a))
    return std::bit_cast<std::uint64_t>(*x) == std::bit_cast<std::uint64_t>(std::get<double>(b));
  return a == b;
}

}  // namespace

TEST_CASE("values only: the built instance's identity and questions, without its sections") {
  const Difficulty levels[] = {Difficulty::easy, Difficulty::standard, Difficulty::hard};
  int compared = 0;
  for (const ExerciseKind* kind : all_kinds()) {
    CAPTURE(kind->name());
    for (const auto& [name, weight] : kind->default_branches()) {
      if (weight <= 0) continue;
      const std::string branch = name;
      CAPTURE(branch);
      for (Difficulty level : levels)
        for (int seed = 1; seed <= 12; ++seed) {
          CAPTURE(static_cast<int>(level));
          CAPTURE(seed);
          ExerciseSpec spec;
          spec.kind = std::string(kind->name());
          spec.difficulty = level;
          const ExerciseContext built_ctx{2, spec, Texts::builtin("fr"), NumberStyle::for_language("fr"), 2, branch};
          ExerciseContext values_ctx = built_ctx;
          values_ctx.sections = values_ctx.tolerances = false;
          Rng rng_built(static_cast<std::uint64_t>(seed) * 7919u + 3), rng_values(static_cast<std::uint64_t>(seed) * 7919u + 3);
          const ExerciseInstance built = kind->make(rng_built, built_ctx);
          const ExerciseInstance values = kind->make(rng_values, values_ctx);
          CHECK(values.instance == built.instance);
          CHECK(values.fingerprint == built.fingerprint);
          CHECK(values.n == built.n);
          CHECK(values.number == built.number);
          CHECK(values.kind == built.kind);
          CHECK(values.branch == built.branch);
          REQUIRE(values.questions.size() == built.questions.size());
          for (std::size_t i = 0; i < built.questions.size(); ++i) {
            const Question &v = values.questions[i], &b = built.questions[i];
            CAPTURE(b.field);
            CHECK(v.field == b.field);
            CHECK(same(v.expected, b.expected));
            CHECK(v.point_group == b.point_group);
            CHECK(std::bit_cast<std::uint64_t>(v.points) == std::bit_cast<std::uint64_t>(b.points));
            CHECK(v.exact == b.exact);
          }
          // nothing built past them
          CHECK(values.sheet.blocks.empty());
          CHECK(values.key.blocks.empty());
          CHECK(values.solution.empty());
          CHECK_FALSE(built.key.blocks.empty());
          ++compared;
        }
    }
  }
  CHECK(compared > 500);
}
