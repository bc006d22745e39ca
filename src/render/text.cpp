#include "render/text.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include "render/font_metrics.h"
#include "render/utf8.h"

namespace epure::render {
namespace {

constexpr std::size_t npos = std::string_view::npos;

bool escapable(char c) { return c == '{' || c == '}' || c == '\\'; }

// Index of the '}' closing the '{' at s[open], skipping escapes and nested groups; npos when the
// group is never closed (its markup is then taken literally).
std::size_t closing_brace(std::string_view s, std::size_t open) {
  int depth = 0;
  for (std::size_t j = open; j < s.size(); ++j) {
    if (s[j] == '\\' && j + 1 < s.size() && escapable(s[j + 1])) {
      ++j;
    } else if (s[j] == '{') {
      ++depth;
    } else if (s[j] == '}' && --depth == 0) {
      return j;
    }
  }
  return npos;
}

// The runs of parse_rich_text: consecutive pieces of one shift and arrow make one run.
class RunSink final : public RichSink {
 public:
  explicit RunSink(bool bold) : bold_(bold) {}
  void piece(std::string_view text, Shift shift, bool arrow) override {
    if (out.empty() || out.back().shift != shift || out.back().arrow != arrow) {
      out.push_back(TextRun{std::string(), shift, arrow, bold_});
    }
    out.back().text += text;
  }
  std::vector<TextRun> out;

 private:
  bool bold_;
};

// Whether a text has a character where the parser may see markup ('\\', '_', '^' start every
// group and escape); a text without one is a single piece of text.
bool may_hold_markup(std::string_view s) {
  for (const char c : s)
    if (c == '\\' || c == '_' || c == '^') return true;
  return false;
}

class Parser {
 public:
  Parser(std::string_view s, RichSink& sink) : s_(s), sink_(sink) {}

  void run() { parse(0, s_.size(), Shift::none, false); }

 private:
  void emit(std::string_view text, Shift shift, bool arrow) { sink_.piece(text, shift, arrow); }

  // Parses s_[begin, end); a group inherits its parent's shift (no script of a script) and arrow.
  void parse(std::size_t begin, std::size_t end, Shift shift, bool arrow) {
    constexpr std::string_view kVec = "\\vec{";
    std::size_t i = begin;
    while (i < end) {
      const char c = s_[i];
      if (c == '\\' && i + 1 < end && escapable(s_[i + 1])) {
        emit(s_.substr(i + 1, 1), shift, arrow);
        i += 2;
        continue;
      }
      if (c == '\\' && s_.substr(i, kVec.size()) == kVec) {
        const std::size_t close = closing_brace(s_, i + kVec.size() - 1);
        if (close != npos && close < end) {
          parse(i + kVec.size(), close, shift, true);
          i = close + 1;
          continue;
        }
      }
      if ((c == '_' || c == '^') && i + 1 < end && s_[i + 1] == '{') {
        const std::size_t close = closing_brace(s_, i + 1);
        if (close != npos && close < end) {
          const Shift inner = shift != Shift::none ? shift : c == '_' ? Shift::sub : Shift::super;
          parse(i + 2, close, inner, arrow);
          i = close + 1;
          continue;
        }
      }
      // Up to the next character that may start markup, the text goes out as one piece.
      std::size_t j = i + 1;
      while (j < end && s_[j] != '\\' && s_[j] != '_' && s_[j] != '^') ++j;
      emit(s_.substr(i, j - i), shift, arrow);
      i = j;
    }
  }

  std::string_view s_;
  RichSink& sink_;
};

// The advances of `text` added to `em`, one character after the other (from 0: a text's sum).
double advance_sum(std::string_view text, Face face, double em = 0) {
  const auto& ascii = detail::kAdvanceEm[face == Face::bold ? 1 : 0];
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x80) {  // the same sum, in the same order, without decoding
      em += ascii[byte];
      ++i;
      continue;
    }
    const utf8::Decoded d = utf8::decode(text, i);
    em += advance_em(d.cp, face);
    i += d.length;
  }
  return em;
}

// The words of one line of `rich` (no '\n' in it): split at spaces outside markup groups. A
// word that must not start a line (see glued_to_previous) says so.
struct Word {
  std::string_view text;
  bool glued = false;  // the space before it is not a place to break the line
};

// Tokens that bind the words either side of them: a line never ends or starts at "=" in
// "I = A + t·û", nor splits "∘" from a map's factors.
bool binding_token(std::string_view w) {
  static constexpr std::string_view kBinding[] = {"=", "≠", "≈", "≤", "≥", "<", ">", "+", "−", "·", "×", "/", "∘", "→", "↦"};
  if (w.empty() || w.size() > 3) return false;  // each is one character: at most 3 bytes
  for (auto t : kBinding)
    if (w == t) return true;
  return false;
}

// French punctuation that follows its word even after a space ("cercle ?"), and quotes that
// hold their word ("« aucun »").
bool sticks_to_previous(std::string_view w) {
  static constexpr std::string_view kAfter[] = {"?", "!", ":", ";", "»"};
  for (auto t : kAfter)
    if (w.substr(0, t.size()) == t) return true;
  return false;
}

// A short bracketed group ("(−2 ; 4)", "[−1 ; 1]", "échelle(a ; b)") is one formula: its spaces
// are not breaks. A long one is prose in parentheses, which may wrap.
constexpr std::size_t kShortGroup = 32;  // bytes, brackets included

std::vector<Word> words(std::string_view rich) {
  std::vector<Word> out;
  // a word a space at most: one allocation, not one for each doubling
  out.reserve(static_cast<std::size_t>(std::count(rich.begin(), rich.end(), ' ')) + 1);
  std::size_t start = 0;
  bool glue_next = false;
  std::size_t group_end = npos;  // the closing bracket of the short group we are in
  const auto flush = [&](std::size_t end) {
    if (end > start) {
      out.push_back({rich.substr(start, end - start), glue_next});
    }
  };
  const auto short_group_end = [&](std::size_t open) -> std::size_t {
    const char close = rich[open] == '(' ? ')' : ']';
    int depth = 0;
    for (std::size_t j = open; j < rich.size() && j - open < kShortGroup; ++j) {
      if (rich[j] == '\\' && j + 1 < rich.size() && escapable(rich[j + 1])) {
        ++j;
      } else if (rich[j] == '{') {  // a markup group is skipped whole, as words() skips it
        const std::size_t close_brace = closing_brace(rich, j);
        if (close_brace == npos) return npos;
        j = close_brace;
      } else if (rich[j] == rich[open]) ++depth;
      else if (rich[j] == close && --depth == 0) return j;
    }
    return npos;
  };
  for (std::size_t j = 0; j < rich.size(); ++j) {
    const char c = rich[j];
    if (c == '\\' && j + 1 < rich.size() && escapable(rich[j + 1])) {
      ++j;
    } else if (c == '{') {
      const std::size_t close = closing_brace(rich, j);
      if (close != npos) j = close;
    } else if ((c == '(' || c == '[') && group_end == npos) {
      group_end = short_group_end(j);
    } else if (j == group_end) {
      group_end = npos;
    } else if (c == ' ') {
      flush(j);
      glue_next = group_end != npos;
      start = j + 1;
    }
  }
  flush(rich.size());
  // The binding tokens and the punctuation glue across the spaces around them.
  for (std::size_t i = 1; i < out.size(); ++i) {
    if (binding_token(out[i].text) || binding_token(out[i - 1].text) || sticks_to_previous(out[i].text) ||
        out[i - 1].text == "«")
      out[i].glued = true;
  }
  return out;
}

// text_width of one word of rich text. Most words carry no markup: they are one unshifted run,
// so their width is measured straight from the bytes (the same sum, in the same order, as
// text_width gives) instead of parsing them into runs first.
double word_width(std::string_view word, double font_size, Face face) {
  const bool markup = std::any_of(word.begin(), word.end(), [](char c) {
    return c == '\\' || c == '_' || c == '^' || c == '{' || c == '}';
  });
  if (markup) return text_width(word, font_size, face == Face::bold ? Weight::bold : Weight::regular);
  return advance_sum(word, face) * font_size;
}

// Letters of DejaVu Sans that reach no higher than the x-height, and glyphs that go below the
// baseline: a label "u" or "A" gets a box that fits it, not a generic one.
constexpr std::string_view kShortLetters = "acemnorsuvwxz";
constexpr std::string_view kDescending = "gjpqyQ,;()[]{}|_@$";

struct Ink {
  double top, bottom;  // em above and below the baseline
};

// The two sets above as flags per byte; any byte of a multi-byte character (≥ 0x80) is neither
// short nor known not to descend.
constexpr unsigned char kShort = 1, kMayDescend = 2;
constexpr std::array<unsigned char, 256> kInkClass = [] {
  std::array<unsigned char, 256> c{};
  for (char ch : kShortLetters) c[static_cast<unsigned char>(ch)] |= kShort;
  for (char ch : kDescending) c[static_cast<unsigned char>(ch)] |= kMayDescend;
  for (std::size_t b = 0x80; b < 256; ++b) c[b] = kMayDescend;  // ç, Greek, arrows, √
  return c;
}();

Ink run_ink(std::string_view text) {
  const VerticalMetrics v = vertical_metrics();
  // Ascenders and digits of DejaVu Sans reach 0.76 em, capitals 0.73 em.
  constexpr double kAscenderTop = 0.76;
  bool all_short = !text.empty();
  bool descends = false;
  for (const char ch : text) {
    const unsigned char c = kInkClass[static_cast<unsigned char>(ch)];
    all_short = all_short && (c & kShort);
    descends = descends || (c & kMayDescend);
  }
  return {all_short ? v.x_height : kAscenderTop, descends ? v.descent : 0.02};
}

}  // namespace

std::vector<RunPlacement> place_runs(std::span<const TextRun> runs, double font_size) {
  std::vector<RunPlacement> out;
  out.reserve(runs.size());
  double x = 0;
  for (const TextRun& r : runs) {
    RunPlacement p;
    p.x = x;
    p.size = r.shift == Shift::none ? font_size : font_size * kScriptScale;
    p.rise = r.shift == Shift::sub     ? -kSubShift * font_size
             : r.shift == Shift::super ? kSuperShift * font_size
                                       : 0;
    p.width = advance_sum(r.text, r.bold ? Face::bold : Face::regular) * p.size;
    p.top = run_ink(r.text).top * p.size;
    x += p.width;
    out.push_back(p);
  }
  return out;
}

TextExtent text_extent(std::span<const TextRun> runs, double font_size) {
  TextExtent e;
  const std::vector<RunPlacement> placed = place_runs(runs, font_size);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunPlacement& p = placed[i];
    double top = p.rise + p.top;
    if (runs[i].arrow) top += (kArrowGap + kArrowHeadHalf) * p.size;
    const double bottom = run_ink(runs[i].text).bottom * p.size - p.rise;
    e.ascent = std::max(e.ascent, top);
    e.descent = std::max(e.descent, bottom);
    e.width = p.x + p.width;
  }
  return e;
}

std::vector<TextRun> parse_rich_text(std::string_view rich, Weight weight) {
  // Most texts and lines hold no markup: the parser would give them as one unshifted run.
  if (!may_hold_markup(rich)) {
    std::vector<TextRun> out;
    if (!rich.empty()) out.push_back(TextRun{std::string(rich), Shift::none, false, weight == Weight::bold});
    return out;
  }
  RunSink runs(weight == Weight::bold);
  Parser(rich, runs).run();
  return std::move(runs.out);
}

void parse_rich_pieces(std::string_view rich, RichSink& sink) { Parser(rich, sink).run(); }

double text_width(std::span<const TextRun> runs, double font_size) {
  double width = 0;
  for (const TextRun& r : runs) {
    const double scale = r.shift == Shift::none ? 1.0 : kScriptScale;
    width += advance_sum(r.text, r.bold ? Face::bold : Face::regular) * scale;
  }
  return width * font_size;
}

namespace {

// text_width of the runs parse_rich_text would make, from the parser's pieces without making
// them: a run's advances are added piece after piece, in the run's order (a piece never splits a
// character: pieces end at ASCII markup), then scaled and added as text_width adds the runs.
class WidthSink final : public RichSink {
 public:
  explicit WidthSink(Face face) : face_(face) {}
  void piece(std::string_view text, Shift shift, bool arrow) override {
    if (!open_ || shift != shift_ || arrow != arrow_) {
      close();
      open_ = true;
      shift_ = shift;
      arrow_ = arrow;
    }
    em_ = advance_sum(text, face_, em_);
  }
  double width() {
    close();
    return width_;
  }

 private:
  void close() {
    if (open_) width_ += em_ * (shift_ == Shift::none ? 1.0 : kScriptScale);
    open_ = false;
    em_ = 0;
  }
  Face face_;
  bool open_ = false, arrow_ = false;
  Shift shift_ = Shift::none;
  double em_ = 0, width_ = 0;
};

}  // namespace

double text_width(std::string_view rich, double font_size, Weight weight) {
  const Face face = weight == Weight::bold ? Face::bold : Face::regular;
  // Without markup, one unshifted run: the same sum and product as text_width of the runs.
  if (!may_hold_markup(rich)) return advance_sum(rich, face) * font_size;
  WidthSink sink(face);
  Parser(rich, sink).run();
  return sink.width() * font_size;
}

std::vector<std::vector<TextRun>> wrap_rich_text(std::string_view rich, double font_size,
                                                 double max_width, Weight weight) {
  std::vector<std::vector<TextRun>> lines;
  for (const auto& line : wrap_rich_source(rich, font_size, max_width, weight))
    lines.push_back(parse_rich_text(line, weight));
  return lines;
}

MeasuredText measure_text(std::string_view rich, double font_size, Weight weight) {
  MeasuredText m;
  m.text = std::string(rich);
  if (rich.empty()) return m;
  const Face face = weight == Weight::bold ? Face::bold : Face::regular;
  m.space = advance_em(U' ', face) * font_size;
  const std::string_view text = m.text;
  std::size_t start = 0;
  for (;;) {
    // A '\n' is a hard break: each piece between them is wrapped on its own.
    const std::size_t nl = text.find('\n', start);
    const std::string_view piece = text.substr(start, nl == npos ? npos : nl - start);
    auto& out = m.pieces.emplace_back();
    const std::vector<Word> ws = words(piece);
    out.reserve(ws.size());
    for (const Word& w : ws)
      out.push_back({static_cast<std::size_t>(w.text.data() - text.data()), w.text.size(),
                     word_width(w.text, font_size, face), w.glued});
    if (nl == npos) break;
    start = nl + 1;
  }
  return m;
}

std::vector<MeasuredLine> break_measured(const MeasuredText& m, double max_width, std::size_t first_word) {
  std::vector<MeasuredLine> lines;
  if (m.text.empty()) return lines;
  const double space = m.space;
  for (std::size_t p = 0; p < m.pieces.size(); ++p) {
    const auto& ws = m.pieces[p];
    const std::size_t start = p == 0 ? std::min(first_word, ws.size()) : 0;
    MeasuredLine line{p, start, start, 0};
    const auto finish = [&](std::size_t next) {
      lines.push_back(line);
      line = MeasuredLine{p, next, next, 0};
    };
    // Adds word k to the line, or starts the next line with it when it does not fit.
    const auto place = [&](std::size_t k) {
      const bool any = line.end > line.first;
      if (any && line.width + space + ws[k].width > max_width) finish(k);
      if (line.end > line.first) line.width += space;  // two sums, in wrap_measured's order
      line.width += ws[k].width;
      line.end = k + 1;
    };
    // Glued words move to the next line together, as one chunk; a chunk wider than a whole line
    // falls back to breaking at its own spaces.
    for (std::size_t i = start; i < ws.size();) {
      std::size_t j = i + 1;
      while (j < ws.size() && ws[j].glued) ++j;
      double chunk = 0;
      for (std::size_t k = i; k < j; ++k) chunk += ws[k].width + (k > i ? space : 0);
      if (j - i > 1 && chunk <= max_width && line.end > line.first && line.width + space + chunk > max_width) finish(i);
      for (std::size_t k = i; k < j; ++k) {
        if (chunk <= max_width && k > i) {  // within a chunk that fits a line: never a break
          line.width += space + ws[k].width;
          line.end = k + 1;
        } else {
          place(k);
        }
      }
      i = j;
    }
    lines.push_back(line);  // an empty piece (two '\n' in a row) gives an empty line
  }
  return lines;
}

std::string line_source(const MeasuredText& m, const MeasuredLine& line) {
  std::string out;
  const auto& ws = m.pieces[line.piece];
  for (std::size_t k = line.first; k < line.end; ++k) {
    if (k > line.first) out += ' ';
    out.append(m.text, ws[k].offset, ws[k].size);
  }
  return out;
}

std::vector<std::string> wrap_measured(const MeasuredText& m, double max_width) {
  std::vector<std::string> lines;
  for (const MeasuredLine& line : break_measured(m, max_width)) lines.push_back(line_source(m, line));
  return lines;
}

std::vector<std::string> wrap_rich_source(std::string_view rich, double font_size, double max_width,
                                          Weight weight) {
  return wrap_measured(measure_text(rich, font_size, weight), max_width);
}

}  // namespace epure::render
