#include "exercises/tolerance.h"

#include <fmt/format.h>

#include <cmath>

namespace epure {

std::vector<double> derive_abs_tolerances(const StudentMethod& method, int intermediates,
                                          int decimals, double floor) {
  const double delta = 0.5 * std::pow(10.0, -decimals);
  const std::vector<double> base = method(Nudge{});
  std::vector<double> total(base.size(), delta);
  // A central difference with a step smaller than δ: the method is smooth where the instance
  // is well-posed (the generator keeps it away from branch boundaries).
  const double h = delta / 8;
  for (int k = 0; k < intermediates; ++k) {
    const auto up = method(Nudge{k, h});
    const auto down = method(Nudge{k, -h});
    for (std::size_t i = 0; i < base.size(); ++i)
      total[i] += std::abs(up[i] - down[i]) / (2 * h) * delta;
  }
  for (double& t : total) t = std::max(floor, 1.5 * t);
  return total;
}

ToleranceRule isclose_rule(double abs, int decimals, const QuestionSpec* spec) {
  ToleranceRule r;
  r.kind = ToleranceRule::Kind::isclose;
  r.rel = kGradingRel;
  r.abs = abs;
  r.why = fmt::format("answers rounded to {} decimals: the rounding of the result and of each "
                      "intermediate value propagated through the method",
                      decimals);
  if (spec && spec->abs) {
    r.abs = *spec->abs;
    r.why = "absolute tolerance set by the spec";
  }
  if (spec && spec->rel) r.rel = *spec->rel;
  if (spec && spec->whole_point) r.kind = ToleranceRule::Kind::distance;
  return r;
}

ToleranceRule exact_rule() {
  ToleranceRule r;
  r.kind = ToleranceRule::Kind::exact;
  r.why = "must match exactly";
  return r;
}

}  // namespace epure
