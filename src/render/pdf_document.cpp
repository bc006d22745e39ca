#include "render/pdf_document.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <pango/pangocairo.h>

#include <charconv>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <stdexcept>

#include <fmt/format.h>

#include "render/cairo_canvas.h"
#include "render/scene_painter.h"

namespace epure::render {
namespace {

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// ISO 8601 in UTC, the form cairo's metadata takes.
std::string iso_date(std::int64_t seconds) {
  const std::time_t t = static_cast<std::time_t>(seconds);
  std::tm utc{};
  gmtime_r(&t, &utc);
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}Z", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                     utc.tm_hour, utc.tm_min, utc.tm_sec);
}

void check(cairo_status_t status, const char* what) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(fmt::format("{}: {}", what, cairo_status_to_string(status)));
}

}  // namespace

// cairo's bytes go through the link writer to the sink. An exception from the sink (a file that
// cannot be written) is kept and rethrown to the caller as it is: cairo only learns that the
// write failed.
struct PdfDocument::Stream {
  explicit Stream(PdfSink sink) : writer(std::move(sink)) {}
  PdfStreamWriter writer;
  std::exception_ptr error;
  bool discard = false;  // a document dropped unfinished: whatever cairo still writes goes nowhere

  static cairo_status_t write(void* closure, const unsigned char* data, unsigned int length) {
    auto* self = static_cast<Stream*>(closure);
    if (self->discard) return CAIRO_STATUS_SUCCESS;
    if (self->error) return CAIRO_STATUS_WRITE_ERROR;
    try {
      self->writer.write(std::string_view(reinterpret_cast<const char*>(data), length));
    } catch (...) {
      self->error = std::current_exception();
      return CAIRO_STATUS_WRITE_ERROR;  // cairo reports it; check_stream() rethrows the cause
    }
    return CAIRO_STATUS_SUCCESS;
  }
};

std::optional<std::int64_t> source_date_epoch() {
  const char* value = std::getenv("SOURCE_DATE_EPOCH");
  if (value == nullptr || *value == '\0') return std::nullopt;
  std::int64_t seconds = 0;
  const char* end = value + std::char_traits<char>::length(value);
  const auto [ptr, ec] = std::from_chars(value, end, seconds);
  if (ec != std::errc() || ptr != end || seconds < 0)
    throw std::runtime_error(
        fmt::format("SOURCE_DATE_EPOCH='{}' is not a number of seconds since 1970-01-01", value));
  return seconds;
}

PdfDocument::PdfDocument(PdfSink sink, const PdfMetadata& metadata, PageSize first_page)
    : stream_(std::make_unique<Stream>(std::move(sink))) {
  surface_ = cairo_pdf_surface_create_for_stream(Stream::write, stream_.get(), first_page.width_pt,
                                                 first_page.height_pt);
  check(cairo_surface_status(surface_), "cannot start a PDF");
  cairo_pdf_surface_restrict_to_version(surface_, CAIRO_PDF_VERSION_1_5);
  const auto set = [&](cairo_pdf_metadata_t key, const std::string& value) {
    if (!value.empty()) cairo_pdf_surface_set_metadata(surface_, key, value.c_str());
  };
  set(CAIRO_PDF_METADATA_TITLE, metadata.title);
  set(CAIRO_PDF_METADATA_AUTHOR, metadata.author);
  set(CAIRO_PDF_METADATA_SUBJECT, metadata.subject);
  set(CAIRO_PDF_METADATA_KEYWORDS, metadata.keywords);
  set(CAIRO_PDF_METADATA_CREATOR, metadata.creator);
  // Without a date to write, none at all: cairo would stamp the current time, and the same
  // spec and seed must give the same bytes. (cairo 1.16 drops a date it cannot parse; "none"
  // is such a value, and the only way to unset its default.)
  const std::string date = metadata.date ? iso_date(*metadata.date) : std::string("none");
  cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATE_DATE, date.c_str());
  cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_MOD_DATE, date.c_str());
  cr_ = cairo_create(surface_);
  fonts_ = pango_cairo_font_map_new();
  canvas_ = std::make_unique<CairoCanvas>(cr_, fonts_);
}

PdfDocument::~PdfDocument() {
  canvas_.reset();
  if (fonts_ != nullptr) g_object_unref(fonts_);
  if (cr_ != nullptr) cairo_destroy(cr_);
  if (surface_ != nullptr) {
    stream_->discard = !finished_;
    cairo_surface_destroy(surface_);
  }
}

void PdfDocument::begin_page(PageSize size) {
  cairo_pdf_surface_set_size(surface_, size.width_pt, size.height_pt);
  ++pages_;
}

std::vector<PageLink> section_links(const std::vector<LaidOutPage>& pages, const Document& doc,
                                    std::string_view base) {
  std::vector<PageLink> links;
  std::vector<bool> done(doc.sections.size(), false);
  for (std::size_t i = 0; i < pages.size(); ++i)
    for (const PlacedBlock& b : pages[i].blocks) {
      if (b.section < 0 || b.block < 0 || static_cast<std::size_t>(b.section) >= doc.sections.size()) continue;
      const Section& s = doc.sections[static_cast<std::size_t>(b.section)];
      const auto block = static_cast<std::size_t>(b.block);
      if (s.link.empty() || done[static_cast<std::size_t>(b.section)] || block >= s.blocks.size() ||
          !std::holds_alternative<Heading>(s.blocks[block]))
        continue;
      done[static_cast<std::size_t>(b.section)] = true;
      links.push_back({static_cast<int>(i), b.rect, std::string(base) + s.link});
    }
  return links;
}

int PdfDocument::links() const { return stream_->writer.annotations(); }

void PdfDocument::check_stream() {
  if (stream_->error) std::rethrow_exception(stream_->error);
}

void PdfDocument::add(const std::vector<LaidOutPage>& pages, std::string_view label, bool outline,
                      const PageStyle& style, std::span<const PageLink> links) {
  for (const PageLink& link : links)
    if (link.page < 0 || static_cast<std::size_t>(link.page) >= pages.size())
      throw std::runtime_error(fmt::format("a PDF link on page {} of {}", link.page + 1, pages.size()));
  // The names in a viewer's page list and the bookmark, written by the stream writer (not
  // cairo's, which keeps ~500 bytes a sheet until the end). A document's pages are "<label> 1/n"
  // to "<label> n/n"; pages numbered otherwise (a part of a document) are named one by one.
  bool whole = true;
  for (std::size_t i = 0; i < pages.size(); ++i)
    if (pages[i].number != static_cast<int>(i) + 1 || pages[i].count != static_cast<int>(pages.size())) whole = false;
  if (pages.empty()) {
    // nothing to name
  } else if (whole || label.empty()) {
    stream_->writer.add_run({std::string(label), static_cast<int>(pages.size()), true, outline});
  } else {
    for (std::size_t i = 0; i < pages.size(); ++i)
      stream_->writer.add_run({fmt::format("{} {}/{}", label, pages[i].number, pages[i].count), 1, false,
                               outline && i == 0, std::string(label)});
  }
  std::vector<PageLink> on_page;
  for (std::size_t i = 0; i < pages.size(); ++i) {
    const LaidOutPage& page = pages[i];
    begin_page(page.size);
    on_page.clear();
    for (const PageLink& link : links)
      if (static_cast<std::size_t>(link.page) == i) on_page.push_back(link);
    stream_->writer.begin_page(pages_, page.size.height_pt, on_page);
    paint_page(*canvas_, page, style);
    canvas_->flush_text();
    cairo_show_page(cr_);
    check_stream();
    stream_->writer.end_page();
  }
  check(cairo_status(cr_), "cannot draw a PDF page");
}

void PdfDocument::add_blank(PageSize size, std::string_view label) {
  stream_->writer.add_run({std::string(label), 1, false, false});
  begin_page(size);
  stream_->writer.begin_page(pages_, size.height_pt, {});
  cairo_show_page(cr_);
  check_stream();
  stream_->writer.end_page();
}

void PdfDocument::finish() {
  canvas_.reset();
  cairo_destroy(cr_);
  cr_ = nullptr;
  stream_->writer.begin_trailer();
  cairo_surface_finish(surface_);
  finished_ = true;
  check_stream();
  check(cairo_surface_status(surface_), "cannot write the PDF");
  stream_->writer.finish();
}

std::string pages_to_pdf(const std::vector<LaidOutPage>& pages, std::string_view label,
                         const PdfMetadata& metadata, const PageStyle& style, std::span<const PageLink> links) {
  std::string bytes;
  PdfDocument pdf(string_sink(bytes), metadata, pages.empty() ? PageSize::a4() : pages.front().size);
  pdf.add(pages, label, false, style, links);
  pdf.finish();
  return bytes;
}

namespace {

std::string to_png(double width_pt, double height_pt, double dpi, const std::function<void(Canvas&)>& draw) {
  const double scale = dpi / 72.0;
  cairo_surface_t* surface = cairo_image_surface_create(
      CAIRO_FORMAT_RGB24, static_cast<int>(width_pt * scale + 0.5), static_cast<int>(height_pt * scale + 0.5));
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, scale, scale);
  {
    CairoCanvas canvas(cr);  // after the scale: pango takes its font options from it
    draw(canvas);
  }
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  std::string bytes;
  const cairo_status_t written =
      drawn == CAIRO_STATUS_SUCCESS ? cairo_surface_write_to_png_stream(surface, append_to_string, &bytes) : drawn;
  cairo_surface_destroy(surface);
  check(written, "cannot draw the PNG");
  return bytes;
}

}  // namespace

std::string page_to_png(const LaidOutPage& page, double dpi, const PageStyle& style) {
  return to_png(page.size.width_pt, page.size.height_pt, dpi, [&](Canvas& c) { paint_page(c, page, style); });
}

std::string scene_to_png(const Scene& scene, double width_pt, double dpi, const Style& style) {
  const double height = scene_height(scene, width_pt, style);
  return to_png(width_pt, height, dpi, [&](Canvas& c) {
    Path background;
    background.move_to({0, 0}).line_to({width_pt, 0}).line_to({width_pt, height}).line_to({0, height}).close();
    c.path(background, Paint{std::nullopt, style.background, 1});
    paint_scene(c, scene, 0, 0, width_pt, style);
  });
}

}  // namespace epure::render
