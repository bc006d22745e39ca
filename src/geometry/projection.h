#pragma once
// Exercise 1 of the course: the orthogonal projection P of a point C on the line (AB), by the
// dot product alone.
#include "geometry/decimal.h"
#include "geometry/vec.h"

namespace epure::geo {

// Where P falls relative to the segment [AB].
enum class Position { before, between, after };

struct Projection {
  Vec2 AB, AC;
  double ab_dot_ac;  // AB·AC
  double ab_dot_ab;  // AB·AB = ‖AB‖²
  double t;          // AP = t·AB, t = AB·AC / AB·AB
  Point2 P;          // A + t·AB
  Position position; // t < 0: before A; 0 ≤ t ≤ 1: between; t > 1: after B
};

// Throws DegenerateFigure("B") when A and B coincide (no line). A t within rounding of 0 or 1
// counts as between (P on an end of the segment is on the segment) and is reported as exactly
// 0 or 1.
Projection project(Point2 A, Point2 B, Point2 C);

// The same projection with every decision exact for the numbers given (README, one meaning for
// a number): decimals as written (decimal.h), or doubles as themselves. No snapping: the
// position is the sign of AB·AC (before) and of AB·BC (after); t = 0 exactly when AB·AC = 0,
// t = 1 when AB·BC = 0, and t never contradicts the position (t < 0 before, t > 1 after).
// Degenerate only when A = B exactly. (`project`, the tolerant one, is the worksheets' drawing
// aid only: it decides nothing a key or `epure solve` prints.)
Projection project_exact(const DPoint2& A, const DPoint2& B, const DPoint2& C);
Projection project_exact(Point2 A, Point2 B, Point2 C);

const char* to_string(Position p);

}  // namespace epure::geo
