// layout_document: a Document's sections measured and broken into atoms (section_atoms.h, with
// the text measured once in text_measure.h), the atoms put on pages (paginate.h), each page given
// its furniture (page_furniture.h); and, for a document over its page budget, the same again with
// its tallest figures set smaller.
#include "render/layout.h"

#include <algorithm>
#include <cstddef>

#include "render/layout_atoms.h"
#include "render/page_furniture.h"
#include "render/paginate.h"
#include "render/section_atoms.h"

namespace epure::render {
namespace {

using namespace layout_detail;

std::vector<LaidOutPage> lay_out(const Document& doc, const LayoutStyle& style) {
  SectionAtoms sections(doc, style);
  sections.build();
  std::vector<LaidOutPage> pages = Paginator(doc, style, sections).run();
  const TextArea area(doc, style);
  for (auto& page : pages) {
    page.count = static_cast<int>(pages.size());
    add_header(page, doc, style, area);
  }
  return pages;
}

}  // namespace

std::vector<LaidOutPage> layout_document(const Document& doc, const LayoutStyle& style) {
  std::vector<LaidOutPage> pages = lay_out(doc, style);
  const auto budget = static_cast<std::size_t>(std::max(doc.page_budget, 0));
  if (budget == 0 || pages.size() <= budget || !(style.figure_height_step > 0)) return pages;
  // The caps in whole steps from the first, so that every platform tries the same doubles.
  for (int step = 1;; ++step) {
    LayoutStyle lower = style;
    lower.figure_max_height = style.figure_max_height - step * style.figure_height_step;
    if (lower.figure_max_height < style.figure_min_height - kFitSlack) break;
    std::vector<LaidOutPage> fewer = lay_out(doc, lower);
    if (fewer.size() <= budget) return fewer;
  }
  return pages;
}

}  // namespace epure::render
