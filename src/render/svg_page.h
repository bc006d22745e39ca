#pragma once
// Laid-out pages as SVG 1.1: one page per document, or all pages of a Document stacked top to
// bottom in one tall SVG with a thin band between them (the single-file sheets and keys of
// `epure generate`). viewBox in points, <title> and <desc>, the document's language as xml:lang,
// text as text in DejaVu Sans. Drawn through page_painter.h, as the PDF backend will be.
#include <string>
#include <vector>

#include "render/document.h"
#include "render/layout.h"
#include "render/page_painter.h"

namespace epure::render {

// The band between two stacked pages, points.
inline constexpr double kPageGap = 8;

// One page as a standalone SVG document. `doc` gives the title, description and language.
std::string page_to_svg(const LaidOutPage& page, const Document& doc, const PageStyle& style = {});

// The pages (of `doc`'s layout) stacked in one SVG, kPageGap apart on a grey band.
std::string pages_to_svg(const std::vector<LaidOutPage>& pages, const Document& doc,
                         const PageStyle& style = {});

// layout_document, then pages_to_svg. The same Document gives the same bytes.
std::string document_to_svg(const Document& doc, const PageStyle& style = {});

}  // namespace epure::render
