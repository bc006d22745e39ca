#include "exercises/tolerance.h"

#include <fmt/format.h>

namespace epure {

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
