#pragma once
// The SVG backend for scenes: the painter's calls (scene_painter.h) written with SvgWriter.
// Groups carry the roles as classes (<g class="data">, "construction", …) and every panel an id;
// text is <text> with <tspan>s for scripts; arrowheads are paths, not markers, so that the cairo
// backend can draw exactly the same shapes.
#include <string>

#include "render/canvas.h"
#include "render/scene.h"
#include "render/scene_painter.h"
#include "render/style.h"
#include "render/svg_writer.h"

namespace epure::render {

// The font every backend sets text in (its metrics are font_metrics.h's).
inline constexpr const char* kFontFamily = "DejaVu Sans, sans-serif";

// A Canvas that writes SVG elements into `writer` (inside an open <svg> or <g>).
class SvgCanvas final : public Canvas {
 public:
  explicit SvgCanvas(SvgWriter& writer) : w_(writer) {}
  void begin_group(std::string_view cls, std::string_view id = {}) override;
  void end_group() override;
  void push_clip(const Box& box) override;
  void pop_clip() override;
  void path(const Path& path, const Paint& paint) override;
  void disc(P2 centre, double radius, const Paint& paint) override;
  void text(const TextLine& line) override;
  void image(const Raster& raster, const Box& box) override;

 private:
  void paint_attributes(const Paint& paint);
  SvgWriter& w_;
  std::string buffer_;  // path data and dash lists, reused
};

// Draws `scene` into the page rectangle whose top-left corner is (x, y), `width` points wide
// and scene_height(scene, width) high. Returns where the labels went.
SceneReport draw_scene(SvgWriter& writer, const Scene& scene, double x, double y, double width,
                       const Style& style = Style::print());

// A standalone SVG 1.1 document of the scene, `width_pt` points wide, with viewBox, <title> and
// <desc>, on a white background.
std::string scene_to_svg(const Scene& scene, double width_pt, const Style& style = Style::print());
// The same, with the label report (for tests and the demo).
std::string scene_to_svg(const Scene& scene, double width_pt, SceneReport& report,
                         const Style& style = Style::print());
// The same in a layout already made (layout_scene(scene, 0, 0, width_pt, style)), for a caller
// that needs it too (the explorer maps the pointer with its first panel).
std::string scene_to_svg(const Scene& scene, double width_pt, const SceneLayout& layout,
                         const Style& style = Style::print());

}  // namespace epure::render
