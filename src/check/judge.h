#pragma once
// What a function should give for a case, from the geometry core, and whether what it gave is
// right.
//
// Values: the point (J, I, P) within tol_point = 1e-6·L + 64ε·S of the core's, the unit normal
// within tol_normal = tol_point / ρ, where L is the figure's size (the largest coordinate of its
// centre or of its sizes; 1 for a canonical figure; all the data for a projection or segments),
// S the largest coordinate of the data (the ray's origin included: from 10^12 away the point is
// known to 64ε·S only) and ρ the figure's smallest size (r, min(a, b)²/max(a, b), min(w, h); 1
// for a canonical figure). Room for the cancellation near tangency (√(6ε)·S ≈ 4e-8·S) and the
// rounding of a student's own method, a million times below the data's own precision.
//
// Decisions (hit or not, intersect or not, which side): exactly the core's (the exact
// predicates, for the doubles given), except where the figure is within the data's rounding of
// a boundary: then the answer for nearby data is right too. "Nearby": each coordinate of the
// data moved by 2^-40·S (far beyond a double computation's noise, far below any data a sheet
// prints), each way, one at a time; the core's tolerant reading of the data as decimals (a
// tangent, a segment's end, parallel lines within rounding); and for segments whose AB∧CD is
// within the rounding of the data, "parallel", false. Data every double computation of the
// course's method decides exactly (small dyadic numbers: integers, quarters, powers of two) get
// no such room. At a corner of the square, the rectangle or the cube, either side's normal is
// right.
#include "check/functions.h"

namespace epure::check {

struct Tolerance {
  double point;
  double normal;
};
Tolerance tolerance_of(const Case& c);

// The core's answer (exact decisions). Never throws for the cases epure generates; a case the
// core refuses (a degenerate figure) gives nothing.
std::optional<Outcome> expected(const Case& c);

// Whether two answers agree: the same decision and, for a hit (or a point), the values within
// the case's tolerance (a normal also agrees with another side's at a corner).
bool agrees(const Case& c, const Outcome& reference, const Outcome& got);

struct Judgement {
  bool right = false;
  Outcome expected;  // the core's answer
  bool in_band = false;  // right through the room near a boundary, not the core's own answer
};
Judgement judge(const Case& c, const Outcome& got);

// Whether the course's method decides this case exactly in doubles (judge.h, above).
bool exact_safe(const Case& c);

// The case's data scale S and figure size L, for reports.
double data_scale(const Case& c);

}  // namespace epure::check
