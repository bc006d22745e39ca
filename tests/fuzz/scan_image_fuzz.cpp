// Scanned pages (src/scan/page_input.cpp, pdf_input.cpp): PNG, JPEG, TIFF and PDF bytes, read
// as `epure scan` reads a file. Every input gives at least one page; a page is an image or an
// error, never both and never neither; an image is grey, non-empty and within kMaxPagePixels;
// an error names no C++ exception type; the pages come in order. A reader's own crash or leak
// is ASan's to catch.
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "scan/page_input.h"

using namespace epure;
using namespace epure::scan;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 20)) return 0;
  auto stream = open_pages_in_memory(std::string(reinterpret_cast<const char*>(data), size), "scan.bin", 24);
  int pages = 0, last = 0;
  for (;;) {
    std::optional<InputPage> p;
    try {
      p = stream->next();
    } catch (const std::exception& e) {
      fuzz::broken("a page reader threw", e.what());
    }
    if (!p) break;
    ++pages;
    fuzz::check(p->file == "scan.bin", "a page does not name its file", p->file);
    fuzz::check(p->page > last, "pages out of order", std::to_string(p->page));
    last = p->page;
    if (p->error.empty()) {
      fuzz::check(!p->image.empty() && p->image.type() == CV_8UC1, "a page with neither an image nor an error");
      fuzz::check(static_cast<std::int64_t>(p->image.total()) <= kMaxPagePixels, "an image past the page limit");
    } else {
      fuzz::check(p->image.empty(), "a page with both an image and an error", p->error);
    }
    if (pages > 64) break;  // a long TIFF or PDF: the first pages tell enough
  }
  fuzz::check(pages >= 1, "an input that gives no page at all (not even its error)");
  return 0;
}
