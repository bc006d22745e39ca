#include "render/page_painter.h"

#include <algorithm>
#include <cstddef>
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

// The dark modules as one path of rectangles: a row's neighbouring modules merged into a run,
// and a run repeated on the rows below it into one taller rectangle, so that a reader sees no
// seams between modules at any zoom, and the path has about a quarter fewer rectangles than runs
// (a QR code's finder patterns and timing lines repeat runs row after row).
void paint_qr(Canvas& canvas, const PlacedQr& qr, const PageStyle& style) {
  canvas.path(rectangle(qr.rect), Paint{std::nullopt, style.paper, 1});
  const QrCode& code = qr.code;
  const double module = qr.rect.width / (code.size + 2 * kQrQuietZone);
  const double x0 = qr.rect.x + module * kQrQuietZone, y0 = qr.rect.y + module * kQrQuietZone;
  struct Block {
    int x, end, top, rows;  // in modules
  };
  std::vector<Block> done, open;  // open: the blocks that reach the row above, left to right
  for (int y = 0; y < code.size; ++y) {
    std::vector<Block> row;
    std::size_t o = 0;
    for (int x = 0; x < code.size;) {
      if (!code.dark(x, y)) {
        ++x;
        continue;
      }
      int end = x;
      while (end < code.size && code.dark(end, y)) ++end;
      while (o < open.size() && open[o].x < x) done.push_back(open[o++]);
      if (o < open.size() && open[o].x == x && open[o].end == end) {
        row.push_back(open[o++]);
        ++row.back().rows;
      } else {
        row.push_back({x, end, y, 1});
      }
      x = end;
    }
    while (o < open.size()) done.push_back(open[o++]);
    open = std::move(row);
  }
  done.insert(done.end(), open.begin(), open.end());
  // top to bottom, then left to right: the same order on every platform
  std::sort(done.begin(), done.end(), [](const Block& a, const Block& b) { return a.top != b.top ? a.top < b.top : a.x < b.x; });
  Path dark;
  for (const Block& b : done) {
    const PageRect r{x0 + module * b.x, y0 + module * b.top, module * (b.end - b.x), module * b.rows};
    dark.move_to({r.x, r.y}).line_to({r.right(), r.y}).line_to({r.right(), r.bottom()}).line_to({r.x, r.bottom()}).close();
  }
  canvas.path(dark, Paint{std::nullopt, style.text, 1});
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
    // operators. Boxes do not overlap, so filling them together changes no pixel.
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
