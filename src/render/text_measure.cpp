#include "render/text_measure.h"

#include <algorithm>
#include <utility>

namespace epure::render::layout_detail {
namespace {

// Closing marks that may follow a sentence's end (".)", "?»", a markup group's "}").
bool closes(char c) { return c == ')' || c == ']' || c == '"' || c == '}' || c == '\''; }
bool ends_with(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// Whether a word ends a sentence: its last character but closing marks is ".", "!" or "?" (or
// the closing quote of French, "»", after one).
bool ends_sentence(std::string_view word) {
  for (;;) {
    if (ends_with(word, "\u00bb") || ends_with(word, "\u201d") || ends_with(word, "\u2019")) {
      word.remove_suffix(ends_with(word, "\u00bb") ? 2 : 3);
      while (!word.empty() && word.back() == ' ') word.remove_suffix(1);
    } else if (!word.empty() && closes(word.back())) {
      word.remove_suffix(1);
    } else {
      break;
    }
  }
  return !word.empty() && (word.back() == '.' || word.back() == '!' || word.back() == '?');
}

}  // namespace

const TextMeasure::Measured& TextMeasure::measured(const RichText& text, double size, Weight weight) {
  const Key key{&text, bits(size), 0, weight};
  auto it = measured_.find(key);
  if (it != measured_.end()) return it->second;
  Measured m{measure_text(text, size, weight), {}};
  int depth = 0;  // parentheses open after each word
  const std::string_view all = m.text.text;
  for (const auto& words : m.text.pieces) {
    auto& ends = m.sentence_ends.emplace_back();
    for (const auto& w : words) {
      const std::string_view word = all.substr(w.offset, w.size);
      for (const char c : word) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      ends.push_back(depth <= 0 && ends_sentence(word));
    }
  }
  return measured_.emplace(key, std::move(m)).first->second;
}

TextMeasure::Entry& TextMeasure::entry(const RichText& text, double size, double width, Weight weight,
                                       std::size_t from) {
  const Key key{&text, bits(size), bits(width), weight, from};
  auto it = wrapped_.find(key);
  if (it != wrapped_.end()) return it->second;
  const Measured& m = measured(text, size, weight);
  Entry e;
  WrappedText& w = e.wrapped;
  w.measured = &m.text;
  w.lines = break_measured(m.text, width, from);
  for (const MeasuredLine& line : w.lines) {
    w.widest = std::max(w.widest, line.width);
    w.ends_sentence.push_back(line.end > line.first && m.sentence_ends[line.piece][line.end - 1]);
  }
  return wrapped_.emplace(key, std::move(e)).first->second;
}

const WrappedText& TextMeasure::wrapped(const RichText& text, double size, double width, Weight weight,
                                        std::size_t from) {
  return entry(text, size, width, weight, from).wrapped;
}

const std::vector<std::vector<TextRun>>& TextMeasure::wrap(const RichText& text, double size, double width,
                                                           Weight weight, std::size_t from) {
  Entry& e = entry(text, size, width, weight, from);
  if (!e.runs) {
    e.runs.emplace();
    for (const MeasuredLine& line : e.wrapped.lines)
      e.runs->push_back(parse_rich_text(line_source(*e.wrapped.measured, line), weight));
  }
  return *e.runs;
}

}  // namespace epure::render::layout_detail
