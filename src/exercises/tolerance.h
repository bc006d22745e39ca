#pragma once
// The tolerance rules of the questions. A student rounds what the statement tells them to (the
// intermediate results of the method, to `decimals` decimals) and the final answer; the answer
// then moves by up to δ for its own rounding plus |∂answer/∂q|·δ for each intermediate q rounded
// on the way, with δ = ½·10^−decimals. The method's dual-number run gives those derivatives
// (method.h: Dual; kind_method.cpp's make_questions); this file writes the rules.
#include <string>

#include "exercises/exercise.h"

namespace epure {

// The isclose rule for a numeric answer: rel = kGradingRel, abs as derived (or the spec's
// overrides), with the derivation written out for the key.
inline constexpr double kGradingRel = 1e-3;
ToleranceRule isclose_rule(double abs, int decimals, const QuestionSpec* spec);
ToleranceRule exact_rule();

}  // namespace epure
