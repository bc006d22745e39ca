#include "render/paginate.h"

#include <algorithm>
#include <iterator>
#include <utility>

namespace epure::render::layout_detail {
namespace {

// A section's opening (statement, first figure and its fields) that does not fit in what is
// left of a page goes whole to the next one only when at most this share of the page's text
// height is left; with more room it starts here and is broken (see open_section), since keeping
// every opening whole leaves a sheet's pages half empty (6 pages a sheet instead of under 5).
// Measured on the default course (30 sheets, en and fr, each difficulty): 0.1 gives the fewest
// pages (a sheet 4.23–4.30 pages on average, from 4.37–4.40 with 0.2); 0.45 and above, 5.
constexpr double kMaxOpeningWaste = 0.1;
// A page but a document's last is never left less than this full by a choice of flow().
constexpr double kMinPageFill = 0.5;
// flow() tries every combination of the sections' fallbacks: 2^n trials of the atoms' heights
// alone. A sheet has seven sections; a document with more keeps the page-by-page choice.
constexpr std::size_t kMaxFallbackChoices = 10;

}  // namespace

Paginator::Paginator(const Document& doc, const LayoutStyle& style)
    : doc_(doc),
      left_(TextArea(doc, style).left),
      width_(TextArea(doc, style).width),
      top_(TextArea(doc, style).top),
      bottom_(TextArea(doc, style).bottom),
      whole_(doc.breaks == Document::Breaks::whole) {}

std::vector<LaidOutPage> Paginator::place(std::vector<Atom> atoms, const Fallbacks& fallbacks) {
  atoms_ = std::move(atoms);
  fallbacks_ = &fallbacks;
  pages_.clear();
  keep_sections_whole();
  choose_fallbacks();
  run_flow();
  return std::move(pages_);
}

std::size_t Paginator::count(std::vector<Atom> atoms, const Fallbacks& fallbacks, bool page_by_page) {
  atoms_ = std::move(atoms);
  fallbacks_ = &fallbacks;
  keep_sections_whole();
  if (page_by_page) {
    fallback_mask_ = ~std::uint32_t{0};
    fallback_bit_.clear();
  } else {
    choose_fallbacks();
  }
  dry_ = true;
  dry_pages_ = 0;
  dry_fills_.clear();
  run_flow();
  dry_ = false;
  return dry_pages_;
}

// A section a page holds is one group: a page ends before it or after it, not inside it. A
// section taller than a page keeps the places its atoms allow (see run_flow).
void Paginator::keep_sections_whole() {
  if (!whole_) return;
  for (std::size_t i = 0; i < atoms_.size();) {
    std::size_t end = i + 1;
    while (end < atoms_.size() && !atoms_[end].section_start) ++end;
    if (atoms_[i].section_start && span(i, end) <= bottom_ - top_ + kFitSlack)
      for (std::size_t k = i + 1; k < end; ++k) atoms_[k].break_before = false;
    i = end;
  }
}

void Paginator::new_page() {
  if (dry_) {
    // A trial only counts pages and how full each one ends.
    if (dry_pages_ > 0) dry_fills_.push_back((y_ - top_) / (bottom_ - top_));
    ++dry_pages_;
    y_ = top_;
    empty_ = true;
    return;
  }
  LaidOutPage page;
  page.number = static_cast<int>(pages_.size()) + 1;
  page.size = doc_.page;
  pages_.push_back(std::move(page));
  y_ = top_;
  empty_ = true;
}

double Paginator::span(std::size_t from, std::size_t to) const { return layout_detail::span(atoms_, from, to); }

bool Paginator::fits(double h) const { return y_ + h <= bottom_ + kFitSlack; }

// A breakable document's sections whose statement (or last steps) went beside its figure and
// whose opening does not fit in what is left of a page have two ways to go (see open_section):
// whole to the next page, or laid out again with the statement above the figure, which may end
// this page. Taking the second every time, as one page alone would choose, can leave a document
// one page longer than it needs: a statement ends a page whose next figure does not fit. So
// every combination of these choices is tried on the atoms' shapes, and the one that gives the
// fewest pages, none of them but the last less than half full, is set; on a tie, the
// page-by-page choice. Each section with a fallback is a bit of the choice mask (set: take the
// fallback when its opening does not fit). A trial reads only the bits of the sections whose
// opening did not fit where it came; a mask that agrees with an earlier trial's on the bits that
// trial read would replay it step for step, so its pages are that trial's, not flowed again (a
// key with 6 fallbacks flows a handful of its 64 masks).
void Paginator::choose_fallbacks() {
  fallback_mask_ = ~std::uint32_t{0};
  fallback_bit_.clear();
  const auto& fallbacks = fallbacks_->shapes;
  if (whole_ || fallbacks.empty() || fallbacks.size() > kMaxFallbackChoices) return;
  std::uint32_t bit = 0;
  for (const auto& [si, atoms] : fallbacks) fallback_bit_[si] = bit++;
  std::vector<Atom> shapes;
  shapes.reserve(atoms_.size());
  for (const Atom& a : atoms_) shapes.push_back(shape(a));
  struct Trial {
    std::uint32_t mask = 0, read = 0;  // read: the bits the flow looked at
    std::size_t pages = 0;
    bool filled = false;  // no page but the last less than kMinPageFill full
  };
  std::vector<Trial> trials;
  const auto trial = [&](std::uint32_t mask) -> Trial {
    for (const Trial& t : trials)
      if (((mask ^ t.mask) & t.read) == 0) return t;
    Trial t{mask, 0, trial_pages(mask, shapes), false};
    t.read = bits_read_;
    t.filled = std::all_of(dry_fills_.begin(), dry_fills_.end(), [](double f) { return f >= kMinPageFill; });
    return trials.emplace_back(t);
  };
  const std::uint32_t all = (std::uint32_t{1} << bit) - 1;
  std::size_t best_pages = trial(all).pages;
  std::uint32_t best = all;
  for (std::uint32_t mask = all; mask-- > 0;) {
    const Trial t = trial(mask);
    if (t.pages < best_pages && t.filled) {
      best_pages = t.pages;
      best = mask;
    }
  }
  fallback_mask_ = best;
}

// How many pages the atoms take with this choice mask (dry_fills_: how full each page but the
// last ends), placed from a copy of `shapes` (placing edits the atoms).
std::size_t Paginator::trial_pages(std::uint32_t mask, const std::vector<Atom>& shapes) {
  std::vector<Atom> copies = shapes;
  std::swap(atoms_, copies);
  const bool dry = dry_;
  fallback_mask_ = mask;
  bits_read_ = 0;
  dry_ = true;
  dry_pages_ = 0;
  dry_fills_.clear();
  run_flow();
  dry_ = dry;
  std::swap(atoms_, copies);
  return dry_pages_;
}

Atom Paginator::shape(const Atom& a) {
  Atom g;
  g.height = a.height;
  g.space_before = a.space_before;
  g.break_before = a.break_before;
  g.section_start = a.section_start;
  g.head_atoms = a.head_atoms;
  g.section = a.section;
  g.block = a.block;
  g.wrapped = a.wrapped;
  g.follows_heading = a.follows_heading;
  g.figure = a.figure;
  g.content.keep_texts = false;
  return g;
}

void Paginator::run_flow() {
  new_page();
  std::size_t group_end = 0;
  for (std::size_t i = 0; i < atoms_.size(); ++i) {
    const double space = empty_ ? 0 : atoms_[i].space_before;
    if (i >= group_end && !empty_ && atoms_[i].section_start) open_section(i, space);  // may replace the section's atoms
    Atom& atom = atoms_[i];
    if (i >= group_end) {
      // A new group: the atoms up to the next place a page may end.
      group_end = i + 1;
      while (group_end < atoms_.size() && !atoms_[group_end].break_before) ++group_end;
      if (!empty_) {
        // A group goes to a fresh page when it does not fit here but would there; one taller
        // than a page starts here, since it must be broken anyway.
        const double group = span(i, group_end);
        if (!fits(space + group) && group <= bottom_ - top_ + kFitSlack) new_page();
      }
    } else if (!empty_ && !fits(space + atom.height)) {
      new_page();  // a group taller than a page: broken where it must be
    }
    place(atom);
  }
}

// Sections share pages (a sheet on four pages, not one exercise a page); a section's opening
// (its statement up to its first figure or field, with the run of fields or answers after it)
// that does not fit in what is left of this page goes whole to the next one only when that
// wastes little of this one. Otherwise it starts here; and when its statement fits here whole,
// the page may end between the statement and its figure, so that the statement is read in one
// piece rather than its last lines carried over with the figure.
void Paginator::open_section(std::size_t i, double space) {
  std::size_t end = i + 1;
  while (end < atoms_.size() && !atoms_[end].section_start) ++end;
  if (whole_) {
    // A section kept whole is one group (keep_sections_whole). One taller than a page is broken
    // anyway: it starts on a fresh page unless more than half of this one is left.
    if (span(i, end) > bottom_ - top_ + kFitSlack && bottom_ - y_ < 0.5 * (bottom_ - top_)) new_page();
    return;
  }
  // A section whose statement was set beside its figure is one tall group: when it does not
  // fit here and would leave much of this page empty, it is laid out as the statement above
  // the figure instead, which may end this page between the two.
  const int si = atoms_[i].section;
  if (auto shapes = fallbacks_->shapes.find(si); shapes != fallbacks_->shapes.end()) {
    const bool little_left = bottom_ - y_ <= kMaxOpeningWaste * (bottom_ - top_);
    std::size_t head_end = std::min(i + atoms_[i].head_atoms, end);
    const auto bit = fallback_bit_.find(si);
    const bool open = !fits(space + span(i, head_end)) && !little_left;
    if (open && bit != fallback_bit_.end()) bits_read_ |= std::uint32_t{1} << bit->second;
    const bool chosen = bit == fallback_bit_.end() || ((fallback_mask_ >> bit->second) & 1) != 0;
    if (open && chosen) {
      std::vector<Atom> other = dry_ ? shapes->second : fallbacks_->build(si);
      atoms_.erase(atoms_.begin() + static_cast<std::ptrdiff_t>(i), atoms_.begin() + static_cast<std::ptrdiff_t>(end));
      const std::size_t n = other.size();
      atoms_.insert(atoms_.begin() + static_cast<std::ptrdiff_t>(i), std::make_move_iterator(other.begin()),
                    std::make_move_iterator(other.end()));
      end = i + n;
    }
  }
  const Atom& atom = atoms_[i];
  std::size_t head_end = std::min(i + atom.head_atoms, end);
  if (head_end < end) {
    ++head_end;
    while (head_end < end && !atoms_[head_end].break_before) ++head_end;
  }
  const double head = span(i, head_end);
  if (fits(space + head)) return;
  const bool little_left = bottom_ - y_ <= kMaxOpeningWaste * (bottom_ - top_);
  if (head <= bottom_ - top_ + kFitSlack && little_left) new_page();
}

void Paginator::place(Atom& atom) {
  const double y = y_ + (empty_ ? 0 : atom.space_before);
  if (dry_) {
    y_ = y + atom.height;
    empty_ = false;
    return;
  }
  LaidOutPage& page = pages_.back();
  atom.content.move_into(page, y);
  const PageRect rect{left_, y, width_, atom.height};
  auto& blocks = page.blocks;
  if (!blocks.empty() && blocks.back().section == atom.section && blocks.back().block == atom.block) {
    blocks.back().rect.height = rect.bottom() - blocks.back().rect.y;
  } else {
    blocks.push_back({rect, atom.section, atom.block});
  }
  for (PlacedBlock b : atom.side_blocks) {
    b.rect.y += y;
    blocks.push_back(b);
  }
  if (!atom.side_blocks.empty()) {
    // The figure's own block: its width, not the whole line's.
    PlacedBlock& own = blocks[blocks.size() - atom.side_blocks.size() - 1];
    own.rect.width = atom.side_blocks.front().rect.x - kSideGap - own.rect.x;
  }
  y_ = y + atom.height;
  empty_ = false;
}

}  // namespace epure::render::layout_detail
