#pragma once
// Measuring text for the layout (internal to layout.cpp and its helpers): a document's texts cut
// into measured words once, and wrapped at each width the layout tries once, remembered for the
// whole layout of a document (the options tried for a figure and its neighbours, and the
// layouts a page budget tries, ask the same texts at the same widths again and again). A wrapped
// text is first only line spans: enough to count its lines, know the widest and where a sentence
// ends; the lines' markup and runs are made when a line is set. A text's measured words are
// also shared, by content, with the thread's later documents (a set's sheets repeat their
// headings, prompts and notes, and a key its sheet's statements).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
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

// A text wrapped at one width.
struct WrappedText {
  const MeasuredText* measured = nullptr;
  std::vector<MeasuredLine> lines;
  // ends_sentence[i]: line i ends with the end of a sentence (".", "!", "?", maybe closed by a
  // quote or bracket) outside any parenthesis: the one place inside a paragraph where a page may
  // end, so that no sentence, and nothing in parentheses, is read across two pages.
  std::vector<bool> ends_sentence;
  double widest = 0;  // the widest line, as the breaking measured it
  std::size_t count() const { return lines.size(); }
};

// Remembers texts by their address: every text the layout measures belongs to the Document (or
// to the layout's memo), which outlives the measuring, so that a lookup hashes a pointer and
// two numbers, not the text.
class TextMeasure {
 public:
  // `text` at `size` broken into lines no wider than `width`; from its `from`-th word on (a
  // paragraph's rest after its first lines; in a text without '\n').
  const WrappedText& wrapped(const RichText& text, double size, double width, Weight weight = Weight::regular,
                             std::size_t from = 0);
  // The lines' runs (parse_rich_text of each line's markup), made once.
  const std::vector<std::vector<TextRun>>& wrap(const RichText& text, double size, double width,
                                                Weight weight = Weight::regular, std::size_t from = 0);

 private:
  struct Key {
    const RichText* text = nullptr;
    std::uint64_t size = 0, width = 0;
    Weight weight = Weight::regular;
    std::size_t from = 0;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return hash_combine(hash_combine(hash_combine(std::hash<const void*>{}(k.text), k.size), k.width),
                          static_cast<std::uint64_t>(k.weight) + (k.from << 1));
    }
  };
  struct Measured;
  struct Entry {
    WrappedText wrapped;
    const Measured* source = nullptr;
    const std::vector<std::vector<TextRun>>* runs = nullptr;  // the source's, once asked for
  };

  // A text's measured words, and after each word whether a sentence ends there outside any
  // parenthesis (counted over the whole text): what every width's ends_sentence is read from.
  struct Measured {
    MeasuredText text;
    std::vector<std::vector<bool>> sentence_ends;  // [piece][word]
    // The lines' runs at a width (its bits) from a word on, made for the first document that
    // asks and kept with the measure: a heading, a prompt or a statement set again at a width
    // it had is not parsed again. Filled by the thread that holds the measure.
    mutable std::map<std::pair<std::uint64_t, std::size_t>, std::vector<std::vector<TextRun>>> runs;
  };

  Entry& entry(const RichText& text, double size, double width, Weight weight, std::size_t from);
  const Measured& measured(const RichText& text, double size, Weight weight);
  // The same text measured in an earlier document of this thread (see text_measure.cpp).
  static std::shared_ptr<const Measured> shared(const RichText& text, double size, Weight weight);

  std::unordered_map<Key, Entry, Hash> wrapped_;
  // shared with the thread's cache of texts by content, which may drop them while they are used
  std::unordered_map<Key, std::shared_ptr<const Measured>, Hash> measured_;
};

}  // namespace epure::render::layout_detail
