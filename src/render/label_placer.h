#pragma once
// Label placement in page space (points, y down): every label gets a box near its anchor that
// overlaps no other label, crosses no drawn line or curve, covers no point mark and stays inside
// its panel. Candidates are tried in order of preference (the preferred side first, then the
// other directions by angle, then the same on farther rings); the first clean one is taken.
// When none is clean, the candidate with the least overlap is taken and the placement says so.
// Deterministic: the same requests and obstacles give the same boxes.
#include <cstddef>
#include <vector>

#include "render/scene.h"

namespace epure::render {

// What a label must keep clear of.
struct Obstacles {
  struct Seg {
    P2 a, b;
    double half_width = 0;  // half the pen's width: a label keeps its clearance from the ink
  };
  struct Disc {
    P2 c;
    double r;
  };
  std::vector<Seg> segments;  // strokes: lines, curves as polylines, arrowheads' outlines
  std::vector<Disc> discs;    // point marks
  std::vector<Box> boxes;     // texts already set (axis numbers are not here: they give way)

  void add_polyline(const std::vector<P2>& pts, bool closed, double half_width = 0);
};

struct LabelRequest {
  P2 anchor;
  double width = 0, height = 0;  // the text's box
  // Preferred direction from the anchor to the label, page space (y down); zero: no preference
  // (above right first).
  P2 prefer{0, 0};
  double gap = 0;  // the box keeps at least this distance from the anchor
  // When the anchor lies on a stroke (a tick on AB, the middle of a dimension line): its
  // direction. The label is then first tried beside the stroke, on the preferred side and then
  // on the other, sliding along it, before the directions around the anchor.
  P2 along{0, 0};
  // How far the text's type box (the font's ascent to its descent: the line a reader, and a
  // PDF's text extraction, takes the text to fill) reaches above and below the ink box. Two
  // labels keep their type boxes apart, not only their ink, so that a subscript never sits in
  // the line of the label under it.
  double type_above = 0, type_below = 0;
  // And beside it: two labels keep this much more room between them across, so that text
  // extraction (and a reader) sees two words, not one run together.
  double type_side = 0;
};

struct Placement {
  Box box;
  Box type;           // `box` with the request's type_above and type_below
  bool clean = true;  // false: no candidate was clear; `box` is the least bad one
  bool leader = false;  // placed far from its anchor: a leader line joins them
};

// Clearance kept between a label's box and anything else (the ink of a stroke, a point's rim,
// another label's box), points: 1.5 pt measured on the printed figure (figure_gaps_test), and
// a little more, for the curves, which are polygons of kCurveSides here and Béziers on paper.
inline constexpr double kLabelClearance = 1.8;

// Places the labels in order (earlier ones have the better spots); each placed box becomes an
// obstacle for the next. `area` is the panel: boxes stay inside it.
std::vector<Placement> place_labels(const std::vector<LabelRequest>& requests,
                                    const Obstacles& obstacles, const Box& area);

// Geometry the placer and its tests share.
bool boxes_overlap(const Box& a, const Box& b);
bool segment_hits_box(P2 a, P2 b, const Box& box);
bool disc_hits_box(P2 c, double r, const Box& box);
Box inflate(const Box& b, double by);

}  // namespace epure::render
