#pragma once
// What a backend implements to draw scenes: paths, discs and lines of text in page space (points,
// y down), with semantic groups and a clip rectangle, in the manner of matplotlib's renderers.
// The painter (scene_painter.h) decides every position, size and style once; the SVG canvas and
// the cairo canvas only turn these calls into their own format, so both draw the same figure.
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "render/scene.h"
#include "render/style.h"
#include "render/text.h"

namespace epure::render {

// A path in page coordinates: move, line, cubic Bézier and close commands.
class Path {
 public:
  enum class Op { move, line, cubic, close };
  struct Cmd {
    Op op;
    P2 p[3];  // line/move: p[0]; cubic: control 1, control 2, end
  };

  Path& move_to(P2 p) {
    cmds_.push_back({Op::move, {p, {}, {}}});
    return *this;
  }
  Path& line_to(P2 p) {
    cmds_.push_back({Op::line, {p, {}, {}}});
    return *this;
  }
  Path& cubic_to(P2 c1, P2 c2, P2 p) {
    cmds_.push_back({Op::cubic, {c1, c2, p}});
    return *this;
  }
  Path& close() {
    cmds_.push_back({Op::close, {}});
    return *this;
  }

  const std::vector<Cmd>& cmds() const { return cmds_; }
  bool empty() const { return cmds_.empty(); }

 private:
  std::vector<Cmd> cmds_;
};

struct StrokeStyle {
  Colour colour;
  double width = 1;
  std::vector<double> dash;  // empty: solid
};

struct Paint {
  std::optional<StrokeStyle> stroke;
  std::optional<Colour> fill;
  double fill_opacity = 1;
};

enum class Anchor { start, middle, end };

// One line of text: runs set one after the other from the baseline point, scripts scaled by
// kScriptScale and shifted by kSubShift / kSuperShift (text.h). The arrows of \vec runs are not
// drawn by the canvas: the painter draws them as paths, from the runs' measured widths.
// The runs are viewed, not owned: a line lives for one call to Canvas::text, and a page's texts
// are most of its elements (a copy of each line's runs was 4 % of writing a sheet).
struct TextLine {
  P2 at;  // on the baseline; left end, middle or right end by `anchor`
  Anchor anchor = Anchor::start;
  double size = 10;
  std::span<const TextRun> runs;
  Colour colour;
};

class Canvas {
 public:
  virtual ~Canvas() = default;
  // A semantic group ("data", "construction", "labels", …); `id` empty for none.
  virtual void begin_group(std::string_view cls, std::string_view id = {}) = 0;
  virtual void end_group() = 0;
  // Everything drawn until pop_clip is clipped to `box` (page coordinates).
  virtual void push_clip(const Box& box) = 0;
  virtual void pop_clip() = 0;
  virtual void path(const Path& path, const Paint& paint) = 0;
  virtual void disc(P2 centre, double radius, const Paint& paint) = 0;
  virtual void text(const TextLine& line) = 0;
  // The raster's pixels scaled into `box` (page coordinates).
  virtual void image(const Raster& raster, const Box& box) = 0;
};

}  // namespace epure::render
