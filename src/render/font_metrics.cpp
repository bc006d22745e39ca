#include "render/font_metrics.h"

#include <algorithm>
#include <iterator>

namespace epure::render {
namespace {

struct GlyphAdvance {
  char32_t cp;
  short regular, bold;  // font units
};

#include "render/font_metrics_table.inc"

static_assert(std::is_sorted(std::begin(kAdvances), std::end(kAdvances),
                             [](const GlyphAdvance& a, const GlyphAdvance& b) {
                               return a.cp < b.cp;
                             }),
              "the generated table must be sorted for the binary search");

const GlyphAdvance* find(char32_t cp) {
  const auto* it = std::lower_bound(std::begin(kAdvances), std::end(kAdvances), cp,
                                    [](const GlyphAdvance& g, char32_t c) { return g.cp < c; });
  return it != std::end(kAdvances) && it->cp == cp ? it : nullptr;
}

}  // namespace

double advance_em(char32_t cp, Face face) {
  const GlyphAdvance* g = find(cp);
  if (g == nullptr) return kFallbackAdvanceEm;
  return (face == Face::bold ? g->bold : g->regular) / double(kUnitsPerEm);
}

bool has_glyph(char32_t cp) { return find(cp) != nullptr; }

VerticalMetrics vertical_metrics() {
  const double em = kUnitsPerEm;
  return {kAscender / em, kDescender / em, kCapHeight / em, kXHeight / em};
}

}  // namespace epure::render
