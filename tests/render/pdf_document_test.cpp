#include "render/pdf_document.h"
#include "pdf_surface_into.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <doctest/doctest.h>
#include <pango/pangocairo.h>
#include <fmt/format.h>

#include <array>
#include <cstdlib>
#include <span>
#include <vector>
#include <stdexcept>
#include <variant>
#include <string>
#include <string_view>
#include <thread>

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
  PdfDocument pdf(string_sink(bytes), metadata());
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

  // a second document's links are on its own pages, after the first's and a blank one
  std::string bytes;
  PdfDocument two(string_sink(bytes), metadata());
  two.add(pages, "K7QF-3M2X", true, {}, std::span(links).first(1));
  two.add_blank(PageSize::a4(), "K7QF-3M2X");
  two.add(pages, "K7QF-3M2Y", true, {}, std::span(links).first(1));
  two.finish();
  CHECK(two.links() == 2);
  CHECK(testing::count(bytes, "/URI (explore.html#K7QF-3M2X.1)") == 2);
  // (tests/render/pdf_stream_writer_test.cpp reads the pages back; tests/cli/pdf.sh with qpdf)
}

TEST_CASE("pdf: a sink that fails is an exception, not a file that looks whole") {
  const Document doc = sample_document(1);  // the pages point into its scenes
  const auto pages = layout_document(doc);
  PdfDocument pdf(PdfSink{[](std::string_view) { throw std::runtime_error("disk full"); }, {}}, metadata());
  // cairo writes as it goes: the error surfaces at the first page drawn, or at the latest when
  // the trailer is written; it is the sink's own
  CHECK_THROWS_WITH_AS((pdf.add(pages, "K7QF-3M2X", false), pdf.finish()), "disk full", std::runtime_error);
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

// Ink of a text line drawn by the canvas (glyph by glyph) and by a plain pango layout with the
// same font and options, on two grey images: the same glyphs at the same places.
TEST_CASE("pdf: text set glyph by glyph looks as pango sets it, and pango still sets what DejaVu lacks") {
  constexpr int kW = 420, kH = 40;
  auto draw = [&](const std::string& text, bool with_canvas) {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, kW, kH);
    cairo_t* cr = cairo_create(surface);
    cairo_scale(cr, 2, 2);  // 144 dpi: half a pixel here is a quarter of a point
    {
      CairoCanvas canvas(cr);
      const std::vector<TextRun> runs{TextRun{text, Shift::none, false, false}};
      if (with_canvas) {
        canvas.text(TextLine{{2, 14}, Anchor::start, 10, runs, Colour{0, 0, 0}});
      } else {
        PangoLayout* layout = pango_cairo_create_layout(cr);
        cairo_font_options_t* options = cairo_font_options_create();
        cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
        cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
        pango_cairo_context_set_font_options(pango_layout_get_context(layout), options);
        cairo_font_options_destroy(options);
        pango_cairo_context_set_resolution(pango_layout_get_context(layout), 72);
        pango_context_set_round_glyph_positions(pango_layout_get_context(layout), FALSE);
        pango_layout_context_changed(layout);
        // The font and features by markup, another road than the canvas's to the same setting.
        char* escaped = g_markup_escape_text(text.data(), static_cast<gssize>(text.size()));
        const std::string markup = fmt::format(
            "<span font_family='DejaVu Sans' font_size='10240' font_features='kern 0, liga 0, clig 0'>{}</span>", escaped);
        g_free(escaped);
        pango_layout_set_markup(layout, markup.data(), static_cast<int>(markup.size()));
        cairo_move_to(cr, 2, 14 - pango_layout_get_baseline(layout) / double(PANGO_SCALE));
        pango_cairo_show_layout(cr, layout);
        g_object_unref(layout);
      }
    }
    cairo_surface_flush(surface);
    std::vector<int> ink;
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) ink.push_back(data[y * stride + x]);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    return ink;
  };
  // Latin, accents, French punctuation, Greek, the course's symbols, and (last) a character
  // DejaVu Sans has no glyph for, which pango takes from another font.
  for (const std::string text : {"AV To Wa ffi", "Numéro d’étudiant : « aucun »", "‖AB‖ = √(x² + y²) ≈ 2,17",
                                  "u∧v · t ≤ 1 → θ = −45° ∘ ↦", "中"}) {
    CAPTURE(text);
    const std::vector<int> glyphs = draw(text, true);
    const std::vector<int> pango = draw(text, false);
    long total = 0, differ = 0;
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
      total += pango[i];
      differ += std::abs(glyphs[i] - pango[i]) > 96;
    }
    CHECK(total > 1000);             // something was drawn
    CHECK(differ * 50 < total / 255);  // and where pango draws it: antialiasing apart
  }
}

// The canvas holds runs of one face, size and colour back and draws them with one cairo call
// (cairo_canvas.h, PendingText): cairo's PDF writer must then write the bytes it writes for a
// call a line. If a cairo release wrote its text objects call by call, this fails, and the
// holding back must go (the class sets would no longer be the same bytes as before it).
TEST_CASE("pdf: text held back and drawn in one call writes the bytes of text drawn line by line") {
  auto pdf = [](bool line_by_line) {
    std::string bytes;
    test::PdfInto into(bytes, 595, 842);
    cairo_pdf_surface_set_metadata(into.surface(), CAIRO_PDF_METADATA_CREATE_DATE, "2026-01-01T00:00:00Z");
    cairo_t* cr = into.cr();
    {
      CairoCanvas canvas(cr);
      // Plain, bold, a subscript (another size), accents, symbols, and a character DejaVu Sans
      // lacks (pango's road, between held runs).
      const std::vector<TextRun> runs[] = {
          {{"Intersection d'un rayon ", Shift::none, false, false}, {"et d'un cercle", Shift::none, false, false}},
          {{"Exercice 2 : ", Shift::none, false, true}, {"projection de C sur la droite", Shift::none, false, false}},
          {{"t", Shift::none, false, false}, {"1", Shift::sub, false, false}, {" = 2,17 ≈ √(x² + y²)", Shift::none, false, false}},
          {{"u∧v · t ≤ 1 → θ = −45° ", Shift::none, false, false}, {"中", Shift::none, false, false}, {" fin", Shift::none, false, false}},
      };
      Path box;
      box.move_to({40, 0}).line_to({60, 0}).line_to({60, 10}).close();
      for (int i = 0; i < 48; ++i) {
        const Colour colour = i % 6 == 5 ? Colour{200, 0, 0} : Colour{0, 0, 0};
        canvas.text(TextLine{{50, 40 + 15.0 * i}, Anchor::start, i % 8 == 0 ? 12.0 : 10.0, runs[i % 4], colour});
        if (line_by_line) canvas.flush_text();
        if (i % 9 == 4) canvas.path(box, Paint{std::nullopt, Colour{0, 0, 200}, 1});
      }
    }
    into.finish();
    return bytes;
  };
  const std::string held = pdf(false);
  CHECK(held.size() > 2000);
  CHECK(held == pdf(true));
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

// A canvas given a font map of its own (a document drawn on a thread of its own) sets its glyphs
// from the font file opened again on its thread (cairo_canvas.cpp, thread_face), so that two
// documents drawn at once share no cairo face nor the locks of its scaled fonts. The faces are
// other objects, the PDF must be the same bytes: the same glyphs, widths and embedded subsets as
// through the faces pango shares, whether the documents are drawn one after the other or at once.
TEST_CASE("pdf: text in faces of the thread's own writes the bytes of pango's shared faces, on two threads at once") {
  // handed_over: the first lines set on one thread, which then ends, the rest on another, as
  // keys.pdf's canvas is drawn by a thread a batch
  auto pdf = [](bool own_faces, bool handed_over = false) {
    std::string bytes;
    test::PdfInto into(bytes, 595, 842);
    cairo_pdf_surface_set_metadata(into.surface(), CAIRO_PDF_METADATA_CREATE_DATE, "2026-01-01T00:00:00Z");
    cairo_t* cr = into.cr();
    PangoFontMap* fonts = own_faces ? pango_cairo_font_map_new() : nullptr;
    {
      CairoCanvas canvas(cr, fonts);
      const std::vector<TextRun> runs[] = {
          {{"Intersection d'un rayon ", Shift::none, false, false}, {"et d'un cercle", Shift::none, false, true}},
          {{"t", Shift::none, false, false}, {"1", Shift::sub, false, false}, {" = 2,17 ≈ √(x² + y²)", Shift::none, false, false}},
          {{"u∧v · t ≤ 1 → θ = −45° ", Shift::none, false, false}, {"中", Shift::none, false, false}, {" fin", Shift::none, false, false}},
      };
      auto lines = [&](int from, int to) {
        for (int i = from; i < to; ++i) canvas.text(TextLine{{50, 40 + 18.0 * i}, Anchor::start, 10, runs[i % 3], Colour{}});
      };
      if (handed_over) {
        std::jthread([&] { lines(0, 20); }).join();
        std::jthread([&] { lines(20, 40); }).join();
      } else {
        lines(0, 40);
      }
    }
    if (fonts != nullptr) g_object_unref(fonts);
    into.finish();
    return bytes;
  };
  const std::string shared = pdf(false);
  REQUIRE(shared.size() > 2000);
  CHECK(pdf(true) == shared);
  CHECK(pdf(true, true) == shared);
  // Four documents at once, two a thread, each with its font map: the same bytes again.
  std::string drawn[4];
  {
    std::jthread a([&] { drawn[0] = pdf(true), drawn[1] = pdf(true); });
    std::jthread b([&] { drawn[2] = pdf(true), drawn[3] = pdf(true); });
  }
  for (const std::string& d : drawn) CHECK(d == shared);
}

TEST_CASE("pdf: canvases with font maps of their own share no face across threads, and one within a thread") {
  // The faces each canvas sets its glyphs from, made on one thread (both canvases alive at once)
  auto faces = [](bool own_maps) {
    std::string bytes;
    test::PdfInto into(bytes, 100, 100);
    cairo_t* cr = into.cr();
    PangoFontMap* maps[2] = {own_maps ? pango_cairo_font_map_new() : nullptr,
                             own_maps ? pango_cairo_font_map_new() : nullptr};
    std::array<cairo_font_face_t*, 4> seen{};
    {
      CairoCanvas a(cr, maps[0]), b(cr, maps[1]);
      seen = {a.glyph_face(false), a.glyph_face(true), b.glyph_face(false), b.glyph_face(true)};
      // held until compared: a face freed with its thread could leave its address to another's
      for (cairo_font_face_t* f : seen) cairo_font_face_reference(f);
    }
    for (PangoFontMap* m : maps)
      if (m != nullptr) g_object_unref(m);
    return seen;
  };
  std::array<cairo_font_face_t*, 4> here{}, there{}, pangos{};
  {
    std::jthread a([&] { here = faces(true); });
  }
  {
    std::jthread b([&] { there = faces(true); });
    pangos = faces(false);
  }
  for (cairo_font_face_t* f : here) REQUIRE(f != nullptr);
  CHECK(here[0] != here[1]);                          // regular and bold
  CHECK((here[0] == here[2] && here[1] == here[3]));  // one thread: one face a file
  CHECK(there[0] != here[0]);                         // another thread: other faces
  CHECK(there[1] != here[1]);
  CHECK(pangos[0] != here[0]);                        // and not pango's
  CHECK(pangos[0] == pangos[2]);
  CHECK(cairo_font_face_get_type(here[0]) == CAIRO_FONT_TYPE_FT);
  for (const auto* set : {&here, &there, &pangos})
    for (cairo_font_face_t* f : *set) cairo_font_face_destroy(f);
}
