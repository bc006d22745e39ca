#pragma once
// The diagram model: what a figure shows, in the figure's own math coordinates (y up), with no
// idea of exercises nor of the backend that will draw it (SVG now, cairo for PDF/PNG later).
// Exercises build Scenes; backends draw them. Every drawable says what it *is* (a data point, a
// construction line, a result), through its Role; the backend's style sheet turns roles into
// colour, stroke width and dash pattern, so that a sheet stays legible in grayscale print.
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace epure::render {

struct P2 {
  double x = 0, y = 0;
};

// What a drawn thing is, not how it looks.
enum class Role {
  data,          // given by the statement: points, segments, the ray, the figure
  construction,  // helper lines of the method: projection line, supporting lines, CP
  result,        // what the answer is: P, I, the hit point
  normal,        // normal vectors at a hit
  muted,         // shown for context but not in play (the square's non-candidate sides)
  highlight,     // picked out (the candidate sides)
  given,         // a student's own answer, drawn over the key's figure (feedback sheets)
};

// Text of a label or caption. Plain UTF-8 with three markups, which every backend renders:
//   t_{ab}       subscript      r^{2}     superscript      \vec{AB}   arrow over AB
// A backslash before {, } or \ escapes it.
using RichText = std::string;

// Where a label would like to sit relative to its anchor; the placer may move it to avoid
// overlaps (it tries the preferred side first, then the others).
enum class Side { auto_, above, below, left, right, above_left, above_right, below_left, below_right };

struct Label {
  RichText text;
  P2 anchor;             // the point the label names (math coordinates)
  Side side = Side::auto_;
  Role role = Role::data;
};

struct PointMark {
  P2 at;
  Role role = Role::data;
  std::optional<Label> label;  // anchored at `at` when present
};

struct Segment {
  P2 a, b;
  Role role = Role::data;
  bool dashed = false;  // dashed regardless of role (e.g. CP in the projection key)
};

// An infinite line through a and b, clipped to the panel's view.
struct Line {
  P2 a, b;
  Role role = Role::construction;
};

// A half-line from origin in direction dir, clipped to the view, with an arrowhead.
struct Ray {
  P2 origin;
  P2 dir;
  Role role = Role::data;
  // Where the ray is followed to: its first hit, in a key. Past it the ray is drawn muted, as
  // not followed (a ray tracer stops there), so a normal drawn along the ray from that point (an
  // exit square to the side) is the one solid stroke there instead of lying on the ray.
  std::optional<P2> followed_to = std::nullopt;
};

// A vector drawn as an arrow from `from` to `to` (a direction u, a normal N).
struct Arrow {
  P2 from, to;
  Role role = Role::data;
};

struct Circle {
  P2 c;
  double r;
  Role role = Role::data;
};

struct Ellipse {
  P2 c;
  double rx, ry;
  double angle_deg;  // counter-clockwise rotation of the rx axis
  Role role = Role::data;
};

struct Polygon {
  std::vector<P2> points;
  bool closed = true;
  Role role = Role::data;
  bool filled = false;  // a light fill in the role's colour (e.g. the Pythagoras triangle)
};

// The right-angle square at `vertex`, between directions d1 and d2 (need not be unit).
struct RightAngle {
  P2 vertex;
  P2 d1, d2;
  Role role = Role::construction;
};

// A tick across the line through `at` with direction `along`, with an optional label
// ("0", "t", "1" along AB in the projection key).
struct Tick {
  P2 at;
  P2 along;
  std::optional<RichText> text;
  Role role = Role::construction;
};

// A dimension line between a and b, offset to one side, with its label ("√(d²)", "r").
struct Dimension {
  P2 a, b;
  RichText text;
  double offset = 0;  // in math units, to the left of a→b when positive
  Role role = Role::construction;
};

struct Grid {
  double step = 1;
  bool numbered_axes = true;  // axes through the origin with numbers every `step`
};

using Item = std::variant<Label, PointMark, Segment, Line, Ray, Arrow, Circle, Ellipse, Polygon,
                          RightAngle, Tick, Dimension, Grid>;

struct Box {
  double x_min = 0, y_min = 0, x_max = 1, y_max = 1;
  double width() const { return x_max - x_min; }
  double height() const { return y_max - y_min; }
};

// A raster image as PNG bytes (a scanned answer's crop on a feedback sheet), with its size in
// pixels: the backends embed the bytes as they are, scaled into the rectangle they are given.
// Shared, so that the layout's copies of a row (replays, options tried) do not copy the bytes.
struct Raster {
  std::shared_ptr<const std::string> png;
  int width_px = 0, height_px = 0;
  double natural_height_pt = 0;  // its height where it was taken (a field on the printed page); 0: unknown
  bool empty() const { return !png || png->empty() || width_px <= 0 || height_px <= 0; }
};

// One framed drawing with its own coordinate system.
struct Panel {
  Box view;               // the math region shown; equal scale on both axes
  std::string caption;    // RichText under the panel ("world frame", "canonical frame")
  std::vector<Item> items;  // drawn in order; labels are placed after everything else is known

  template <class T>
  Panel& add(T item) {
    items.emplace_back(std::move(item));
    return *this;
  }
};

// One entry of a figure's legend: what a role's colour means in this figure, where it means
// something the reader could not guess (orange: a candidate side), shown as the role draws it.
struct LegendEntry {
  enum class Swatch { line, area };
  Role role;
  Swatch swatch = Swatch::line;
  RichText text;
};

// A diagram: one panel, or several side by side (the world and canonical frames of an ellipse),
// with a note between consecutive panels (the transform that maps one onto the next), and a
// small legend under it all when a colour carries a meaning.
struct Scene {
  std::string title;        // <title> of the SVG: short, plain text
  std::string description;  // <desc>: what the figure shows, for screen readers
  std::vector<Panel> panels;
  std::vector<std::string> links;  // RichText between panel i and i+1 (size panels − 1 or 0)
  std::vector<LegendEntry> legend;
};

// Whether any item of the scene is drawn in `role`: a legend says what a colour means only where
// the figure shows it.
inline bool uses_role(const Scene& scene, Role role) {
  for (const Panel& panel : scene.panels)
    for (const Item& item : panel.items) {
      const bool in_role = std::visit(
          [&](const auto& i) {
            if constexpr (requires { i.role; }) return i.role == role;
            else return false;
          },
          item);
      if (in_role) return true;
    }
  return false;
}

}  // namespace epure::render
