#pragma once
// The page furniture (internal to layout.cpp): what every page carries besides its content, so
// that a loose page finds its owner — the header (course, title, sheet id, "page i/n", a rule) —
// and the first page's name and student number fields with the sheet id as a QR code. Everything
// a page carries for its own sake is placed here, in one place: marks or a code per page belong
// here too.
#include "render/layout.h"
#include "render/layout_atoms.h"

namespace epure::render::layout_detail {

// The first page's name and student number writing lines, with the sheet id's QR code at the
// right end of the row: an atom at the top of the content, since the first page's content flows
// under it.
Atom name_row(const Document& doc, const LayoutStyle& style, const TextArea& area);

// Adds the header to a laid-out page whose number and the document's page count are set: its
// texts, rule and block go first in the page's lists.
void add_header(LaidOutPage& page, const Document& doc, const LayoutStyle& style, const TextArea& area);

}  // namespace epure::render::layout_detail
