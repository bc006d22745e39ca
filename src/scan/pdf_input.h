#pragma once
// PDF pages as grey images (page_input.h): a page that draws one image filling it (what a
// scanner or a copier writes) gives that image as it is stored, decoded without rendering
// (JPEG by libjpeg, Flate and uncompressed grey, RGB or 1-bit pixels through qpdf); any other
// page is rendered by poppler at the resolution asked.
#include <memory>
#include <string>

#include "scan/page_input.h"

namespace epure::scan {

std::unique_ptr<PageStream> open_pdf_pages(const std::string& path, int render_dpi);
std::unique_ptr<PageStream> open_pdf_pages_in_memory(std::string bytes, const std::string& name, int render_dpi);

}  // namespace epure::scan
