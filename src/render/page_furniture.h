#pragma once
// The page furniture (internal to layout.cpp): what every page carries besides its content, so
// that a loose page finds its owner — the header (course, title, sheet id, "page i/n", a rule;
// with Document::page_code, the page's QR code at its right end and the four corner marks a scan
// registers the page on) — and the first page's name and student number fields (a writing line
// and a comb, or a roster's student printed). Everything a page carries for its own sake is
// placed here, in one place.
#include "render/layout.h"
#include "render/layout_atoms.h"

namespace epure::render::layout_detail {

// The first page's name and student number: a writing line for the name and the number's comb
// (Document::student_number_cells) or line, or the roster's student printed: an atom at the top
// of the content, since the first page's content flows under it.
Atom name_row(const Document& doc, const LayoutStyle& style, const TextArea& area);

// Adds the header to a laid-out page whose number and the document's page count are set: its
// texts, rule and block go first in the page's lists; with Document::page_code, the page's code
// and marks too.
void add_header(LaidOutPage& page, const Document& doc, const LayoutStyle& style, const TextArea& area);

}  // namespace epure::render::layout_detail
