#pragma once
// Grading tolerances derived from the instance. A student rounds what the statement tells them
// to (the intermediate results of the method, to `decimals` decimals) and the final answer; the
// answer then moves by up to δ for its own rounding plus |∂answer/∂q|·δ for each intermediate q
// rounded on the way, with δ = ½·10^−decimals. Each kind writes its worked solution once as a
// function of those intermediates (Steps), and this file differentiates it numerically.
#include <functional>
#include <string>
#include <vector>

#include "exercises/exercise.h"

namespace epure {

// Nudges intermediate values the student rounds: steps call `at(k, value)` for their k-th
// rounded intermediate, and get value + nudge when k is the one being differentiated.
class Nudge {
 public:
  Nudge() = default;
  Nudge(int index, double amount) : index_(index), amount_(amount) {}
  double at(int k, double value) const { return k == index_ ? value + amount_ : value; }

 private:
  int index_ = -1;
  double amount_ = 0;
};

// The worked method as a function of the nudge: the numeric answers, in a fixed order.
using StudentMethod = std::function<std::vector<double>(const Nudge&)>;

// For each numeric answer, the absolute tolerance: 1.5·(δ + Σ_k |∂a/∂q_k|·δ) over the
// `intermediates` rounded intermediates, floored at `floor`. The factor 1.5 leaves room for a
// student who rounds a little differently from the key (truncates, or rounds twice).
std::vector<double> derive_abs_tolerances(const StudentMethod& method, int intermediates,
                                          int decimals, double floor = 0);

// The isclose rule for a numeric answer: rel = kGradingRel, abs as derived (or the spec's
// overrides), with the derivation written out for the key.
inline constexpr double kGradingRel = 1e-3;
ToleranceRule isclose_rule(double abs, int decimals, const QuestionSpec* spec);
ToleranceRule exact_rule();

}  // namespace epure
