// A cairo PDF surface whose bytes are appended to a string: the tests that read what cairo wrote.
#pragma once

#include <cairo-pdf.h>

#include <string>

namespace epure::render::test {

// The surface (width x height points) writes into `bytes`, which must outlive it.
inline cairo_surface_t* pdf_surface_into(std::string& bytes, double width_pt, double height_pt) {
  return cairo_pdf_surface_create_for_stream(
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &bytes, width_pt, height_pt);
}

}  // namespace epure::render::test
