#pragma once
// From a laid-out page (layout.h) to Canvas calls, once for every backend: the SVG page writer
// and the cairo backend both draw a page through this, so they draw the same page. Nothing is
// measured or moved here; this only gives the page's inks, boxes and rules their look.
#include "render/canvas.h"
#include "render/layout.h"
#include "render/style.h"

namespace epure::render {

struct PageStyle {
  Colour paper{0xff, 0xff, 0xff};
  Colour text{0x00, 0x00, 0x00};
  Colour muted{0x6b, 0x6b, 0x6b};
  Colour answer{0x0b, 0x3d, 0x91};  // a key's answers: dark blue, still dark in grayscale

  Colour box_stroke{0x55, 0x55, 0x55};
  double box_width = 0.7;
  Colour tick_stroke{0x33, 0x33, 0x33};
  double tick_width = 0.8;
  Colour shade{0xf0, 0xf2, 0xf5};
  Colour shade_bar{0x9a, 0xa5, 0xb4};  // a bar down the left of a shaded paragraph
  double shade_bar_width = 2;

  // The figures' style: layout reserved scene_height with Style::print(), so keep its sizes.
  Style scene = Style::print();

  Colour ink(Ink i) const { return i == Ink::muted ? muted : i == Ink::answer ? answer : text; }
};

// Draws `page` in page coordinates (points, y down, origin at its top-left corner), paper first.
void paint_page(Canvas& canvas, const LaidOutPage& page, const PageStyle& style = {});

// One line of text with the arrows of its \vec runs, from the left end of its baseline.
void paint_text(Canvas& canvas, const PlacedText& text, Colour colour);

}  // namespace epure::render
