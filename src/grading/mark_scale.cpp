#include "grading/mark_scale.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "grading/answer_key.h"

namespace epure::grading {

namespace {

// Whether x is the whole number n, up to the rounding of a decimal typed on the command line.
bool whole(double x, double& n) {
  n = std::round(x);
  return std::abs(x - n) <= 1e-9 * std::max(1.0, std::abs(x));
}

// num / den rounded to the nearest integer, halves up (den > 0).
std::int64_t nearest(std::int64_t num, std::int64_t den) {
  const std::int64_t twice = 2 * num + den;
  const std::int64_t q = twice / (2 * den);
  return twice % (2 * den) < 0 ? q - 1 : q;  // floor for a negative quotient
}

}  // namespace

double MarkScale::round(double mark) const {
  double per_unit = 0;
  whole(1 / step, per_unit);
  return std::floor(mark * per_unit + 0.5) / per_unit;
}

double MarkScale::mark(double score, double max) const {
  if (!out_of) return score;
  if (!(max > 0)) return 0;
  double per_unit = 0, n = 0, q = 0, m = 0;
  whole(1 / step, per_unit);
  // exactly, when the scores are quarter points and N a whole number (always, for a spec's
  // points): units of the step = score·4 · N · (1/step) / (max·4), halves up
  if (whole(*out_of, n) && whole(score * 4, q) && whole(max * 4, m) && m > 0 && n < 1e6 && m < 1e9 && q < 1e9)
    return static_cast<double>(nearest(static_cast<std::int64_t>(q) * static_cast<std::int64_t>(n) *
                                           static_cast<std::int64_t>(per_unit),
                                       static_cast<std::int64_t>(m))) /
           per_unit;
  return round(score / max * *out_of);
}

MarkScale MarkScale::choose(const KeyInfo& key, std::string_view language, double out_of_option, double step_option) {
  MarkScale s;
  if (step_option < 0) throw std::invalid_argument(fmt::format("--round-to {}: must be positive", step_option));
  if (step_option > 0) s.step = step_option;
  double per_unit = 0;
  if (!(s.step > 0) || s.step > 1 || !whole(1 / s.step, per_unit))
    throw std::invalid_argument(
        fmt::format("--round-to {}: a step that divides 1 into a whole number of steps (0.01, 0.05, 0.1, 0.25, 0.5, 1)", s.step));
  if (out_of_option < 0) throw std::invalid_argument(fmt::format("--out-of {}: must be positive", out_of_option));
  if (out_of_option > 0) s.out_of = out_of_option;
  else if (key.scale) s.out_of = *key.scale;
  else if (language == "fr") s.out_of = 20;
  return s;
}

}  // namespace epure::grading
