// layout_document: a Document's sections measured and broken into atoms (section_atoms.h, with
// the text measured once in text_measure.h), the atoms put on pages (paginate.h), each page given
// its furniture (page_furniture.h). A document over its page budget has some of its sections'
// figures set smaller: the layouts tried for that are counted from shapes, and only the one
// chosen is built.
#include "render/layout.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "render/layout_atoms.h"
#include "render/page_furniture.h"
#include "render/paginate.h"
#include "render/section_atoms.h"

namespace epure::render {
namespace {

using namespace layout_detail;

class DocumentLayout {
 public:
  DocumentLayout(const Document& doc, const LayoutStyle& style)
      : doc_(doc), style_(style), sections_(doc, style, memo_), paginator_(doc, style) {
    const double step = style.figure_scale_step;
    if (step > 0)
      // The scales in whole steps from 1, so that every platform tries the same doubles.
      for (int k = 1; 1 - k * step >= style.figure_min_scale - kFitSlack; ++k) scales_.push_back(1 - k * step);
  }

  // The pages with every section's figures at full size, unless that breaks the page budget and
  // setting some smaller keeps it.
  std::vector<LaidOutPage> run() {
    std::vector<int> levels(doc_.sections.size(), 0);  // a scale per section: 0 is full size
    const auto budget = static_cast<std::size_t>(std::max(doc_.page_budget, 0));
    // Counted on shapes; the options measured for them are not measured again when the pages
    // are built.
    if (budget > 0 && !scales_.empty())
      if (const Count full = count(levels, budget); full.over) levels = within_budget(budget, full.quick);
    return build(levels);
  }

 private:
  double scale(int level) const { return level == 0 ? 1.0 : scales_[static_cast<std::size_t>(level - 1)]; }
  int lowest() const { return static_cast<int>(scales_.size()); }

  // The fewest figures set smaller, by as little as will do: the largest scale that all the
  // sections need alike to meet the budget (tried from the largest down: a sheet over its
  // budget by a little, the common case, is measured once or twice), then each section in turn,
  // in the document's order, given back its full size where the budget still holds. When even
  // the smallest scale does not meet it, the same for the fewest pages a scale reaches, if that
  // is fewer than at full size (a Letter sheet with tall figures: 6 pages, 5 smaller); else full
  // size everywhere: the budget is then past what figures can do.
  std::vector<int> within_budget(std::size_t budget, std::size_t full) {
    const std::size_t n = doc_.sections.size();
    int uniform = 0;
    // where no scale meets the budget: the largest that saves the most pages
    int fewest_level = 0;
    std::size_t fewest = full;
    for (int level = 1; level <= lowest() && uniform == 0; ++level) {
      const std::vector<int> alike(n, level);
      const Count c = count(alike, budget);
      if (!c.over) uniform = level;
      if (c.quick < fewest) fewest = c.quick, fewest_level = level;
    }
    if (uniform == 0) {
      if (fewest_level == 0) return std::vector<int>(n, 0);
      uniform = fewest_level;
      budget = fewest;
    }
    std::vector<int> levels(n, uniform);
    for (std::size_t si = 0; si < n; ++si) {
      levels[si] = 0;
      if (count(levels, budget).over) levels[si] = uniform;
    }
    return levels;
  }

  // A section's shapes at a level, made once.
  const SectionAtoms::Built& shapes(int si, int level) {
    auto key = std::pair{si, level};
    auto it = shapes_.find(key);
    if (it == shapes_.end()) it = shapes_.emplace(key, sections_.section(si, scale(level), true)).first;
    return it->second;
  }

  // A section's fallback (no paragraph beside a figure) as shapes at a level, made once: the
  // count of the page budget and the pages built ask for the same ones.
  const std::vector<Atom>& fallback_shapes(int si, int level) {
    auto key = std::pair{si, level};
    auto it = fallback_shapes_.find(key);
    if (it == fallback_shapes_.end())
      it = fallback_shapes_.emplace(key, sections_.section(si, scale(level), true, false).atoms).first;
    return it->second;
  }

  // The fallbacks of the sections (with paragraphs beside a figure) at their levels: shapes, and
  // how to build one.
  Fallbacks fallbacks(const std::vector<int>& levels, const std::vector<bool>& side_used) {
    Fallbacks f;
    if (doc_.breaks == Document::Breaks::whole) return f;  // a section kept whole has no use for one
    for (std::size_t si = 0; si < levels.size(); ++si) {
      if (!side_used[si]) continue;
      const int s = static_cast<int>(si);
      f.shapes.emplace(s, fallback_shapes(s, levels[si]));
    }
    f.build = [this, levels](int s) {
      return sections_.section(s, scale(levels[static_cast<std::size_t>(s)]), false, false).atoms;
    };
    return f;
  }

  // The pages at these levels against the budget. `quick` is counted with each fallback taken
  // as its page alone would (fast, for the trials); that can count a page more than place(),
  // which tries the fallbacks' combinations, so a quick count over the budget is made again as
  // place() chooses, and `over` says whether the pages as they will be placed break the budget:
  // no figure is set smaller for a page the pages would not take.
  struct Count {
    std::size_t quick;
    bool over;
  };
  Count count(const std::vector<int>& levels, std::size_t budget) {
    const std::size_t quick = pages(levels);
    return {quick, quick > budget && pages(levels, false) > budget};
  }

  // The pages at these levels, counted from shapes: the fallbacks taken page by page, or (not
  // `page_by_page`) chosen as place() chooses them.
  std::size_t pages(const std::vector<int>& levels, bool page_by_page = true) {
    if (!opening_) opening_ = sections_.opening(true);
    std::vector<bool> side_used;
    std::size_t n = opening_->size();
    for (std::size_t si = 0; si < levels.size(); ++si) n += shapes(static_cast<int>(si), levels[si]).atoms.size();
    std::vector<Atom> atoms;
    atoms.reserve(n);
    atoms.insert(atoms.end(), opening_->begin(), opening_->end());
    for (std::size_t si = 0; si < levels.size(); ++si) {
      const auto& built = shapes(static_cast<int>(si), levels[si]);
      atoms.insert(atoms.end(), built.atoms.begin(), built.atoms.end());
      side_used.push_back(built.side_used);
    }
    return paginator_.count(std::move(atoms), fallbacks(levels, side_used), page_by_page);
  }

  std::vector<LaidOutPage> build(const std::vector<int>& levels) {
    std::vector<Atom> atoms = sections_.opening(false);
    std::vector<bool> side_used;
    for (std::size_t si = 0; si < levels.size(); ++si) {
      auto built = sections_.section(static_cast<int>(si), scale(levels[si]), false);
      atoms.insert(atoms.end(), std::make_move_iterator(built.atoms.begin()), std::make_move_iterator(built.atoms.end()));
      side_used.push_back(built.side_used);
    }
    std::vector<LaidOutPage> pages = paginator_.place(std::move(atoms), fallbacks(levels, side_used));
    const TextArea area(doc_, style_);
    for (auto& page : pages) {
      page.count = static_cast<int>(pages.size());
      add_header(page, doc_, style_, area);
    }
    return pages;
  }

  const Document& doc_;
  const LayoutStyle& style_;
  LayoutMemo memo_;
  SectionAtoms sections_;
  Paginator paginator_;
  std::vector<double> scales_;  // below full size, largest first
  std::map<std::pair<int, int>, SectionAtoms::Built> shapes_;
  std::map<std::pair<int, int>, std::vector<Atom>> fallback_shapes_;
  std::optional<std::vector<Atom>> opening_;  // its shapes
};

}  // namespace

std::vector<LaidOutPage> layout_document(const Document& doc, const LayoutStyle& style) {
  return DocumentLayout(doc, style).run();
}

}  // namespace epure::render
