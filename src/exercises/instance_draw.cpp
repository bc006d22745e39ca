#include "exercises/instance_draw.h"

#include <cmath>

namespace epure::kinds {

double constraint(const ExerciseContext& ctx, const ExerciseKind& kind, const std::string& name) {
  auto it = ctx.spec.constraints.find(name);
  if (it != ctx.spec.constraints.end()) return it->second;
  return kind.default_constraints().at(name);
}

double grid_value(Rng& rng, double lo, double hi, Difficulty d) {
  if (d == Difficulty::hard)
    return static_cast<double>(rng.integer(static_cast<std::int64_t>(std::ceil(lo * 10)),
                                           static_cast<std::int64_t>(std::floor(hi * 10)))) / 10.0;
  return static_cast<double>(rng.integer(static_cast<std::int64_t>(std::ceil(lo)),
                                         static_cast<std::int64_t>(std::floor(hi))));
}

}  // namespace epure::kinds
