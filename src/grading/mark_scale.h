#pragma once
// Marks as a teacher publishes them: a score out of the sheet's points turned into a mark out of
// N (a French "note sur 20"), rounded to a stated step. N is `--out-of`, else the spec's
// `scale`, else 20 for a French set (the French convention), else none: an English set's marks
// are its points. The step is `--round-to` (0.01 by default: the mark to the hundredth); the
// mark is score / max × N rounded to the nearest multiple of the step, halves up, computed
// exactly on the quarter points scores are made of (no 14.125 rounding to 14.12 through a
// binary 14.12499…).
#include <optional>
#include <string>
#include <string_view>

namespace epure::grading {

struct KeyInfo;

struct MarkScale {
  std::optional<double> out_of;  // none: marks are the points
  double step = 0.01;

  // The mark of `score` out of `max` points: out of N, rounded to the step; without N the score
  // itself (not rounded: points are quarter points already).
  double mark(double score, double max) const;
  // The same of a value that is already out of N (a class mean): rounded to the step.
  double round(double mark) const;

  // N from `--out-of` (0: not given), else the key's scale, else 20 for French; `step` from
  // `--round-to` (0: the default). Throws std::invalid_argument for a step that does not divide
  // 1 into a whole number of steps (0.01, 0.05, 0.1, 0.25, 0.5, 1 and the like do), or for
  // N ≤ 0.
  static MarkScale choose(const KeyInfo& key, std::string_view language, double out_of_option, double step_option);
};

}  // namespace epure::grading
