#pragma once
// A method kind's instances as the property tests draw them: every branch the kind draws by
// default, the three difficulties and `seeds` seeds, each made by the kind as a sheet makes it
// (English texts, `decimals` decimals). `f(branch, level, seed, inst)`; the branch, difficulty and
// seed are captured for doctest's messages.
#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "exercises/exercise.h"
#include "exercises/kind_support.h"
#include "exercises/texts.h"

namespace epure::test {

template <class F>
void for_each_drawn(const ExerciseKind& kind, int seeds, int decimals, std::uint64_t seed_mul, std::uint64_t seed_add,
                    F&& f) {
  const Difficulty levels[] = {Difficulty::easy, Difficulty::standard, Difficulty::hard};
  for (const auto& [branch, weight] : kind.default_branches()) {
    if (weight <= 0) continue;
    for (Difficulty level : levels)
      for (int seed = 1; seed <= seeds; ++seed) {
        CAPTURE(branch);
        CAPTURE(static_cast<int>(level));
        CAPTURE(seed);
        ExerciseSpec spec;
        spec.kind = std::string(kind.name());
        spec.difficulty = level;
        const ExerciseContext ctx{1, spec, Texts::builtin("en"), NumberStyle::for_language("en"), decimals, branch};
        Rng rng(static_cast<std::uint64_t>(seed) * seed_mul + seed_add);
        const ExerciseInstance inst = kind.make(rng, ctx);
        f(branch, level, seed, inst);
      }
  }
}

}  // namespace epure::test
