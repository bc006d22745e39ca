#include "exercises/tolerance.h"

#include <fmt/format.h>

#include "exercises/method.h"

namespace epure {

ToleranceRule isclose_rule(double abs, int decimals, const QuestionSpec* spec) {
  ToleranceRule r;
  r.kind = ToleranceRule::Kind::isclose;
  r.rel = kGradingRel;
  r.abs = abs;
  r.why = fmt::format("answer written to {} decimals, each step carried to {} significant digits: the "
                      "answer's own rounding plus each carried step's propagated through the method",
                      decimals, method::kCarriedDigits);
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
