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

// A PDF surface writing into `bytes` and a cairo context on it, released however the test
// leaves: finish() ends the PDF (the bytes are whole after it) and says how cairo fared.
class PdfInto {
 public:
  PdfInto(std::string& bytes, double width_pt, double height_pt)
      : surface_(pdf_surface_into(bytes, width_pt, height_pt)), cr_(cairo_create(surface_)) {}
  PdfInto(const PdfInto&) = delete;
  PdfInto& operator=(const PdfInto&) = delete;
  ~PdfInto() {
    if (cr_ != nullptr) cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }

  cairo_surface_t* surface() const { return surface_; }
  cairo_t* cr() const { return cr_; }

  cairo_status_t finish() {
    if (cr_ != nullptr) cairo_destroy(cr_);
    cr_ = nullptr;
    cairo_surface_finish(surface_);
    return cairo_surface_status(surface_);
  }

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

}  // namespace epure::render::test
