#include "exercises/step_text.h"

#include <fmt/format.h>

#include "exercises/method.h"

#include <cmath>

namespace epure::kinds {

namespace {
// A step's value as a student carries it (method.h: carried_decimals), not as an answer is written.
std::string carried_text(const ExerciseContext& ctx, double value) {
  return ctx.numbers.rounded(value, method::carried_decimals(value, ctx.decimals));
}
}  // namespace

std::string step_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& e) {
  const std::string rounded = carried_text(ctx, value);
  if (!e) return rounded;
  try {
    const std::string pretty = e->pretty();
    if (pretty.size() > 16 || e->a().den() > 1000 || e->b().den() > 1000) return rounded;
    const std::string exact = ctx.numbers.localise(pretty);
    if (!e->is_rational()) return fmt::format("{} ≈ {}", exact, rounded);
    const std::int64_t den = e->a().den();
    if (den == 1) return exact;
    std::int64_t pow10 = 1;
    for (int i = 0; i < ctx.decimals; ++i) pow10 *= 10;
    if (pow10 % den == 0) return fmt::format("{} = {}", exact, ctx.numbers.datum(value, ctx.decimals));
    return fmt::format("{} ≈ {}", exact, rounded);
  } catch (const exact::ExactOverflow&) {
    return rounded;
  }
}

std::string step_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                       const std::optional<exact::Surd>& ey) {
  return fmt::format("({}{} {})", step_value(ctx, p.x, ex), ctx.numbers.decimal_comma ? "\u00a0;" : ",",
                     step_value(ctx, p.y, ey));
}

std::string shown(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact) {
  if (exact) {
    try {
      const std::string pretty = exact->pretty();
      if (pretty.size() <= 16) return ctx.numbers.localise(pretty);
    } catch (const exact::ExactOverflow&) {
    }
  }
  return carried_text(ctx, value);
}

std::string shown_point(const ExerciseContext& ctx, geo::Point2 p,
                        const std::optional<exact::Surd>& ex, const std::optional<exact::Surd>& ey) {
  return fmt::format("({}{} {})", shown(ctx, p.x, ex), ctx.numbers.decimal_comma ? "\u00a0;" : ",",
                     shown(ctx, p.y, ey));
}

std::string equals_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact) {
  const std::string rounded = carried_text(ctx, value);
  std::string pretty;
  if (exact) {
    try {
      pretty = exact->pretty();
    } catch (const exact::ExactOverflow&) {
    }
  }
  // the same length limit as shown(): a longer exact form does not help a reader
  if (pretty.empty() || pretty.size() > 16) return fmt::format("≈ {}", rounded);
  pretty = ctx.numbers.localise(pretty);
  if (!exact->is_rational()) return fmt::format("= {} ≈ {}", pretty, rounded);
  if (exact->a().is_integer()) return fmt::format("= {}", pretty);
  // a fraction that stops within the asked decimals is written out exactly
  if (terminates_within(exact, ctx.decimals))
    return fmt::format("= {} = {}", pretty, ctx.numbers.datum(value, ctx.decimals));
  return fmt::format("= {} ≈ {}", pretty, rounded);
}

bool terminates_within(const std::optional<exact::Surd>& exact, int decimals) {
  if (!exact || !exact->is_rational()) return false;
  std::int64_t pow10 = 1;
  for (int i = 0; i < decimals; ++i) pow10 *= 10;
  return pow10 % exact->a().den() == 0;
}

std::string equals_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                         const std::optional<exact::Surd>& ey) {
  if (terminates_within(ex, ctx.decimals) && terminates_within(ey, ctx.decimals))
    return fmt::format("= {}", ctx.numbers.point(p.x, p.y, ctx.decimals));
  return fmt::format("≈ ({}{} {})", carried_text(ctx, p.x), ctx.numbers.decimal_comma ? "\u00a0;" : ",", carried_text(ctx, p.y));
}

}  // namespace epure::kinds
