#include "render/svg_page.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include "render/svg_writer.h"
#include "sample_document.h"

using namespace epure::render;

using epure::render::testing::count;
using epure::render::testing::sample_document;

TEST_CASE("svg page: every page of a document stacked in one SVG") {
  const Document doc = sample_document(4);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  const std::string svg = pages_to_svg(pages, doc);

  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(count(svg, "class=\"page\"") == pages.size());
  CHECK(count(svg, "class=\"band\"") == pages.size() - 1);
  CHECK(count(svg, "class=\"figure\"") == 4);
  CHECK(svg.find("xml:lang=\"fr\"") != std::string::npos);
  CHECK(svg.find("font-family=\"DejaVu Sans, sans-serif\"") != std::string::npos);
  // The page height, times the pages, plus the bands between them.
  const double h = doc.page.height_pt * static_cast<double>(pages.size()) +
                   kPageGap * static_cast<double>(pages.size() - 1);
  CHECK(svg.find(fmt::format("viewBox=\"0 0 {} {}\"", format_number(doc.page.width_pt), format_number(h))) !=
        std::string::npos);
  // Every string escaped, in <title> as in the header's text.
  CHECK(svg.find("<title>Rays &amp; &lt;circles&gt; — \"worksheet\"</title>") != std::string::npos);
  CHECK(svg.find("<circles>") == std::string::npos);
  // Text as text: the header's "page i/n" and a statement's accents are searchable.
  for (const auto& p : pages) CHECK(svg.find(fmt::format("page {}/{}", p.number, pages.size())) != std::string::npos);
  CHECK(svg.find("décimales") != std::string::npos);
  CHECK(svg.find("Numéro d’étudiant :") != std::string::npos);
}

TEST_CASE("svg page: one page alone, and the same bytes every time") {
  const Document doc = sample_document(2);
  const auto pages = layout_document(doc);
  const std::string one = page_to_svg(pages[0], doc);
  CHECK(count(one, "class=\"page\"") == 1);
  CHECK(count(one, "class=\"band\"") == 0);
  CHECK(one.find(fmt::format("viewBox=\"0 0 {} {}\"", format_number(doc.page.width_pt),
                             format_number(doc.page.height_pt))) != std::string::npos);
  CHECK(document_to_svg(doc) == document_to_svg(doc));
  CHECK(document_to_svg(doc) == pages_to_svg(pages, doc));
}

TEST_CASE("svg page: an empty document is one page with its header") {
  Document doc;
  doc.title = "Empty";
  doc.sheet_id = "AAAA-AAAA";
  const std::string svg = document_to_svg(doc);
  CHECK(count(svg, "class=\"page\"") == 1);
  CHECK(svg.find("page 1/1") != std::string::npos);
  CHECK(svg.find("xml:lang") == std::string::npos);  // no language, no empty tag
}
