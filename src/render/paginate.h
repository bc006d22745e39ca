#pragma once
// Atoms on pages (internal to layout.cpp): the atoms of SectionAtoms placed from the top of the
// text column down, a page ended where an atom allows it, a section's opening kept whole or its
// fallback taken as layout.h says. The pages come out without their furniture (page_furniture.h).
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

#include "render/layout.h"
#include "render/layout_atoms.h"
#include "render/section_atoms.h"

namespace epure::render::layout_detail {

class Paginator {
 public:
  Paginator(const Document& doc, const LayoutStyle& style, SectionAtoms& sections);

  // The sections' atoms on pages (numbered, without header). Consumes the atoms.
  std::vector<LaidOutPage> run();

 private:
  void new_page();
  double span(std::size_t from, std::size_t to) const;
  bool fits(double h) const;
  void flow();
  void choose_fallbacks();
  std::size_t trial_pages(std::uint32_t mask, const std::vector<Atom>& shapes);
  static Atom geometry(const Atom& a);
  static std::vector<Atom> geometry(const std::vector<Atom>& atoms);
  void run_flow();
  void open_section(std::size_t i, double space);
  void place(Atom& atom);

  const Document& doc_;
  SectionAtoms& sections_;
  std::vector<Atom>& atoms_;
  const double left_, width_, top_, bottom_;

  std::set<int> fallback_;  // the sections with paragraphs beside a figure
  std::map<int, std::uint32_t> fallback_bit_;    // their bit in a choice mask
  std::map<int, std::vector<Atom>> fallback_atoms_;  // their fallback, built once
  std::map<int, std::vector<Atom>> fallback_shapes_;  // and its geometry, for the trials
  std::uint32_t fallback_mask_ = ~std::uint32_t{0};  // set: the fallback is taken (see flow)
  bool dry_ = false;                // placing copies only to count pages (see trial_pages)
  std::size_t dry_pages_ = 0;
  std::vector<double> dry_fills_;   // a trial's pages but the last: the share of the text height used

  std::vector<LaidOutPage> pages_;
  double y_ = 0;
  bool empty_ = true;
};

}  // namespace epure::render::layout_detail
