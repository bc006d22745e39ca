#pragma once
// What epure adds to a PDF while cairo streams it: link annotations, the outline (a bookmark per
// document) and the page labels, so that a class-set PDF of any size is written once, in memory
// that does not grow with its pages.
//
// Why not cairo: Debian 12's cairo (1.16.0) writes a link tag (cairo_tag_begin(cr,
// CAIRO_TAG_LINK, "rect=[…] uri='…'")) as an annotation whose /StructParent leads to objects it
// never writes, and qpdf calls the file damaged. Its outline and page labels work, but it keeps
// them until the end as about 500 bytes a sheet (a 140-byte record and two copies of the name
// per bookmark, a string per page): 5 MB for 10,000 sheets, a third of what a class set's
// memory grew by (issue 37, heaptrack). Here a document is one record (its name once, its
// first page and page count). Why not a second pass (libqpdf read the finished file and wrote
// it again, until issue 37): qpdf holds every object of the file, about 60 KB of memory per
// sheet of a class-set keys.pdf, 950 MB for 10,000 sheets.
//
// How: cairo writes a page whole in cairo_show_page, its page object last ("N 0 obj\n<< /Type
// /Page % <number>\n … >>\nendobj\n"). The bytes of a page that carries links, or opens a
// bookmarked document, are held until it returns: an /Annots entry goes into the page object,
// and one /Link annotation object per link is written after it; a bookmark takes the page
// object's number. The annotations' numbers come after cairo's last one, which is known only when
// cairo writes its cross-reference table: they are written as ten-character fields of spaces,
// filled in place at the end through PdfSink::overwrite. cairo's catalog, its last object, is
// held until its table says how many objects it wrote; /Outlines and /PageLabels go into it,
// and the outline's and the labels' objects after it. The table is rewritten as it passes
// (cairo's offsets moved by the bytes inserted before them, the new objects' entries added),
// and so is the trailer (/Size, startxref). A PDF with neither links nor labels nor bookmarks
// passes through untouched.
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

// Pages named in a viewer's page list: `label` alone, or, when `numbered`, "<label> 1/n" to
// "<label> n/n" for the n pages. With `outline`, also a bookmark opening the first, named
// `title` (`label` when empty).
struct PageRun {
  std::string label;
  int pages = 1;
  bool numbered = true;
  bool outline = false;
  std::string title{};
};

// Between cairo's output stream and a sink. For each page: begin_page, cairo_show_page, then
// end_page; before cairo_surface_finish, begin_trailer; after it, finish. Every step that finds
// cairo's output other than described above throws std::runtime_error ("cannot add the PDF's
// links, bookmarks and labels: …"): a file without its links, or a damaged one, is never taken for a whole one.
class PdfStreamWriter {
 public:
  explicit PdfStreamWriter(PdfSink sink);

  // cairo's bytes, in order.
  void write(std::string_view bytes);

  // The next `run.pages` pages, after those of the earlier runs, are named by `run`. Pages past
  // the last run's (written without one) keep their number as their name.
  void add_run(PageRun run);

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
  // Where `mark` is in the bytes pending; when it is not there yet, they are written but for
  // what could be its start, and npos.
  std::size_t find_or_pass(std::string_view mark);
  void trailer_line(std::string_view line);
  bool adds_catalog_entries() const;
  std::size_t document_objects() const;  // the outline's and the labels' objects
  void write_catalog_and_objects();

  PdfSink sink_;
  std::uint64_t in_ = 0;   // bytes received from cairo
  std::uint64_t out_ = 0;  // bytes written to the sink

  // the runs of named pages, in order; the pages they cover so far
  struct Run {
    PageRun names;
    int first_page = 0;            // from 1
    std::int64_t page_object = 0;  // the first page's object number, for a bookmark
  };
  std::vector<Run> runs_;
  int run_pages_ = 0;      // the pages the runs cover
  int pages_written_ = 0;  // the pages cairo wrote
  bool any_label_ = false;  // a run with a name (an all-unnamed document writes no /PageLabels)
  int bookmarks_ = 0;

  // the page being held
  bool holding_ = false;
  bool wants_object_ = false;  // the page opens a bookmarked run
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

  // the trailer: cairo's tail until its catalog (when entries go into it), the catalog held
  // until its table, then line by line
  enum class Trailer { off, seeking, catalog, table } trailer_ = Trailer::off;
  std::string catalog_rest_;   // cairo's catalog after "<< /Type /Catalog\n"
  std::vector<std::uint64_t> document_offsets_;  // where the outline's and labels' objects are
  std::string pending_;        // bytes not yet known to be before the table, or a partial line
  std::uint64_t table_cairo_ = 0, table_out_ = 0;  // where the table starts, in both files
  std::int64_t objects_ = -1;  // cairo's object count ("0 N")
  std::int64_t entries_ = 0;   // its entries read so far
  enum class Expect { header, subsection, entries, trailer, startxref, eof, done } expect_ = Expect::header;
  bool size_written_ = false;
};

}  // namespace epure::render
