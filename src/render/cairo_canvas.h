#pragma once
// The cairo backend: the painter's calls (canvas.h) drawn with cairo, text in DejaVu Sans set
// glyph by glyph at font_metrics.h's advances (pango loads the font, and sets the rare character
// DejaVu Sans lacks from a fallback font). It draws on whatever surface the cairo context targets: a PDF page
// (pdf_document.h) or an image for PNG previews. Like the SVG canvas it decides nothing: every
// position comes from the painter and every width from font_metrics.h, so both backends draw the
// same figure.
#include <cairo.h>

#include <array>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "render/canvas.h"

typedef struct _PangoContext PangoContext;
typedef struct _PangoFontMap PangoFontMap;
typedef struct _PangoLayout PangoLayout;
typedef struct _PangoFont PangoFont;

namespace epure::render {

class CairoCanvas final : public Canvas {
 public:
  // Draws through `cr` (not owned; it must outlive the canvas), in its current user space, whose
  // unit is taken to be the point. Fonts come from `fonts` (not owned) when given, else from
  // the calling thread's default font map: a canvas used from another thread than the one that
  // made it needs a font map of its own, since pango's font maps are not thread-safe.
  explicit CairoCanvas(cairo_t* cr, PangoFontMap* fonts = nullptr);
  ~CairoCanvas() override;
  CairoCanvas(const CairoCanvas&) = delete;
  CairoCanvas& operator=(const CairoCanvas&) = delete;

  void begin_group(std::string_view cls, std::string_view id = {}) override;
  void end_group() override;
  void push_clip(const Box& box) override;
  void pop_clip() override;
  void path(const Path& path, const Paint& paint) override;
  void disc(P2 centre, double radius, const Paint& paint) override;
  void text(const TextLine& line) override;
  void image(const Raster& raster, const Box& box) override;

  // Draws the text still held back (see pending_): before the page is shown or the surface read.
  // Every other drawing call, and the destructor, does it first.
  void flush_text();

  // The advance width pango sets `run` at, `size` points: font_metrics.h's widths must be these
  // (the tests compare them), or the PDF's text would not be where layout measured it.
  double set_width(const TextRun& run, double size);

  // The cairo face glyphs are set from (regular or bold; null when DejaVu Sans is missing): the
  // thread's own with a font map of the canvas's own, else pango's, which every thread shares.
  // For the tests, which check that two documents on two threads share none.
  cairo_font_face_t* glyph_face(bool bold) { return face(bold).face; }

 private:
  void fill_and_stroke(const Paint& paint);
  PangoLayout* shaped(const TextRun& run, double size);
  // A run set glyph by glyph at font_metrics.h's advances, in `colour`; false (nothing drawn nor
  // held) when the face lacks one of its characters, which pango then sets from a fallback font.
  bool set_glyphs(const TextRun& run, double size, double x, double baseline, Colour colour);

  // DejaVu Sans (regular, bold) as pango chose it, and its glyph for each character met so far
  // (0: none). Text is set from these directly: shaping through pango costs more than all the
  // rest of a page, and with no kerning nor ligature (see shaped) it gives the same glyphs at
  // the same advances.
  struct LoadedFace {
    PangoFont* font = nullptr;
    cairo_font_face_t* face = nullptr;
    cairo_scaled_font_t* scaled = nullptr;
    std::unordered_map<char32_t, unsigned long> glyphs;
  };
  LoadedFace& face(bool bold);
  std::array<LoadedFace, 2> faces_;
  cairo_font_options_t* font_options_ = nullptr;

  // Runs set but not drawn yet, all in one face, size and colour, drawn by one
  // cairo_show_text_glyphs when the next run differs or anything else is drawn. cairo's PDF
  // writer keeps a text object's glyphs across calls and writes the same operators whether
  // glyphs came in one call or many; but each call costs, before a byte is written, a copy into
  // cairo's recording of the page, an analysis pass over it, the glyphs' extents and the
  // font's state twice over: about as much as setting the glyphs themselves.
  struct PendingText {
    const LoadedFace* face = nullptr;
    double size = 0;
    Colour colour;
    std::string utf8;
    std::vector<cairo_glyph_t> glyphs;
    std::vector<cairo_text_cluster_t> clusters;
  };
  PendingText pending_;

  cairo_t* cr_;
  // With a font map of its own (a document drawn on a thread of its own), faces of its own too:
  // glyphs are set from the font file opened again on the thread that first sets text, a face
  // no canvas first used on another thread shares (thread_face).
  bool own_faces_;
  PangoContext* context_ = nullptr;
  // Runs shaped once and drawn as often as they occur (labels, axis numbers and the templates'
  // words repeat from sheet to sheet): shaping is most of the cost of text.
  std::unordered_map<std::string, PangoLayout*> shaped_;
};

}  // namespace epure::render
