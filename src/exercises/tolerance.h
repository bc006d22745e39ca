#pragma once
// The tolerance rules of the questions. A student does what the statement tells them: carries
// every step to method::kCarriedDigits significant digits and writes each answer rounded to
// `decimals` decimals; the answer then moves by up to δ = ½·10^−decimals for its own rounding
// plus |∂answer/∂q|·δ_q for each step q carried on the way (method.h: tolerances). The method's
// dual-number run gives those derivatives (kind_method.cpp's make_questions); this file writes
// the rules.
#include <string>

#include "exercises/exercise.h"

namespace epure {

// The isclose rule for a numeric answer: rel = kGradingRel, abs as derived (or the spec's
// overrides), with the derivation written out for the key.
inline constexpr double kGradingRel = 1e-3;
ToleranceRule isclose_rule(double abs, int decimals, const QuestionSpec* spec);
ToleranceRule exact_rule();

}  // namespace epure
