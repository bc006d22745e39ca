#pragma once
// Reading laid-out pages back in the layout tests (layout_test, sheet_pages_test): a line's text,
// and the Document block a placed block stands for.
#include <cstddef>
#include <string>

#include "render/layout.h"

namespace epure::render::testing {

// Placement is summed from a few dozen lengths in points; a thousandth of a point is far below
// anything a printer or a reader would see.
inline constexpr double kPt = 1e-3;

inline std::string joined(const PlacedText& t) {
  std::string s;
  for (const auto& r : t.runs) s += r.text;
  return s;
}

inline const Block& block_of(const Document& doc, const PlacedBlock& b) {
  return doc.sections[static_cast<std::size_t>(b.section)].blocks[static_cast<std::size_t>(b.block)];
}

}  // namespace epure::render::testing
