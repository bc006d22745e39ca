#pragma once
// Drawing a random instance: until the constraints hold, with the spec's constraint values, on
// the difficulty's grid.
#include <stdexcept>
#include <string>
#include <string_view>

#include "exercises/exercise.h"
#include "exercises/rng.h"

namespace epure::kinds {

// Draws until `ok` accepts or `attempts` run out; throws std::runtime_error naming `what`.
template <class Draw>
auto draw_until(int attempts, std::string_view what, Draw&& draw) {
  for (int i = 0; i < attempts; ++i)
    if (auto instance = draw()) return *instance;
  throw std::runtime_error(std::string("could not draw an instance meeting the constraints: ") +
                           std::string(what));
}

// A constraint's value: the spec's override or the kind's default.
double constraint(const ExerciseContext& ctx, const ExerciseKind& kind, const std::string& name);

// A random coordinate on the difficulty's grid: integers for easy and standard, one decimal for
// hard.
double grid_value(Rng& rng, double lo, double hi, Difficulty d);

}  // namespace epure::kinds
