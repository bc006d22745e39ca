#include "render/page_painter.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "render/scene_painter.h"

namespace epure::render {
namespace {

void append_rectangle(Path& p, const PageRect& r) {
  p.move_to({r.x, r.y}).line_to({r.right(), r.y}).line_to({r.right(), r.bottom()}).line_to({r.x, r.bottom()}).close();
}

Path rectangle(const PageRect& r) {
  Path p;
  append_rectangle(p, r);
  return p;
}

// Answer boxes, or tick boxes and comb cells (one look), as one path.
void paint_boxes(Canvas& canvas, BoxKind kind, const Path& rectangles, const PageStyle& style) {
  if (kind == BoxKind::answer)
    canvas.path(rectangles, Paint{StrokeStyle{style.box_stroke, style.box_width, {}}, style.paper, 1});
  else
    canvas.path(rectangles, Paint{StrokeStyle{style.tick_stroke, style.tick_width, {}}, style.paper, 1});
}

// The light background of an emphasised paragraph, with its bar.
void paint_shade(Canvas& canvas, const PageRect& rect, const PageStyle& style) {
  canvas.path(rectangle(rect), Paint{std::nullopt, style.shade, 1});
  const PageRect bar{rect.x, rect.y, style.shade_bar_width, rect.height};
  canvas.path(rectangle(bar), Paint{std::nullopt, style.shade_bar, 1});
}

// A code's modules with a ring of light ones around them, a byte each, row by row ((n + 2)²):
// paint_qr's edge scan reads every module eight times, without bounds tests or bit extraction.
std::vector<std::uint8_t> padded_modules(const QrCode& code) {
  const int n = code.size, padded = n + 2;
  std::vector<std::uint8_t> grid(static_cast<std::size_t>(padded * padded), 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) grid[static_cast<std::size_t>((y + 1) * padded + x + 1)] = code.dark(x, y) ? 1 : 0;
  return grid;
}

// The dark modules as one path: the outlines of the dark regions, a corner a point. Each region
// is traced clockwise (on the page, y down) and each light hole inside one anticlockwise, so
// the nonzero fill paints exactly the dark modules, with no seam between neighbours at any zoom.
// A PDF's cost is per point (cairo records, replays, formats and compresses each one: about
// 0.8 us a point, and a page code was 14 % of a PDF's CPU): a page code's outlines take 383
// points where its modules' merged rectangles took 469 (33 loops against 118 rectangles).
void paint_qr(Canvas& canvas, const PlacedQr& qr, const PageStyle& style) {
  canvas.path(rectangle(qr.rect), Paint{std::nullopt, style.paper, 1});
  const QrCode& code = qr.code;
  const int n = code.size;
  const double module = qr.rect.width / (n + 2 * kQrQuietZone);
  const double x0 = qr.rect.x + module * kQrQuietZone, y0 = qr.rect.y + module * kQrQuietZone;
  const int padded = n + 2;
  const std::vector<std::uint8_t> grid = padded_modules(code);
  // (-1 <= x, y <= n)
  const auto dark = [&](int x, int y) { return grid[static_cast<std::size_t>((y + 1) * padded + x + 1)] != 0; };
  // The outline's edges, one module long, leaving each grid corner (x, y) (0 <= x, y <= n), the
  // dark side on their right: a bit per direction (right, down, left, up). A corner where two
  // dark modules touch diagonally has two.
  enum : std::uint8_t { right = 1, down = 2, left = 4, up = 8 };
  const int corners = n + 1;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(corners * corners), 0);
  const auto at = [&](int x, int y) -> std::uint8_t& { return out[static_cast<std::size_t>(y * corners + x)]; };
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      if (x < n && dark(x, y) && !dark(x, y - 1)) at(x, y) |= right;      // top edge of (x, y)
      if (x > 0 && dark(x - 1, y - 1) && !dark(x - 1, y)) at(x, y) |= left;  // bottom edge of (x-1, y-1)
      if (y < n && dark(x - 1, y) && !dark(x, y)) at(x, y) |= down;       // right edge of (x-1, y)
      if (y > 0 && dark(x, y - 1) && !dark(x - 1, y - 1)) at(x, y) |= up;    // left edge of (x, y-1)
    }
  const auto point = [&](int x, int y) { return P2{x0 + module * x, y0 + module * y}; };
  Path outline;
  // Loops from the first corner, row by row, that still has an edge: the same path on every
  // platform. Following unused edges from a corner can only end back at it (as many edges enter
  // every corner as leave it); where two leave, either gives the same fill.
  for (int sy = 0; sy <= n; ++sy)
    for (int sx = 0; sx <= n; ++sx)
      while (at(sx, sy) != 0) {
        int x = sx, y = sy;
        std::uint8_t heading = 0;
        outline.move_to(point(x, y));
        do {
          std::uint8_t& edges = at(x, y);
          const std::uint8_t next = edges & static_cast<std::uint8_t>(-edges);  // the lowest bit
          edges &= static_cast<std::uint8_t>(~next);
          if (heading != 0 && next != heading) outline.line_to(point(x, y));  // a corner
          heading = next;
          x += next == right ? 1 : next == left ? -1 : 0;
          y += next == down ? 1 : next == up ? -1 : 0;
        } while (x != sx || y != sy);
        outline.close();
      }
  canvas.path(outline, Paint{std::nullopt, style.text, 1});
}

}  // namespace

void paint_text(Canvas& canvas, const PlacedText& t, Colour colour) {
  canvas.text(TextLine{t.baseline, Anchor::start, t.size, t.runs, colour});
  // The arrow over a \vec run, drawn as the scene painter draws it over a label (text.h's
  // constants), so a vector looks the same in a statement and in its figure.
  bool any = false;
  for (const TextRun& r : t.runs) any = any || r.arrow;
  if (!any) return;
  const std::vector<RunPlacement> placed = place_runs(t.runs, t.size);
  for (std::size_t i = 0; i < t.runs.size(); ++i) {
    if (!t.runs[i].arrow) continue;
    const RunPlacement& p = placed[i];
    const double y = t.baseline.y - (p.rise + p.top + kArrowGap * p.size);
    const double left = t.baseline.x + p.x + 0.06 * p.size;
    const double right = t.baseline.x + p.x + p.width - 0.02 * p.size;
    const double head = kArrowHead * p.size, half = kArrowHeadHalf * p.size;
    Path shaft;
    shaft.move_to({left, y}).line_to({right - head * 0.6, y});
    canvas.path(shaft, Paint{StrokeStyle{colour, kArrowStroke * p.size, {}}, std::nullopt, 1});
    Path tip;
    tip.move_to({right, y}).line_to({right - head, y - half}).line_to({right - head, y + half}).close();
    canvas.path(tip, Paint{std::nullopt, colour, 1});
  }
}

void paint_page(Canvas& canvas, const LaidOutPage& page, const PageStyle& style) {
  canvas.path(rectangle({0, 0, page.size.width_pt, page.size.height_pt}), Paint{std::nullopt, style.paper, 1});
  if (!page.boxes.empty()) {
    canvas.begin_group("boxes");
    // Neighbouring boxes of one paint (a comb's cells, a row of ticks) as one path of
    // rectangles: the same marks as one path each, in a fraction of the bytes and the PDF's
    // operators. Boxes do not overlap; only the antialiasing along an edge two cells share
    // differs (each cell's fill no longer covers half of its neighbour's stroke there).
    Path batch;
    std::optional<BoxKind> batch_kind;
    const auto flush = [&] {
      if (batch_kind) paint_boxes(canvas, *batch_kind, batch, style);
      batch = Path{};
      batch_kind.reset();
    };
    for (const PlacedBox& b : page.boxes) {
      if (b.kind == BoxKind::shade) {
        flush();
        paint_shade(canvas, b.rect, style);
        continue;
      }
      const BoxKind paint_kind = b.kind == BoxKind::answer ? BoxKind::answer : BoxKind::tick;
      if (batch_kind && *batch_kind != paint_kind) flush();
      batch_kind = paint_kind;
      append_rectangle(batch, b.rect);
    }
    flush();
    canvas.end_group();
  }
  if (!page.rules.empty()) {
    canvas.begin_group("rules");
    for (const PlacedRule& r : page.rules) {
      Path p;
      p.move_to(r.a).line_to(r.b);
      canvas.path(p, Paint{StrokeStyle{style.ink(r.ink), r.width, {}}, std::nullopt, 1});
    }
    canvas.end_group();
  }
  for (const PlacedFigure& f : page.figures) {
    if (f.scene == nullptr) continue;
    canvas.begin_group("figure", "figure");
    paint_scene(canvas, *f.scene, f.rect.x, f.rect.y, f.rect.width, style.scene);
    canvas.end_group();
  }
  if (!page.marks.empty()) {
    canvas.begin_group("marks");
    for (const PageRect& m : page.marks) canvas.path(rectangle(m), Paint{std::nullopt, style.ink(Ink::text), 1});
    canvas.end_group();
  }
  if (!page.images.empty()) {
    canvas.begin_group("images");
    for (const PlacedImage& i : page.images)
      canvas.image(i.raster, Box{i.rect.x, i.rect.y, i.rect.right(), i.rect.bottom()});
    canvas.end_group();
  }
  for (const PlacedQr& q : page.codes) {
    canvas.begin_group("qr-code");
    paint_qr(canvas, q, style);
    canvas.end_group();
  }
  if (!page.texts.empty()) {
    canvas.begin_group("text");
    for (const PlacedText& t : page.texts) paint_text(canvas, t, style.ink(t.ink));
    canvas.end_group();
  }
}

}  // namespace epure::render
