#pragma once
// From a Scene (math coordinates, roles) to Canvas calls (page coordinates, paints), once for
// every backend: the panels' frames, the math → page map (the only y flip), clipping of lines and
// rays, arrowheads, marks, the grid and its numbers, and label placement. The SVG backend
// (svg_scene.h) and the cairo backend draw what this decides, so they draw the same figure.
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/label_placer.h"
#include "render/scene.h"
#include "render/style.h"

namespace epure::render {

// The map from a panel's math view onto its rectangle on the page, at one scale on both axes.
class Frame {
 public:
  // `rect` in page coordinates (points, y down); the view is centred in it if the aspect ratios
  // differ.
  Frame(const Box& view, const Box& rect);

  // Math → page. The one place where y turns from up to down.
  P2 to_page(P2 m) const;
  // A math direction as a page direction (same length × scale).
  P2 dir_to_page(P2 v) const;

  double scale() const { return scale_; }
  const Box& view() const { return view_; }
  const Box& rect() const { return rect_; }

 private:
  Box view_, rect_;
  double scale_ = 1;
  P2 origin_;  // page position of the view's top-left corner (x_min, y_max)
};

// Where a scene's parts go inside its rectangle.
struct SceneLayout {
  std::vector<Box> panels;    // page rectangles of the panels' views
  std::vector<Box> captions;  // under each panel (empty box when it has no caption)
  std::vector<Box> links;     // the gaps between consecutive panels
  // For each link: true when its text stands on the arrow in its gap, false when it is set
  // under the panels' captions instead (it would not fit the gap on one line).
  std::vector<bool> link_on_arrow;
  Box notes;                  // those links' lines, across the whole scene (empty: none)
  Box legend;                 // the legend's one line, under everything (empty: none)
  double height = 0;
};

// Panels side by side at one common height, a gap between consecutive ones (wide enough for the
// link's text when there is one), captions underneath. A link whose text would not fit its gap
// on one line gets a plain arrow and its text under the captions, across the scene's width: a map
// such as T⁻¹ = scale(…) ∘ rotate(…) ∘ translate(…) stays on one line, and the panels keep the
// width a narrow column of text would take. x, y: top-left corner, points.
SceneLayout layout_scene(const Scene& scene, double x, double y, double width,
                         const Style& style = Style::print());

// The height a scene takes when drawn `width` points wide: what page layout reserves.
double scene_height(const Scene& scene, double width, const Style& style = Style::print());

// What painting decided for one panel: for tests, and for the generator to reject a figure
// whose labels do not fit.
struct PanelReport {
  Box area;                        // the panel's rectangle
  std::vector<std::string> texts;  // each placed label's text, in placement order
  std::vector<Placement> labels;   // their boxes, same order
  Obstacles obstacles;             // everything drawn that a label must keep clear of
};

struct SceneReport {
  std::vector<PanelReport> panels;
  // Labels that could not be placed clear of everything.
  int unclean() const;
};

SceneReport paint_scene(Canvas& canvas, const Scene& scene, double x, double y, double width,
                        const Style& style = Style::print());
// The same in a layout already made (layout_scene(scene, x, y, width, style)): a caller that
// needs the layout too makes it once.
SceneReport paint_scene(Canvas& canvas, const Scene& scene, const SceneLayout& layout,
                        const Style& style = Style::print());

}  // namespace epure::render
