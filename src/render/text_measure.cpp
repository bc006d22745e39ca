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
  // Most words end with a letter or a digit: neither an end mark, a closing mark, nor the last
  // byte of a closing quote.
  if (word.empty()) return false;
  const char last = word.back();
  if (static_cast<unsigned char>(last) < 0x80 && last != '.' && last != '!' && last != '?' && !closes(last)) return false;
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

// A line's source (line_source) as a view of the text when its words stand one space apart
// there, as they mostly do; else built in `scratch`.
std::string_view line_text(const MeasuredText& m, const MeasuredLine& line, std::string& scratch) {
  if (line.end == line.first) return {};  // an empty line: line_source's ""
  const auto& ws = m.pieces[line.piece];
  for (std::size_t k = line.first + 1; k < line.end; ++k)
    if (ws[k].offset != ws[k - 1].offset + ws[k - 1].size + 1) {
      scratch = line_source(m, line);
      return scratch;
    }
  const std::size_t begin = ws[line.first].offset, end = ws[line.end - 1].offset + ws[line.end - 1].size;
  return std::string_view(m.text).substr(begin, end - begin);
}

}  // namespace

const TextMeasure::Measured& TextMeasure::measured(const RichText& text, double size, Weight weight) {
  const Key key{&text, bits(size), 0, weight};
  auto it = measured_.find(key);
  if (it == measured_.end()) it = measured_.emplace(key, shared(text, size, weight)).first;
  return *it->second;
}

namespace {

// A text's content, size and weight: what its measure depends on. The view points into the
// cached measure's own copy of the text.
struct ContentKey {
  std::string_view text;
  std::uint64_t size = 0;
  Weight weight = Weight::regular;
  friend bool operator==(const ContentKey&, const ContentKey&) = default;
};
// From the text's length and its two ends only: a lookup costs the same for a long statement as
// for a prompt, and texts that differ only inside are told apart by the comparison.
struct ContentHash {
  std::size_t operator()(const ContentKey& k) const {
    constexpr std::size_t kEnd = 24;
    const std::string_view t = k.text;
    const std::size_t ends = t.size() <= 2 * kEnd ? std::hash<std::string_view>{}(t)
                                                   : hash_combine(std::hash<std::string_view>{}(t.substr(0, kEnd)),
                                                                  std::hash<std::string_view>{}(t.substr(t.size() - kEnd)));
    return hash_combine(hash_combine(hash_combine(ends, t.size()), k.size), static_cast<std::uint64_t>(k.weight));
  }
};
// Texts kept at most, per thread: a set's documents repeat their headings, prompts, the sheet's
// notes and each statement in its key (70 % of the texts a course's layout measures, a third of
// their bytes), while the texts with the instance's numbers in them come once. Past this many
// (a sheet and its key bring about 60 new ones) the cache starts again, which bounds its memory:
// 500 sheets' max RSS +1 MB over none (4,096 texts: +6 MB, for the same instructions within
// 0.3 %). The measures are the same either way.
constexpr std::size_t kSharedTexts = 1024;

}  // namespace

std::shared_ptr<const TextMeasure::Measured> TextMeasure::shared(const RichText& text, double size, Weight weight) {
  thread_local std::unordered_map<ContentKey, std::shared_ptr<const Measured>, ContentHash> cache;
  if (auto it = cache.find({text, bits(size), weight}); it != cache.end()) return it->second;
  auto m = std::make_shared<Measured>();
  m->text = measure_text(text, size, weight);
  int depth = 0;  // parentheses open after each word
  const std::string_view all = m->text.text;
  for (const auto& words : m->text.pieces) {
    auto& ends = m->sentence_ends.emplace_back();
    ends.reserve(words.size());
    for (const auto& w : words) {
      const std::string_view word = all.substr(w.offset, w.size);
      for (const char c : word) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      ends.push_back(depth <= 0 && ends_sentence(word));
    }
  }
  if (cache.size() >= kSharedTexts) cache.clear();
  cache.emplace(ContentKey{m->text.text, bits(size), weight}, m);
  return m;
}

TextMeasure::Entry& TextMeasure::entry(const RichText& text, double size, double width, Weight weight,
                                       std::size_t from) {
  const Key key{&text, bits(size), bits(width), weight, from};
  auto it = wrapped_.find(key);
  if (it != wrapped_.end()) return it->second;
  const Measured& m = measured(text, size, weight);
  Entry e;
  e.source = &m;
  WrappedText& w = e.wrapped;
  w.measured = &m.text;
  w.lines = break_measured(m.text, width, from);
  w.ends_sentence.reserve(w.lines.size());
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
    auto [it, fresh] = e.source->runs.try_emplace({bits(width), from});
    if (fresh) {
      std::string scratch;
      for (const MeasuredLine& line : e.wrapped.lines)
        it->second.push_back(parse_rich_text(line_text(*e.wrapped.measured, line, scratch), weight));
    }
    e.runs = &it->second;
  }
  return *e.runs;
}

}  // namespace epure::render::layout_detail
