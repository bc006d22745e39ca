#include "render/svg_page.h"

#include <algorithm>

#include <fmt/format.h>

#include "render/svg_scene.h"
#include "render/svg_writer.h"

namespace epure::render {
namespace {

// Grey enough to read as "between two sheets of paper", light enough not to print as a bar.
constexpr Colour kBand{0xb8, 0xb8, 0xb8};

void open_svg(SvgWriter& w, const Document& doc, double width, double height) {
  w.declaration();
  const std::string wn = format_number(width), hn = format_number(height);
  std::vector<SvgWriter::Attr> root{{"xmlns", "http://www.w3.org/2000/svg"},
                                    {"version", "1.1"},
                                    {"width", wn + "pt"},
                                    {"height", hn + "pt"},
                                    {"viewBox", "0 0 " + wn + " " + hn}};
  if (!doc.language.empty()) root.emplace_back("xml:lang", doc.language);
  root.emplace_back("font-family", kFontFamily);
  root.emplace_back("xml:space", "preserve");  // inherited by every text (see SvgCanvas::text)
  w.start("svg", root);
  w.element("title", {}, doc.title);
  // What a screen reader needs to tell one sheet from another.
  w.element("desc", {}, fmt::format("{} — {} — {}", doc.course, doc.title, doc.sheet_id));
}

void write_page(SvgWriter& w, const LaidOutPage& page, double y, const PageStyle& style) {
  std::vector<SvgWriter::Attr> attrs{{"id", fmt::format("page{}", page.number)}, {"class", "page"}};
  if (y > 0) attrs.emplace_back("transform", "translate(0 " + format_number(y) + ")");
  w.start("g", attrs);
  SvgCanvas canvas(w);
  paint_page(canvas, page, style);
  w.end("g");
}

}  // namespace

std::string page_to_svg(const LaidOutPage& page, const Document& doc, const PageStyle& style) {
  SvgWriter w;
  open_svg(w, doc, page.size.width_pt, page.size.height_pt);
  write_page(w, page, 0, style);
  w.end("svg");
  return w.finish();
}

std::string pages_to_svg(const std::vector<LaidOutPage>& pages, const Document& doc, const PageStyle& style) {
  double width = 0, height = 0;
  for (const auto& p : pages) {
    width = std::max(width, p.size.width_pt);
    height += p.size.height_pt;
  }
  const double gaps = pages.empty() ? 0 : kPageGap * static_cast<double>(pages.size() - 1);
  SvgWriter w;
  open_svg(w, doc, width, height + gaps);
  double y = 0;
  for (const auto& p : pages) {
    if (y > 0) {
      // The band only between pages: under a page it would show at its anti-aliased edges.
      w.element("rect", {{"class", "band"}, {"y", y - kPageGap}, {"width", width}, {"height", kPageGap},
                         {"fill", kBand.hex()}});
    }
    write_page(w, p, y, style);
    y += p.size.height_pt + kPageGap;
  }
  w.end("svg");
  return w.finish();
}

std::string document_to_svg(const Document& doc, const PageStyle& style) {
  return pages_to_svg(layout_document(doc), doc, style);
}

}  // namespace epure::render
