#include "render/cairo_deflate.h"
#include "pdf_surface_into.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <zlib.h>

#include <doctest/doctest.h>

#include <string>

using namespace epure::render;

namespace {

// zlib's deflate at `level` (6 for the default), through deflateInit2_, which cairo_deflate.cpp
// leaves alone (compress2 goes through deflateInit_, so it would not do as a reference).
std::string deflated(const std::string& bytes, int level) {
  z_stream z{};
  REQUIRE(deflateInit2_(&z, level, Z_DEFLATED, MAX_WBITS, 8, Z_DEFAULT_STRATEGY, ZLIB_VERSION,
                        static_cast<int>(sizeof(z_stream))) == Z_OK);
  std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

std::string inflated(const std::string& bytes) {
  std::string out(1 << 20, '\0');
  uLongf length = out.size();
  REQUIRE(uncompress(reinterpret_cast<Bytef*>(out.data()), &length, reinterpret_cast<const Bytef*>(bytes.data()),
                     static_cast<uLong>(bytes.size())) == Z_OK);
  out.resize(length);
  return out;
}

}  // namespace

TEST_CASE("cairo_deflate: cairo's PDF streams are compressed at the fast level, other levels as asked") {
  const std::uint64_t before = cairo_deflate_streams();
  std::string pdf;
  test::PdfInto into(pdf, 200, 200);
  cairo_pdf_surface_restrict_to_version(into.surface(), CAIRO_PDF_VERSION_1_5);
  cairo_t* cr = into.cr();
  for (int i = 0; i < 3000; ++i) {  // a content stream long enough for the levels to differ
    cairo_rectangle(cr, i % 137 + 0.25 * (i % 7), i % 153 + 0.125 * (i % 13), 3 + i % 5, 2 + i % 11);
    cairo_set_source_rgb(cr, (i % 4) / 4.0, 0, 0);
    cairo_fill(cr);
  }
  REQUIRE(into.finish() == CAIRO_STATUS_SUCCESS);
  CHECK(cairo_deflate_streams() > before);

  // The page's content stream: its bytes are what zlib writes at the fast level, not the default.
  const std::size_t filter = pdf.find("/Filter /FlateDecode");
  REQUIRE(filter != std::string::npos);
  const std::size_t start = pdf.find("stream\n", filter) + 7;
  const std::size_t end = pdf.find("\nendstream", start);
  REQUIRE(end != std::string::npos);
  const std::string stream = pdf.substr(start, end - start);
  const std::string content = inflated(stream);
  CHECK(content.find(" re") != std::string::npos);
  CHECK(stream == deflated(content, kCairoDeflateLevel));
  CHECK(stream != deflated(content, 6));

  // A caller naming its level keeps it (compress2 goes through deflateInit_).
  const std::uint64_t streams = cairo_deflate_streams();
  std::string level9(compressBound(static_cast<uLong>(content.size())), '\0');
  uLongf length = level9.size();
  REQUIRE(compress2(reinterpret_cast<Bytef*>(level9.data()), &length, reinterpret_cast<const Bytef*>(content.data()),
                    static_cast<uLong>(content.size()), 9) == Z_OK);
  level9.resize(length);
  CHECK(cairo_deflate_streams() == streams);
  CHECK(level9 == deflated(content, 9));
  CHECK(level9 != stream);
}
