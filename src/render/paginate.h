#pragma once
// Atoms on pages (internal to layout.cpp): the atoms of SectionAtoms placed from the top of the
// text column down, a page ended only where an atom allows it (between sentences or blocks, never
// after a heading, never between a figure and its neighbours), and, as Document::breaks says,
// each section kept on one page where a page holds it, or its opening kept whole and its
// fallback taken where that saves a page. The pages come out without their furniture
// (page_furniture.h).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "render/layout.h"
#include "render/layout_atoms.h"

namespace epure::render::layout_detail {

// The sections whose paragraphs went beside a figure, laid out again without that: their shapes,
// to count pages, and how to build one in full when it is taken.
struct Fallbacks {
  std::map<int, std::vector<Atom>> shapes;
  std::function<std::vector<Atom>(int section)> build;
};

class Paginator {
 public:
  Paginator(const Document& doc, const LayoutStyle& style);

  // The atoms on pages, numbered, without header.
  std::vector<LaidOutPage> place(std::vector<Atom> atoms, const Fallbacks& fallbacks);
  // How many pages the atoms take; shapes are enough. With `page_by_page`, each fallback is
  // taken as one page alone would choose, without trying every combination (for a budget's
  // trials): that may count more pages than place() gives, which tries the combinations.
  std::size_t count(std::vector<Atom> atoms, const Fallbacks& fallbacks, bool page_by_page = false);

  // An atom without its content: what placing it needs.
  static Atom shape(const Atom& a);

 private:
  void new_page();
  double span(std::size_t from, std::size_t to) const;
  bool fits(double h) const;
  void keep_sections_whole();
  void choose_fallbacks();
  std::size_t trial_pages(std::uint32_t mask, const std::vector<Atom>& shapes);
  void run_flow();
  void open_section(std::size_t i, double space);
  void place(Atom& atom);

  const Document& doc_;
  const double left_, width_, top_, bottom_;
  const bool whole_;  // Document::Breaks::whole

  std::vector<Atom> atoms_;
  const Fallbacks* fallbacks_ = nullptr;
  std::map<int, std::uint32_t> fallback_bit_;    // a fallback's bit in a choice mask
  std::uint32_t fallback_mask_ = ~std::uint32_t{0};  // set: the fallback is taken (see choose_fallbacks)
  std::uint32_t bits_read_ = 0;  // the mask's bits a flow looked at (choose_fallbacks)
  bool dry_ = false;                // counting pages only (count, trial_pages)
  std::size_t dry_pages_ = 0;
  std::vector<double> dry_fills_;   // a trial's pages but the last: the share of the text height used

  std::vector<LaidOutPage> pages_;
  double y_ = 0;
  bool empty_ = true;
};

}  // namespace epure::render::layout_detail
