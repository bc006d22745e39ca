#pragma once
// The cases a function is run on: random ones drawn as a sheet's data are (decimals within ±10),
// the hard categories (functions.h, Category) where the classic bugs show and where rounding
// decides, and the student's own sheet instances when the file names its sheet. The same seed
// gives every student the same random and hard cases, in the same order.
#include <cstdint>
#include <vector>

#include "check/functions.h"
#include "exercises/sheet_id.h"
#include "exercises/spec.h"

namespace epure::check {

// The random and hard cases of one function.
std::vector<Case> standard_cases(Fn fn, std::uint64_t seed);

// The instances of a student's sheet that the course's functions take: projection, segments,
// ray/circle (also as the canonical circle, carried there: A' = (A − C)/r, the same direction),
// ray/square, ray/ellipse, ray/rectangle, ray/sphere, ray/cube. A direction the contract wants
// unit is normalised. Throws std::runtime_error when the sheet cannot be rebuilt from the spec.
std::vector<Case> sheet_cases(const WorksheetSpec& spec, const SheetId& id);

}  // namespace epure::check
