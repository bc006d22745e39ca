#pragma once
// Values as the key's worked steps write them: exact forms when short, with their decimals,
// and the relation sign ("= 1/4 = 0.25", "≈ 2.17").
#include <optional>
#include <string>

#include "exercises/exact.h"
#include "exercises/exercise.h"
#include "exercises/method.h"
#include "geometry/vec.h"

namespace epure::kinds {

// The exact rational a datum denotes, when it has at most 6 decimals (data on a grid always do).
using method::rational_of;

// A value as a worked step shows it: its exact form when short, with its decimal value when that
// is not the same number written otherwise ("37/5 = 7.4", "−6√5/5 ≈ −2.68"); the decimal alone
// when the exact form is long (one-decimal data give fractions like 376996/25925).
std::string step_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& e);
std::string step_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                       const std::optional<exact::Surd>& ey);

// A value as the key's worked steps show it: its exact form when it has a short one, else
// rounded ("1/4", "5 − 2√2", "≈ 2.17" → "2.17").
std::string shown(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact);
std::string shown_point(const ExerciseContext& ctx, geo::Point2 p,
                        const std::optional<exact::Surd>& ex, const std::optional<exact::Surd>& ey);

// A worked step's result with its relation sign, as the key writes it after a formula: "= 5",
// "= 1/4 = 0.25", "= √13 ≈ 3.61", or "≈ 2.17" when there is no short exact form.
std::string equals_value(const ExerciseContext& ctx, double value, const std::optional<exact::Surd>& exact);

// Whether the value is exactly a decimal of at most `decimals` places (per its exact form): a
// student writes it out, and does not round it on the way. Without an exact form, false.
bool terminates_within(const std::optional<exact::Surd>& exact, int decimals);

// A worked step's point with its relation sign: "= (1.5, 2)" when both coordinates stop within
// the asked decimals, else "≈ (1.43, 2.17)".
std::string equals_point(const ExerciseContext& ctx, geo::Point2 p, const std::optional<exact::Surd>& ex,
                         const std::optional<exact::Surd>& ey);

}  // namespace epure::kinds
