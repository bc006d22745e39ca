#pragma once
// What the layout's parts hand each other (internal to layout.cpp and its helpers): the atoms a
// Document is broken into (section_atoms.h makes them, paginate.h puts them on pages) and the
// lengths they share. Not a public header: backends see LaidOutPage only.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/layout.h"

namespace epure::render::layout_detail {

// Baseline of a text line below the top of its line box, × font size: DejaVu Sans's ascent is
// 0.93 em and an arrow over AB sits just above the capitals, both inside the line box.
inline constexpr double kBaseline = 1.02;
// Baseline that centres capitals and digits (cap height 0.73 em) on a box's middle, × font size.
inline constexpr double kCentredBaseline = 0.36;
// Page space is compared in points summed from a few dozen terms; this much rounding never
// decides a page break.
inline constexpr double kFitSlack = 1e-6;
// Between a header's left and right columns, and around the name row's QR code, in points.
inline constexpr double kHeaderGap = 12;
// Between a figure and the fields or answers beside it, in points.
inline constexpr double kSideGap = 18;
// Before a question id at the right edge of a row, in points.
inline constexpr double kIdGap = 10;

inline std::vector<TextRun> plain(std::string text, bool bold = false) {
  TextRun run;
  run.text = std::move(text);
  run.bold = bold;
  return {std::move(run)};
}

// Everything one atom puts on the page; x in page coordinates, y from the atom's top.
struct Fragment {
  // The marks themselves live on the heap, made when the first is kept: a shape (an option
  // measured, a page count) keeps none, and the layout makes, copies, moves and drops ten times
  // as many shapes as atoms it puts on pages; six empty vectors in each cost more than one
  // pointer.
  using Marks = PageMarks;
  // Copied whole with its atom (a row remembered and replayed), as the vectors were.
  struct MarksPtr {
    std::unique_ptr<Marks> p;
    MarksPtr() = default;
    MarksPtr(const MarksPtr& o) : p(o.p ? std::make_unique<Marks>(*o.p) : nullptr) {}
    MarksPtr& operator=(const MarksPtr& o) {
      if (this != &o) p = o.p ? std::make_unique<Marks>(*o.p) : nullptr;
      return *this;
    }
    MarksPtr(MarksPtr&&) noexcept = default;
    MarksPtr& operator=(MarksPtr&&) noexcept = default;
  };
  MarksPtr marks;
  // A layout option only measured (its height, whether it fits a column) keeps no text: the
  // options tried for a figure and its neighbours would otherwise copy every run of every line
  // again for each one. What the fit test needs of the texts is kept as two extents.
  bool keep_texts = true;
  bool track_extents = false;       // set for the atoms of a column beside a figure
  double text_right_edge = -1e300;  // the right end of the furthest text that is not muted
  double muted_left = 1e300;        // the left end of the first muted text (a question id)
  double box_right_edge = -1e300;   // the right end of the furthest box

  Marks& kept() {
    if (!marks.p) marks.p = std::make_unique<Marks>();
    return *marks.p;
  }

  void image(PlacedImage i) {
    if (keep_texts) kept().images.push_back(std::move(i));
  }

  // (a shape's rows, remembered and replayed many times, then copy no rule either)
  void rule(const PlacedRule& r) {
    if (keep_texts) kept().rules.push_back(r);
  }

  void box(PlacedBox b) {
    box_right_edge = std::max(box_right_edge, b.rect.right());
    if (keep_texts) kept().boxes.push_back(std::move(b));
  }
  // The box `make()` gives, at `rect`, made only when kept: a shape notes how far it reaches
  // without copying its question id and value (a comb is a box a cell, each with both).
  template <class Make>
  void box(const PageRect& rect, Make&& make) {
    box_right_edge = std::max(box_right_edge, rect.right());
    if (keep_texts) kept().boxes.push_back(make());
  }

  void text(const std::vector<TextRun>& runs, double x, double baseline, double size, Ink ink = Ink::text) {
    note_extent(runs, x, size, ink);
    if (keep_texts) kept().texts.push_back({{x, baseline}, size, runs, ink});
  }
  void text(std::vector<TextRun>&& runs, double x, double baseline, double size, Ink ink = Ink::text) {
    note_extent(runs, x, size, ink);
    if (keep_texts) kept().texts.push_back({{x, baseline}, size, std::move(runs), ink});
  }
  // Right-aligned on `right`.
  void text_right(std::vector<TextRun> runs, double right, double baseline, double size, Ink ink) {
    const double width = text_width(runs, size);
    if (ink == Ink::muted) {
      muted_left = std::min(muted_left, right - width);
    } else {
      text_right_edge = std::max(text_right_edge, right);
    }
    if (keep_texts) kept().texts.push_back({{right - width, baseline}, size, std::move(runs), ink});
  }
  void note_extent(const std::vector<TextRun>& runs, double x, double size, Ink ink) {
    if (!track_extents) return;
    if (ink == Ink::muted) {
      muted_left = std::min(muted_left, x);
    } else {
      text_right_edge = std::max(text_right_edge, x + text_width(runs, size));
    }
  }

  // Appends `other`'s content, moved down by dy (not its QR codes: a column holds none).
  void append(Fragment&& other, double dy) {
    text_right_edge = std::max(text_right_edge, other.text_right_edge);
    box_right_edge = std::max(box_right_edge, other.box_right_edge);
    muted_left = std::min(muted_left, other.muted_left);
    if (other.marks.p) move_marks(*other.marks.p, kept(), dy, false);
  }

  void move_into(LaidOutPage& page, double dy) {
    if (marks.p) move_marks(*marks.p, page, dy, true);
  }

 private:
  // Each of `from`'s marks moved down by dy, to the end of its list in `to`.
  static void move_marks(Marks& from, PageMarks& to, double dy, bool codes) {
    for (auto& b : from.boxes) {
      b.rect.y += dy;
      to.boxes.push_back(std::move(b));
    }
    for (auto& r : from.rules) {
      r.a.y += dy;
      r.b.y += dy;
      to.rules.push_back(r);
    }
    for (auto& f : from.figures) {
      f.rect.y += dy;
      to.figures.push_back(f);
    }
    for (auto& t : from.texts) {
      t.baseline.y += dy;
      to.texts.push_back(std::move(t));
    }
    if (codes)
      for (auto& q : from.codes) {
        q.rect.y += dy;
        to.codes.push_back(std::move(q));
      }
    for (auto& i : from.images) {
      i.rect.y += dy;
      to.images.push_back(std::move(i));
    }
  }
};

// The unit of page breaking: a line of a paragraph, a heading, a row of fields, a figure.
struct Atom {
  double height = 0;
  double space_before = 0;   // dropped at the top of a page
  bool break_before = true;  // a page may end just before this atom
  bool section_start = false;
  std::size_t head_atoms = 0;  // on a section's first atom: how many atoms its statement takes
  int section = -1, block = -1;
  // The blocks set beside a figure in this atom, with rectangles from the atom's top.
  std::vector<PlacedBlock> side_blocks;
  bool wrapped = false;  // a key's answer broken over lines it does not ask for
  bool follows_heading = false;  // right after a heading: a page may not end before it
  bool figure = false;   // holds a figure (a shape keeps this of its content)
  Fragment content;
};

// Height from the start of atoms[from] to the end of atoms[to - 1], on a page already begun.
inline double span(const std::vector<Atom>& atoms, std::size_t from, std::size_t to) {
  double h = 0;
  for (std::size_t i = from; i < to; ++i) h += (i > from ? atoms[i].space_before : 0) + atoms[i].height;
  return h;
}

// The text column of a page of `doc` with `style`: its edges, in points.
struct TextArea {
  double left = 0, right = 0, width = 0;
  double top = 0, bottom = 0;  // under the header, above the bottom margin
  TextArea(const Document& doc, const LayoutStyle& style)
      : left(style.margin_left),
        right(doc.page.width_pt - style.margin_right),
        width(right - left),
        top(style.margin_top + style.header_height + style.header_gap),
        bottom(doc.page.height_pt - style.margin_bottom) {}
};

}  // namespace epure::render::layout_detail
