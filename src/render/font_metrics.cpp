#include "render/font_metrics.h"

#include <algorithm>
#include <array>
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

constexpr const GlyphAdvance* find(char32_t cp) {
  const auto* it = std::lower_bound(std::begin(kAdvances), std::end(kAdvances), cp,
                                    [](const GlyphAdvance& g, char32_t c) { return g.cp < c; });
  return it != std::end(kAdvances) && it->cp == cp ? it : nullptr;
}

constexpr double advance_from_table(char32_t cp, Face face) {
  const GlyphAdvance* g = find(cp);
  if (g == nullptr) return kFallbackAdvanceEm;
  return (face == Face::bold ? g->bold : g->regular) / double(kUnitsPerEm);
}

}  // namespace

namespace detail {

// Measuring calls advance_em once per glyph, and nearly every glyph is Latin or Greek: one flat
// array indexed by code point, filled at compile time from the very same expression as the
// binary search, gives the same doubles without the search. Rarer code points (arrows, symbols)
// still search.
constexpr std::array<std::array<double, kFlatAdvances>, 2> kAdvanceEm = [] {
  std::array<std::array<double, kFlatAdvances>, 2> a{};
  for (char32_t cp = 0; cp < kFlatAdvances; ++cp) {
    a[0][cp] = advance_from_table(cp, Face::regular);
    a[1][cp] = advance_from_table(cp, Face::bold);
  }
  return a;
}();

double advance_em_from_table(char32_t cp, Face face) { return advance_from_table(cp, face); }

}  // namespace detail

bool has_glyph(char32_t cp) { return find(cp) != nullptr; }

VerticalMetrics vertical_metrics() {
  const double em = kUnitsPerEm;
  return {kAscender / em, kDescender / em, kCapHeight / em, kXHeight / em};
}

}  // namespace epure::render
