#include "render/svg_scene.h"

#include <string_view>

#include "render/svg_path_data.h"
#include "support/base64.h"

namespace epure::render {
namespace {

const char* anchor_name(Anchor a) {
  switch (a) {
    case Anchor::start: return "start";
    case Anchor::middle: return "middle";
    case Anchor::end: return "end";
  }
  return "start";
}

}  // namespace

// Fill and stroke attributes, in a fixed order; SVG's defaults (black fill, no stroke) are
// written out so that the meaning never depends on a parent group.
void SvgCanvas::paint_attributes(const Paint& p) {
  w_.attribute("fill", p.fill ? std::string_view(p.fill->hex()) : std::string_view("none"));
  if (p.fill && p.fill_opacity < 1) w_.attribute("fill-opacity", p.fill_opacity);
  if (p.stroke) {
    w_.attribute("stroke", p.stroke->colour.hex());
    w_.attribute("stroke-width", p.stroke->width);
    if (!p.stroke->dash.empty()) {
      buffer_.clear();
      for (double v : p.stroke->dash) {
        if (!buffer_.empty()) buffer_ += ' ';
        append_number(buffer_, v);
      }
      w_.attribute("stroke-dasharray", buffer_);
    }
  }
}

void SvgCanvas::begin_group(std::string_view cls, std::string_view id) {
  w_.open("g");
  if (!id.empty()) w_.attribute("id", w_.next_id(id));
  w_.attribute("class", cls);
  w_.close_start();
}

void SvgCanvas::end_group() { w_.end("g"); }

void SvgCanvas::push_clip(const Box& box) {
  const std::string id = w_.next_id("clip");
  w_.start("clipPath", {{"id", id}});
  w_.element(
      "rect",
      {{"x", box.x_min}, {"y", box.y_min}, {"width", box.width()}, {"height", box.height()}});
  w_.end("clipPath");
  w_.start("g", {{"clip-path", "url(#" + id + ")"}});
}

void SvgCanvas::pop_clip() { w_.end("g"); }

void SvgCanvas::path(const Path& path, const Paint& paint) {
  if (path.empty()) return;
  buffer_.clear();
  append_path_data(buffer_, path);
  w_.open("path");
  w_.plain_attribute("d", buffer_);
  paint_attributes(paint);
  w_.close_empty();
}

void SvgCanvas::disc(P2 centre, double radius, const Paint& paint) {
  w_.open("circle");
  w_.attribute("cx", centre.x);
  w_.attribute("cy", centre.y);
  w_.attribute("r", radius);
  paint_attributes(paint);
  w_.close_empty();
}

// The PNG inline as a data: URI, so that a page stays one file that opens offline.
void SvgCanvas::image(const Raster& raster, const Box& box) {
  if (raster.empty()) return;
  w_.open("image");
  w_.attribute("x", box.x_min);
  w_.attribute("y", box.y_min);
  w_.attribute("width", box.width());
  w_.attribute("height", box.height());
  w_.attribute("preserveAspectRatio", "none");
  w_.plain_attribute("href", "data:image/png;base64," + base64(*raster.png));
  w_.close_empty();
}

void SvgCanvas::text(const TextLine& line) {
  w_.open("text");
  w_.attribute("x", line.at.x);
  w_.attribute("y", line.at.y);
  w_.attribute("font-size", line.size);
  // Text is most of a sheet's elements: SVG's initial values (black, anchored at the start) go
  // unwritten, and xml:space="preserve" is set once on the root, whose every text inherits it.
  // No group of ours sets fill or text-anchor, so nothing else can be inherited.
  if (line.colour != Colour{}) w_.attribute("fill", line.colour.hex());
  if (line.anchor != Anchor::start) w_.attribute("text-anchor", anchor_name(line.anchor));
  w_.close_start_inline();
  // Scripts are tspans shifted with dy; the next run shifts back, so every run's baseline is
  // the one text.h's place_runs gives.
  const auto rise = [&](Shift s) {
    return s == Shift::sub     ? -kSubShift * line.size
           : s == Shift::super ? kSuperShift * line.size
                               : 0.0;
  };
  Shift current = Shift::none;
  for (const TextRun& r : line.runs) {
    if (r.shift == current && r.shift == Shift::none && !r.bold) {
      w_.text(r.text);
      continue;
    }
    w_.open("tspan");
    if (r.shift != current) w_.attribute("dy", rise(current) - rise(r.shift));  // dy points down
    if (r.shift != Shift::none) w_.attribute("font-size", line.size * kScriptScale);
    if (r.bold) w_.attribute("font-weight", "bold");
    w_.close_start_inline();
    w_.text(r.text);
    w_.end("tspan");
    current = r.shift;
  }
  w_.end("text");
}

namespace {

SceneReport draw_in(SvgWriter& writer, const Scene& scene, const SceneLayout& layout, const Style& style) {
  SvgCanvas canvas(writer);
  writer.start("g", {{"id", writer.next_id("figure")}, {"class", "figure"}});
  SceneReport report = paint_scene(canvas, scene, layout, style);
  writer.end("g");
  return report;
}

std::string document(const Scene& scene, double width_pt, const SceneLayout& layout, SceneReport& report,
                     const Style& style) {
  const double height = layout.height;
  SvgWriter w;
  w.declaration();
  w.start("svg", {{"xmlns", "http://www.w3.org/2000/svg"},
                  {"version", "1.1"},
                  {"width", format_number(width_pt) + "pt"},
                  {"height", format_number(height) + "pt"},
                  {"viewBox", "0 0 " + format_number(width_pt) + " " + format_number(height)},
                  {"font-family", kFontFamily},
                  {"xml:space", "preserve"}});
  w.element("title", {}, scene.title);
  w.element("desc", {}, scene.description);
  w.element("rect", {{"width", width_pt}, {"height", height}, {"fill", style.background.hex()}});
  report = draw_in(w, scene, layout, style);
  w.end("svg");
  return w.finish();
}

}  // namespace

SceneReport draw_scene(SvgWriter& writer, const Scene& scene, double x, double y, double width,
                       const Style& style) {
  return draw_in(writer, scene, layout_scene(scene, x, y, width, style), style);
}

std::string scene_to_svg(const Scene& scene, double width_pt, SceneReport& report,
                         const Style& style) {
  return document(scene, width_pt, layout_scene(scene, 0, 0, width_pt, style), report, style);
}

std::string scene_to_svg(const Scene& scene, double width_pt, const Style& style) {
  SceneReport report;
  return scene_to_svg(scene, width_pt, report, style);
}

std::string scene_to_svg(const Scene& scene, double width_pt, const SceneLayout& layout, const Style& style) {
  SceneReport report;
  return document(scene, width_pt, layout, report, style);
}

}  // namespace epure::render
