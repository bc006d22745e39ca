#pragma once
// Exercise 2 of the course: the intersection of the segments [AB] and [CD] by 2D cross
// products. AP = t_ab·AB and CP = t_cd·CD meet where
//   t_ab = AC∧CD / AB∧CD   and   t_cd = AC∧AB / AB∧CD.
#include <optional>

#include "geometry/decimal.h"
#include "geometry/vec.h"

namespace epure::geo {

enum class SegmentRelation {
  intersects,  // the lines cross within both segments (an endpoint touching counts)
  outside,     // the lines cross, outside one segment or both
  parallel,    // AB∧CD ≈ 0 and the lines are distinct
  collinear,   // AB∧CD ≈ 0 on one and the same line, whether or not the segments overlap
};

struct SegmentIntersection {
  SegmentRelation relation;
  Vec2 AB, CD, AC;
  double ab_cross_cd;  // AB∧CD, the denominator (≈ 0 when parallel)
  double ac_cross_cd;  // AC∧CD, numerator of t_ab
  double ac_cross_ab;  // AC∧AB, numerator of t_cd
  // The lines' parameters at their crossing: present for `intersects` and `outside`.
  std::optional<double> t_ab, t_cd;
  // The intersection point: present for `intersects` only.
  std::optional<Point2> I;

  bool intersects() const { return relation == SegmentRelation::intersects; }
};

// Throws DegenerateFigure("B") when A = B and ("D") when C = D. A parameter within rounding of
// 0 or 1 is reported as exactly that bound (a segment touching the other at an end intersects).
SegmentIntersection intersect_segments(Point2 A, Point2 B, Point2 C, Point2 D);

// The same with every decision exact for the numbers given (`epure solve`, README, "What a
// number means"; as for project_exact): parallel means AB∧CD = 0 exactly, collinear that and
// AC∧AB = 0; the place of each parameter against 0 and 1 is the sign of its numerator against
// its denominator (AC∧CD, CB∧CD for t_ab; AC∧AB, AB∧AD for t_cd). No snapping: a parameter is
// exactly 0 or 1 only when the lines meet exactly at that end, and it never contradicts the
// relation (within [0, 1] for `intersects`, beyond for the one that is, for `outside`).
// Degenerate only when A = B or C = D exactly.
// Decimals as written (decimal.h), doubles as themselves: one meaning for a number (README).
SegmentIntersection intersect_segments_exact(const DPoint2& A, const DPoint2& B, const DPoint2& C, const DPoint2& D);
SegmentIntersection intersect_segments_exact(Point2 A, Point2 B, Point2 C, Point2 D);

const char* to_string(SegmentRelation r);

}  // namespace epure::geo
