#pragma once
// Laid-out pages as a PDF, drawn with cairo and pango (cairo_canvas.h) through the same page
// painter as the SVG pages. Text is real text in embedded DejaVu Sans subsets, so it can be
// selected, searched and extracted. The bytes are streamed to a sink as cairo produces them,
// the links written in on the way (pdf_stream_writer.h); with the creation date fixed
// (SOURCE_DATE_EPOCH), the same pages give the same bytes.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "render/layout.h"
#include "render/page_painter.h"
#include "render/pdf_stream_writer.h"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;
typedef struct _PangoFontMap PangoFontMap;

namespace epure::render {

struct PdfMetadata {
  std::string title, author, subject, keywords;
  std::string creator;  // the program: "epure 0.4.0"
  // Creation and modification date, seconds since 1970 UTC; unset: no date, so that the bytes
  // depend on nothing but the pages.
  std::optional<std::int64_t> date;
};

// The date a reproducible build asks for: SOURCE_DATE_EPOCH when it is set to a number of
// seconds, nothing otherwise. Throws std::runtime_error for a value that is not a number.
std::optional<std::int64_t> source_date_epoch();

// The links of a document's sections (Section::link), each on the sections' heading where it is
// placed (a section split across pages: on its first part), the uri prefixed with `base` ("../"
// for a PDF one directory below the set's).
std::vector<PageLink> section_links(const std::vector<LaidOutPage>& pages, const Document& doc,
                                    std::string_view base = {});

// A PDF being written. It has its own font map, so that two documents can be drawn on two
// threads (pango's font maps are not thread-safe); one document is used by one thread at a time.
class PdfDocument {
 public:
  PdfDocument(PdfSink sink, const PdfMetadata& metadata, PageSize first_page = PageSize::a4());
  ~PdfDocument();
  PdfDocument(const PdfDocument&) = delete;
  PdfDocument& operator=(const PdfDocument&) = delete;

  // Appends the pages of one document. `label` names them in a viewer's page list ("<label>
  // 1/3") and, when `outline` is set, in the bookmarks, pointing at the first page.
  // `links`: annotations on these pages (PageLink::page indexes `pages`), written with them.
  void add(const std::vector<LaidOutPage>& pages, std::string_view label, bool outline,
           const PageStyle& style = {}, std::span<const PageLink> links = {});
  // An empty page, to make the next document start on an odd page for duplex printing.
  void add_blank(PageSize size, std::string_view label);
  int pages() const { return pages_; }
  // The link annotations written so far.
  int links() const;

  // Writes the trailer; throws std::runtime_error when cairo or the sink failed at any point
  // (the sink's own exception, e.g. the file's "cannot write").
  void finish();

 private:
  void begin_page(PageSize size);
  void check_stream();
  struct Stream;  // what cairo writes into: the link writer, and the sink's error
  std::unique_ptr<Stream> stream_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
  PangoFontMap* fonts_ = nullptr;
  std::unique_ptr<class CairoCanvas> canvas_;
  int pages_ = 0;
  bool finished_ = false;
};

// The pages as one PDF in memory (tests and --split), with their links.
std::string pages_to_pdf(const std::vector<LaidOutPage>& pages, std::string_view label,
                         const PdfMetadata& metadata, const PageStyle& style = {},
                         std::span<const PageLink> links = {});

// A page (or a scene) as a PNG image at `dpi`, for previews and the backends' pixel comparison.
std::string page_to_png(const LaidOutPage& page, double dpi, const PageStyle& style = {});
std::string scene_to_png(const Scene& scene, double width_pt, double dpi, const Style& style = Style::print());

}  // namespace epure::render
