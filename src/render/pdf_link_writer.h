#pragma once
// Link annotations written into a PDF while cairo streams it, so that a linked PDF of any size is
// written once, in bounded memory.
//
// Why not cairo: Debian 12's cairo (1.16.0) writes a link tag (cairo_tag_begin(cr,
// CAIRO_TAG_LINK, "rect=[…] uri='…'")) as an annotation whose /StructParent leads to objects it
// never writes, and qpdf calls the file damaged. Why not a second pass (libqpdf read the finished
// file and wrote it again, until issue 37): qpdf holds every object of the file, about 60 KB of
// memory per sheet of a class-set keys.pdf, 950 MB for 10,000 sheets.
//
// How: cairo writes a page whole in cairo_show_page, its page object last ("N 0 obj\n<< /Type
// /Page % <number>\n … >>\nendobj\n"). The bytes of a page that carries links are held until
// it returns; an /Annots entry goes into the page object, and one /Link annotation object per
// link is written after it. Their object numbers come after cairo's last one, which is known
// only when cairo writes its cross-reference table: they are written as ten-character fields
// of spaces, filled in place at the end through PdfSink::overwrite. The table is rewritten as it
// passes (cairo's offsets moved by the bytes inserted before them, the annotations' entries
// added), and so is the trailer (/Size, startxref). A PDF without links passes through
// untouched.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "render/layout.h"

namespace epure::render {

// A link annotation: a rectangle of one of a document's pages (an index in its laid-out pages)
// that opens `uri`. The rectangle is in page points from the top left corner, like the layout's.
struct PageLink {
  int page = 0;
  PageRect rect;
  std::string uri;
};

// Where a PDF's bytes go: `write` appends them in order; `overwrite` rewrites bytes already
// written (the links' object numbers, at the end). A sink without `overwrite` takes PDFs
// without links only.
struct PdfSink {
  std::function<void(std::string_view bytes)> write;
  std::function<void(std::uint64_t offset, std::string_view bytes)> overwrite;
};

// A sink into `bytes` (appended to, then overwritten in place).
PdfSink string_sink(std::string& bytes);

// Between cairo's output stream and a sink. For each page: begin_page, cairo_show_page, then
// end_page; before cairo_surface_finish, begin_trailer; after it, finish. Every step that finds
// cairo's output other than described above throws std::runtime_error ("cannot add the PDF's
// links: …"): a file without its links, or a damaged one, is never taken for a whole one.
class PdfLinkWriter {
 public:
  explicit PdfLinkWriter(PdfSink sink);

  // cairo's bytes, in order.
  void write(std::string_view bytes);

  // The next page cairo writes is page `number` (from 1) of the PDF, `height_pt` high (the
  // rectangles are flipped to PDF's user space, from the bottom left), with `links` on it.
  void begin_page(int number, double height_pt, std::span<const PageLink> links);
  void end_page();
  void begin_trailer();
  void finish();

  int annotations() const { return static_cast<int>(annotations_.size()); }

 private:
  void emit(std::string_view bytes);
  void trailer_bytes(std::string_view bytes);
  void trailer_line(std::string_view line);

  PdfSink sink_;
  std::uint64_t in_ = 0;   // bytes received from cairo
  std::uint64_t out_ = 0;  // bytes written to the sink

  // the page being held
  bool holding_ = false;
  int page_number_ = 0;
  double page_height_ = 0;
  std::vector<PageLink> page_links_;
  std::string page_bytes_;

  // What is patched at the end, and how cairo's offsets move. A few dozen bytes per linked page:
  // the memory stays that of cairo's own table of objects.
  struct LinkedPage {
    std::uint64_t cairo_end;    // cairo's offset just past the page object
    std::uint64_t shift;        // bytes inserted up to there, the page's own included
    std::uint64_t annots_at;    // where the page's /Annots array's first field is
    std::uint32_t first, count; // its annotations, as indexes in annotations_
  };
  std::vector<LinkedPage> pages_;
  std::vector<std::uint64_t> annotations_;  // where each annotation object's number field is

  // the trailer: cairo's tail until its cross-reference table, then line by line
  enum class Trailer { off, seeking, table } trailer_ = Trailer::off;
  std::string pending_;        // bytes not yet known to be before the table, or a partial line
  std::uint64_t table_cairo_ = 0, table_out_ = 0;  // where the table starts, in both files
  std::int64_t objects_ = -1;  // cairo's object count ("0 N")
  std::int64_t entries_ = 0;   // its entries read so far
  enum class Expect { header, subsection, entries, trailer, startxref, eof, done } expect_ = Expect::header;
  bool size_written_ = false;
};

}  // namespace epure::render
