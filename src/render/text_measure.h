#pragma once
// Measuring text for the layout (internal to layout.cpp and its helpers): a document's texts
// wrapped at the widths the layout tries, each remembered, so that the options tried for a
// figure and its neighbours (and the layouts a page budget tries) wrap the same text at the same
// width once. The lines' markup is enough to count them; their runs are parsed when a line is set.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "render/scene.h"
#include "render/text.h"
#include "support/portable.h"

namespace epure::render::layout_detail {

// The same width is the same bits: a memo, not a tolerance (the options ask the widths they
// computed the same way).
inline std::uint64_t bits(double x) { return portable::bit_cast<std::uint64_t>(x); }
// Boost's hash_combine: the memo keys hash several fields.
inline std::size_t hash_combine(std::size_t h, std::uint64_t v) {
  return h ^ (std::hash<std::uint64_t>{}(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}

// What a wrapped text is remembered by: the text, its size and its width. Looked up through a
// view, so that a lookup copies nothing.
struct WrapView {
  std::string_view text;
  double size = 0, width = 0;
  friend bool operator==(const WrapView& a, const WrapView& b) {
    return a.text == b.text && bits(a.size) == bits(b.size) && bits(a.width) == bits(b.width);
  }
};
struct WrapKey {
  std::string text;
  double size = 0, width = 0;
  operator WrapView() const { return {text, size, width}; }
  friend bool operator==(const WrapKey& a, const WrapKey& b) { return WrapView(a) == WrapView(b); }
};
struct WrapHash {
  using is_transparent = void;
  std::size_t operator()(const WrapView& k) const {
    return hash_combine(hash_combine(std::hash<std::string_view>{}(k.text), bits(k.size)), bits(k.width));
  }
  std::size_t operator()(const WrapKey& k) const { return (*this)(WrapView(k)); }
};

class TextMeasure {
 public:
  // wrap_rich_text, remembered: how many lines `text` takes at `width`.
  std::size_t line_count(const RichText& text, double size, double width);
  // The lines' runs, parsed once a line is to be set.
  const std::vector<std::vector<TextRun>>& wrap(const RichText& text, double size, double width);
  // wrap_rich_source, remembered: the lines' markup, to split a paragraph after its first lines.
  const std::vector<std::string>& wrap_source(const RichText& text, double size, double width);

 private:
  // A text wrapped at a width: its lines' markup, enough to count them, and their runs once a
  // line is set.
  struct Wrapped {
    std::vector<std::string> lines;
    std::optional<std::vector<std::vector<TextRun>>> runs;
  };

  Wrapped& wrapped(const RichText& text, double size, double width);
  // A text's words and their widths, measured once for all the widths it is wrapped at.
  const MeasuredText& measured(const RichText& text, double size);

  std::unordered_map<WrapKey, Wrapped, WrapHash, std::equal_to<>> wrapped_;
  std::unordered_map<WrapKey, MeasuredText, WrapHash, std::equal_to<>> measured_;
};

}  // namespace epure::render::layout_detail
