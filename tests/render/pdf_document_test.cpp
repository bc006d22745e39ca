#include "render/pdf_document.h"

#include <cairo.h>
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdlib>
#include <span>
#include <stdexcept>
#include <variant>
#include <string>
#include <string_view>

#include "render/cairo_canvas.h"
#include "render/text.h"
#include "sample_document.h"

using namespace epure::render;

namespace {

using testing::sample_document;

PdfMetadata metadata() {
  PdfMetadata m;
  m.title = "Rayon et cercle — feuille";
  m.author = "A. Teacher";
  m.subject = "Ray tracing";
  m.creator = "epure test";
  m.date = 1700000000;
  return m;
}

}  // namespace

TEST_CASE("pdf: a document's pages, one PDF page each, the same bytes every time") {
  const Document doc = sample_document(3);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  const std::string pdf = pages_to_pdf(pages, doc.sheet_id, metadata());
  CHECK(pdf.rfind("%PDF-1.5", 0) == 0);
  CHECK(pdf.find("%%EOF") != std::string::npos);
  CHECK(pdf == pages_to_pdf(pages, doc.sheet_id, metadata()));
  // Another date, other bytes: the date is really taken from the metadata (tests/cli/pdf.sh
  // reads it back with pdfinfo; here the Info dictionary sits in a compressed object stream).
  PdfMetadata later = metadata();
  later.date = 1700000060;
  CHECK(pages_to_pdf(pages, doc.sheet_id, later) != pdf);
}

TEST_CASE("pdf: pages, blank pages and labels counted as they are added") {
  const Document doc = sample_document(1);
  const auto pages = layout_document(doc);
  std::string bytes;
  PdfDocument pdf([&](std::string_view b) { bytes.append(b); }, metadata());
  pdf.add(pages, "K7QF-3M2X", true);
  CHECK(pdf.pages() == static_cast<int>(pages.size()));
  pdf.add_blank(PageSize::a4(), "K7QF-3M2X");
  pdf.add(pages, "K7QF-3M2Y", true);
  CHECK(pdf.pages() == 2 * static_cast<int>(pages.size()) + 1);
  pdf.finish();
  CHECK(bytes.find("K7QF-3M2Y") != std::string::npos);  // the outline and the page labels
}

TEST_CASE("pdf: links, as Link annotations with a URI, counted in the whole PDF's pages") {
  const Document doc = sample_document(3);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  const std::vector<PageLink> links{{0, {50, 60, 200, 14}, "explore.html#K7QF-3M2X.1"},
                                    {1, {50, 80, 200, 14}, "../explore.html#K7QF-3M2X.2"}};
  const std::string pdf = pages_to_pdf(pages, doc.sheet_id, metadata(), {}, links);
  CHECK(pdf.rfind("%PDF-1.5", 0) == 0);
  CHECK(pdf.find("/Subtype /Link") != std::string::npos);
  CHECK(pdf.find("/URI (explore.html#K7QF-3M2X.1)") != std::string::npos);
  CHECK(pdf.find("/URI (../explore.html#K7QF-3M2X.2)") != std::string::npos);
  // the layout's rectangle (from the top left) in PDF's user space (from the bottom left)
  CHECK(pdf.find(fmt::format("/Rect [ 50 {:.2f} 250 {:.2f} ]", pages[0].size.height_pt - 74,
                             pages[0].size.height_pt - 60)) != std::string::npos);
  CHECK(pdf == pages_to_pdf(pages, doc.sheet_id, metadata(), {}, links));  // no random ID
  CHECK(pages_to_pdf(pages, doc.sheet_id, metadata()).find("/Link") == std::string::npos);

  // a second document's links count its pages after the first's and a blank one
  std::string bytes;
  PdfDocument two([&](std::string_view b) { bytes.append(b); }, metadata());
  two.add(pages, "K7QF-3M2X", true, {}, std::span(links).first(1));
  two.add_blank(PageSize::a4(), "K7QF-3M2X");
  two.add(pages, "K7QF-3M2Y", true, {}, std::span(links).first(1));
  two.finish();
  REQUIRE(two.links().size() == 2);
  CHECK(two.links()[0].page == 0);
  CHECK(two.links()[1].page == static_cast<int>(pages.size()) + 1);
  CHECK(bytes.find("/Link") == std::string::npos);  // cairo wrote none
  std::string linked;
  add_links(bytes, two.links(), [&](std::string_view b) { linked.append(b); });
  CHECK(linked.find("/URI (explore.html#K7QF-3M2X.1)") != std::string::npos);

  // a link past the last page is an error, not a file without it
  const std::vector<PageLink> far{{static_cast<int>(pages.size()), {0, 0, 10, 10}, "x"}};
  CHECK_THROWS_AS(add_links(pages_to_pdf(pages, doc.sheet_id, metadata()), far, [](std::string_view) {}),
                  std::runtime_error);
}

TEST_CASE("pdf: a sink that fails is an exception, not a file that looks whole") {
  const Document doc = sample_document(1);  // the pages point into its scenes
  const auto pages = layout_document(doc);
  PdfDocument pdf([](std::string_view) { throw std::runtime_error("disk full"); }, metadata());
  // cairo writes as it goes: the error surfaces at the first page drawn, or at the latest when
  // the trailer is written.
  CHECK_THROWS_AS((pdf.add(pages, "K7QF-3M2X", false), pdf.finish()), std::runtime_error);
}

TEST_CASE("pdf: SOURCE_DATE_EPOCH read as seconds, refused when it is not a number") {
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  CHECK(source_date_epoch() == 1700000000);
  ::setenv("SOURCE_DATE_EPOCH", "tomorrow", 1);
  CHECK_THROWS_AS(source_date_epoch(), std::runtime_error);
  ::setenv("SOURCE_DATE_EPOCH", "-5", 1);
  CHECK_THROWS_AS(source_date_epoch(), std::runtime_error);
  ::unsetenv("SOURCE_DATE_EPOCH");
  CHECK_FALSE(source_date_epoch().has_value());
}

TEST_CASE("pdf: pango sets every run at the width font_metrics measured") {
  // If kerning, ligatures or hinting crept in, the PDF's text would drift from where layout put
  // it (answer boxes, arrows over vectors, labels' clearance).
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 10, 10);
  cairo_t* cr = cairo_create(surface);
  {
    CairoCanvas canvas(cr);
    for (const std::string text :
         {"AV To Wa", "Numéro d’étudiant : K7QF-3M2X", "‖AB‖ = √(x² + y²) ≈ 2,17", "u∧v · t ≤ 1 → θ = −45°",
          "ffi fl office", "Intersection d'un rayon et d'un cercle"}) {
      for (bool bold : {false, true}) {
        CAPTURE(text);
        CAPTURE(bold);
        TextRun run{text, Shift::none, false, bold};
        for (double size : {7.0, 10.5}) {
          const double measured = text_width(std::vector<TextRun>{run}, size);
          CHECK(canvas.set_width(run, size) == doctest::Approx(measured).epsilon(0.002));
        }
      }
    }
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

TEST_CASE("png: a page and a scene drawn as PNG images of the asked size") {
  const Document doc = sample_document(1);
  const auto pages = layout_document(doc);
  const std::string png = page_to_png(pages[0], 36);
  REQUIRE(png.size() > 24);
  CHECK(png.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  // IHDR: width and height, big-endian, at bytes 16 and 20.
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  CHECK(be32(16) == 298);  // 595.3 pt at 36 dpi
  CHECK(be32(20) == 421);
  const auto* figure = std::get_if<Figure>(&doc.sections[0].blocks[2]);
  REQUIRE(figure != nullptr);
  CHECK(scene_to_png(figure->scene, 300, 72).rfind("\x89PNG", 0) == 0);
}
