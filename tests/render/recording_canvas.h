#pragma once
// A Canvas that remembers what was drawn, flattened to segments, discs and text boxes, with the
// semantic group each sat in: the label tests check placed boxes against what a backend would
// really draw, not against the placer's own idea of it.
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/label_placer.h"
#include "render/text.h"

namespace epure::test {

struct RecordingCanvas final : render::Canvas {
  struct Stroke {
    render::P2 a, b;
    std::string group;  // innermost group's class
    double width = 0;   // the pen's width; 0 for a filled outline (an arrowhead)
  };
  struct Disc {
    render::P2 c;
    double r;
    std::string group;
  };
  struct Text {
    render::Box box;
    std::string text;
    std::string group;
  };

  std::vector<std::string> groups;
  std::vector<Stroke> strokes;  // stroked paths and filled outlines, cubics sampled
  std::vector<Disc> discs;
  std::vector<Text> texts;
  std::vector<render::Box> images;  // where each raster was drawn
  int clips = 0;

  std::string group() const { return groups.empty() ? std::string() : groups.back(); }
  // True when drawn inside a group of class `cls` at any depth.
  bool inside(const std::string& cls) const {
    for (const auto& g : groups) {
      if (g == cls) return true;
    }
    return false;
  }

  void begin_group(std::string_view cls, std::string_view) override { groups.emplace_back(cls); }
  void end_group() override { groups.pop_back(); }
  void push_clip(const render::Box&) override { ++clips; }
  void pop_clip() override { --clips; }

  void path(const render::Path& path, const render::Paint& paint) override {
    // Label backgrounds and \vec arrows belong to the labels themselves.
    if (inside("labels") || inside("grid")) return;
    const double width = paint.stroke ? paint.stroke->width : 0;
    render::P2 start{}, at{};
    for (const auto& c : path.cmds()) {
      switch (c.op) {
        case render::Path::Op::move: start = at = c.p[0]; break;
        case render::Path::Op::line:
          strokes.push_back({at, c.p[0], group(), width});
          at = c.p[0];
          break;
        case render::Path::Op::cubic: {
          constexpr int kSamples = 24;
          const render::P2 p0 = at;
          for (int k = 1; k <= kSamples; ++k) {
            const double t = double(k) / kSamples, u = 1 - t;
            const render::P2 p{u * u * u * p0.x + 3 * u * u * t * c.p[0].x +
                                   3 * u * t * t * c.p[1].x + t * t * t * c.p[2].x,
                               u * u * u * p0.y + 3 * u * u * t * c.p[0].y +
                                   3 * u * t * t * c.p[1].y + t * t * t * c.p[2].y};
            strokes.push_back({at, p, group(), width});
            at = p;
          }
          break;
        }
        case render::Path::Op::close:
          strokes.push_back({at, start, group(), width});
          at = start;
          break;
      }
    }
  }

  void disc(render::P2 c, double r, const render::Paint&) override {
    discs.push_back({c, r, group()});
  }

  void text(const render::TextLine& line) override {
    const render::TextExtent e = render::text_extent(line.runs, line.size);
    double x0 = line.at.x;
    if (line.anchor == render::Anchor::middle) x0 -= e.width / 2;
    if (line.anchor == render::Anchor::end) x0 -= e.width;
    std::string s;
    for (const auto& r : line.runs) s += r.text;
    texts.push_back({{x0, line.at.y - e.ascent, x0 + e.width, line.at.y + e.descent}, s, group()});
  }

  void image(const render::Raster&, const render::Box& box) override { images.push_back(box); }
};

}  // namespace epure::test
