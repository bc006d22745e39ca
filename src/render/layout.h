#pragma once
// Pages placed, not drawn: a Document's blocks broken into lines and put on pages of the
// document's size, in points, y down from the page's top-left corner. Every backend (SVG now,
// cairo for the PDF) draws these pages as they are: no backend measures, wraps or breaks pages,
// so both draw the same thing.
//
// The rules: a header on every page (course, title, sheet id, "page i/n"; for a document with
// scan furniture, Document::page_code, the page's QR code at its right end and four corner
// marks in the margins); the first page opens with the name and student number fields;
// sections share pages.
// A page ends only between blocks or between sentences of a paragraph (never inside a sentence or
// a parenthesis, never leaving one line of a paragraph alone), never right after a Heading, never
// between a Figure and the Paragraph just before it or the fields (a key's answers) just after
// it, never inside a run of fields or a key's table that a page could hold. A document whose
// sections are kept whole (Document::breaks, a student's sheet) has each section on one page,
// unless the section alone is taller than a page. In one whose sections may break (a key), a
// section starts on a fresh page only when its opening (its statement, up to its first figure or
// field, and the run of fields or answers after it) would fit there but not in what is left of
// the current one; otherwise it flows.
//
// A figure followed by fields or a key's answers has them beside it, in a column on its right,
// when they fit there (half the paper of one above the other); a figure of several panels side
// by side is never narrowed for that column. The plain paragraphs just before a figure (a
// statement, a key's last steps) go in that column too, above the answers or with the answers
// under the figure, when that makes the whole shorter by more than half a line; the figure keeps
// the width its kind asks for. A statement too long for that column may flow around the figure:
// its first lines across the page, the rest in the column above the fields. Every such option is
// measured as shapes (heights and extents, no text) and only the shortest is built. In a document
// whose sections may break, such a section, when its opening does not fit in what is left of a
// page and would leave more than a tenth of it empty, may be set with its paragraphs above the
// figure instead, so that the page may end between them: every combination of these choices over
// the document is tried on the atoms' shapes, and the one with the fewest pages (no page but the
// last less than half full) is set, on a tie the one that takes the paragraphs-above layout each
// time.
//
// Every answer field is a PlacedBox with its question id and the value it stands for, in points
// from its page's top-left corner: the rectangles a scan would read, exported as they are drawn.
#include <string>
#include <vector>

#include "render/document.h"
#include "render/qr_code.h"
#include "render/text.h"

namespace epure::render {

// A rectangle on the page, in points, y down.
struct PageRect {
  double x = 0, y = 0, width = 0, height = 0;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
};

// What a placed thing is, not how it looks: the backend's style gives the colour (as Role does
// for scenes), so a key's answers can stand out and ids stay discreet.
enum class Ink {
  text,    // statements, prompts, headings
  muted,   // page furniture and question ids
  answer,  // a key's expected answers
};

// One line of text, already broken into runs; backends set it as it is, from the left end of
// its baseline.
struct PlacedText {
  P2 baseline;
  double size = 10;  // font size, points
  std::vector<TextRun> runs;
  Ink ink = Ink::text;
};

struct PlacedRule {
  P2 a, b;
  double width = 0.5;  // stroke width, points
  Ink ink = Ink::text;
};

enum class BoxKind {
  answer,  // a box the student writes a value in
  tick,    // a small square to tick, one per option
  cell,    // one cell of a comb field: one character written in it
  shade,   // the light background of an emphasised paragraph
};

struct PlacedBox {
  PageRect rect;
  BoxKind kind = BoxKind::answer;
  // For answer and tick boxes, where a scan would read the answer: the field's question id and
  // what this box stands for: "x", "y", "z" for a point's coordinates, the option for a tick
  // ("before", a face name, "true"/"false"), empty for a single number.
  std::string question_id;
  std::string value;
  // For a comb's cells: whether the comb starts with a sign cell, and how many of its last cells
  // are decimals (the same on each of its cells).
  bool comb_sign = false;
  int comb_decimals = 0;
  // For a tick: whether any number of the field's boxes may be ticked (sides), or one.
  bool any = false;
};

// A Scene drawn into a rectangle scene_height (scene_painter.h) high, with Style::print().
// Points into the Document: the Document must outlive the pages.
struct PlacedFigure {
  PageRect rect;
  const Scene* scene = nullptr;
};

// A page's code as a QR code (Document::page_code), in the header: `rect` holds the modules and
// their quiet zone, so nothing else may be drawn in it.
struct PlacedQr {
  PageRect rect;
  QrCode code;
};

// A raster image in its rectangle (a scanned answer's crop).
struct PlacedImage {
  PageRect rect;
  Raster raster;
};

// Where a block (or its part on this page) sits; section and block index the Document, -1 for
// the page furniture (header, name fields, the note under them).
struct PlacedBlock {
  PageRect rect;
  int section = -1;
  int block = -1;
};

// What a page shows, mark by mark (the layout's atoms carry the same lists, layout_atoms.h).
// Backends draw boxes, then rules, figures and texts, so that shades lie under the text.
struct PageMarks {
  std::vector<PlacedBox> boxes;
  std::vector<PlacedRule> rules;
  std::vector<PlacedFigure> figures;
  std::vector<PlacedText> texts;
  std::vector<PlacedQr> codes;
  std::vector<PlacedImage> images;
};

struct LaidOutPage : PageMarks {
  int number = 1;  // 1-based
  int count = 1;   // pages in the document
  PageSize size;
  std::vector<PlacedBlock> blocks;
  // The corner marks (solid squares) a scan registers the page on: top-left, top-right,
  // bottom-right, bottom-left; empty for a page without scan furniture.
  std::vector<PageRect> marks;
};

// Sizes of the printed page, in points. The defaults are a plain A4/Letter worksheet.
struct LayoutStyle {
  double margin_left = 56.7, margin_right = 56.7;  // 20 mm
  double margin_top = 42.5, margin_bottom = 42.5;  // 15 mm

  double header_title_size = 10, header_small_size = 8.5;
  double header_height = 28;        // from the top margin to the rule under the header
  double header_gap = 14;           // from that rule to the content

  double name_row_height = 26;      // the first page's name and student number fields
  double qr_module = 1.3;           // side of a QR module: 25 modules (a page code) ≈ 11.5 mm
  double mark_size = 14.17;         // a corner mark's side (5 mm)
  double mark_inset = 34;           // from a page edge to a mark's centre (12 mm: in the margin)
  double comb_cell_width = 14, comb_cell_height = 18;  // a comb's cell: one handwritten character
  double comb_separator_gap = 6;    // between the integer and decimal cells, for the separator

  double body_size = 10;
  double line_height = 1.4;         // × font size; room for an arrow over AB or a subscript
  double heading1_size = 12.5, heading2_size = 11;
  double heading1_space = 10, heading2_space = 8;  // above a heading (dropped at a page top)
  double block_space = 5;           // between blocks
  double shade_padding = 5;         // around an emphasised paragraph's text

  double id_size = 6.5;             // question ids beside fields
  double field_box_height = 20;
  double number_box_width = 88;
  double point_box_width = 62;      // each coordinate of a point
  double point3_box_width = 54;
  double tick_size = 10;           // a box to tick (3.5 mm): at 9 pt, a cross in a 150 dpi scan was once taken for
                                   // a filled, cancelled box; 11 pt, the fixture's, cost a Letter sheet a 5th page
  double tick_row_height = 17;
  double row_space = 4;             // between consecutive field rows
  double prompt_column_max = 0.4;   // × text width, for the shared prompt column of fields

  double key_prompt_column_min = 56;  // so that an answer never hugs a one-letter prompt
  double key_prompt_column_max = 0.38;
  double key_row_padding = 3;

  // A figure never takes more than this share of a page's text height, so that the paragraph
  // it belongs to still fits above it.
  double figure_max_height = 0.55;
  // A document over its page budget (Document::page_budget) is laid out again with some of its
  // sections' figures smaller: each section's figures at a scale below 1 (their width and their
  // height cap alike), in steps of figure_scale_step down to figure_min_scale. The smallest scale
  // that all sections need alike to meet the budget is found first, then each section, in order,
  // is given back the largest scale that still meets it, so that only the figures that must be
  // smaller are, and by no more than they must. When even figure_min_scale does not meet the
  // budget, the same for the fewest pages a scale reaches; the figures keep their size when no
  // scale saves a page (a spec with many exercises: no figure shrinks for nothing). 0.6: a
  // French Letter sheet of the hard level with two tall figures needed it to keep to 4 pages
  // (0.7: 5, full size: 6); a figure 60 % of its width is still read at arm's length.
  double figure_min_scale = 0.6;
  double figure_scale_step = 0.05;
  double figure_space = 6;         // above and below a figure (a frame needs more air than text)
  // A figure followed by answer fields (or a key's answers) gets them in a column on its right
  // when they fit there; the figure is then narrowed, but never below this share of the text width.
  double figure_min_share = 0.42;
};

// Lays out the whole document, within its page budget where setting some figures smaller
// (figure_min_scale) achieves it. Deterministic: the same Document and style give the same pages.
std::vector<LaidOutPage> layout_document(const Document& doc, const LayoutStyle& style = {});

}  // namespace epure::render
