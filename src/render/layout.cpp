#include "render/layout.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "render/scene_painter.h"
#include "support/portable.h"

namespace epure::render {
namespace {

// Baseline of a text line below the top of its line box, × font size: DejaVu Sans's ascent is
// 0.93 em and an arrow over AB sits just above the capitals, both inside the line box.
constexpr double kBaseline = 1.02;
// Baseline that centres capitals and digits (cap height 0.73 em) on a box's middle, × font size.
constexpr double kCentredBaseline = 0.36;
// Page space is compared in points summed from a few dozen terms; this much rounding never
// decides a page break.
constexpr double kFitSlack = 1e-6;
// A section's opening (statement, first figure and its fields) that does not fit in what is
// left of a page goes whole to the next one only when at most this share of the page's text
// height is left; with more room it starts here and is broken (see open_section), since keeping
// every opening whole leaves a sheet's pages half empty (6 pages a sheet instead of under 5).
// Measured on the default course (30 sheets, en and fr, each difficulty): 0.1 gives the fewest
// pages (a sheet 4.23–4.30 pages on average, from 4.37–4.40 with 0.2); 0.45 and above, 5.
constexpr double kMaxOpeningWaste = 0.1;
// Paragraphs go beside a figure when that makes the exercise shorter by more than this many
// lines: half a line is enough to be worth the narrower column (a whole line cost sheets pages).
constexpr double kSideSaving = 0.5;

// Horizontal gaps, in points.
constexpr double kPromptGap = 8;    // after a prompt column
constexpr double kIdGap = 10;       // before a question id at the right edge
constexpr double kBoxGap = 3;       // between a box and the "(", ";" around it
constexpr double kTickGap = 4;      // between a tick box and its option
constexpr double kOptionGap = 16;   // between two options
constexpr double kHeaderGap = 12;   // between the header's left and right columns
constexpr double kSideGap = 18;     // between a figure and the fields or answers beside it
constexpr double kSidePromptShare = 0.3;  // of that column, at most, for the fields' prompts
// A key's answer too long for the cell beside its prompt goes on the line under the prompt, this
// much indented, when that wraps it less (a point or a value is then on one line).
constexpr double kStackIndent = 12;
// A page but a document's last is never left less than this full by a choice of flow().
constexpr double kMinPageFill = 0.5;
// flow() tries every combination of the sections' fallbacks: 2^n trials of the atoms' heights
// alone. A sheet has seven sections; a document with more keeps the page-by-page choice.
constexpr std::size_t kMaxFallbackChoices = 10;
// At most this many paragraphs before a figure are tried in the column beside it.
constexpr std::size_t kMaxSideParagraphs = 8;
// Wider than any line a page holds: what wrapping gives for this width is the text's own lines
// (only its '\n' break it).
constexpr double kUnbounded = 1e9;
// The name fields: the name gets the larger share of the line (names are longer than student
// numbers); a writing line starts a little after its label and runs just under the baseline,
// below the descenders (0.24 em).
constexpr double kNameShare = 0.6;
constexpr double kWritingLineGap = 4;
constexpr double kWritingLineDrop = 3;

std::vector<TextRun> plain(std::string text, bool bold = false) {
  TextRun run;
  run.text = std::move(text);
  run.bold = bold;
  return {std::move(run)};
}

// Everything one atom puts on the page; x in page coordinates, y from the atom's top.
struct Fragment {
  std::vector<PlacedBox> boxes;
  std::vector<PlacedRule> rules;
  std::vector<PlacedFigure> figures;
  std::vector<PlacedText> texts;
  std::vector<PlacedQr> codes;
  // A layout option only measured (its height, whether it fits a column) keeps no text: the
  // options tried for a figure and its neighbours would otherwise copy every run of every line
  // again for each one. What the fit test needs of the texts is kept as two extents.
  bool keep_texts = true;
  bool track_extents = false;       // set for the atoms of a column beside a figure
  double text_right_edge = -1e300;  // the right end of the furthest text that is not muted
  double muted_left = 1e300;        // the left end of the first muted text (a question id)
  double box_right_edge = -1e300;   // the right end of the furthest box

  void box(PlacedBox b) {
    box_right_edge = std::max(box_right_edge, b.rect.right());
    if (keep_texts) boxes.push_back(std::move(b));
  }

  void text(const std::vector<TextRun>& runs, double x, double baseline, double size, Ink ink = Ink::text) {
    note_extent(runs, x, size, ink);
    if (keep_texts) texts.push_back({{x, baseline}, size, runs, ink});
  }
  void text(std::vector<TextRun>&& runs, double x, double baseline, double size, Ink ink = Ink::text) {
    note_extent(runs, x, size, ink);
    if (keep_texts) texts.push_back({{x, baseline}, size, std::move(runs), ink});
  }
  // Right-aligned on `right`.
  void text_right(std::vector<TextRun> runs, double right, double baseline, double size, Ink ink) {
    const double width = text_width(runs, size);
    if (ink == Ink::muted) {
      muted_left = std::min(muted_left, right - width);
    } else {
      text_right_edge = std::max(text_right_edge, right);
    }
    if (keep_texts) texts.push_back({{right - width, baseline}, size, std::move(runs), ink});
  }
  void note_extent(const std::vector<TextRun>& runs, double x, double size, Ink ink) {
    if (!track_extents) return;
    if (ink == Ink::muted) {
      muted_left = std::min(muted_left, x);
    } else {
      text_right_edge = std::max(text_right_edge, x + text_width(runs, size));
    }
  }

  // Appends `other`'s content, moved down by dy.
  void append(Fragment&& other, double dy) {
    for (auto& b : other.boxes) {
      b.rect.y += dy;
      boxes.push_back(std::move(b));
    }
    for (auto& r : other.rules) {
      r.a.y += dy;
      r.b.y += dy;
      rules.push_back(r);
    }
    for (auto& f : other.figures) {
      f.rect.y += dy;
      figures.push_back(f);
    }
    for (auto& t : other.texts) {
      t.baseline.y += dy;
      texts.push_back(std::move(t));
    }
    text_right_edge = std::max(text_right_edge, other.text_right_edge);
    box_right_edge = std::max(box_right_edge, other.box_right_edge);
    muted_left = std::min(muted_left, other.muted_left);
  }

  void move_into(LaidOutPage& page, double dy) {
    for (auto& b : boxes) {
      b.rect.y += dy;
      page.boxes.push_back(std::move(b));
    }
    for (auto& r : rules) {
      r.a.y += dy;
      r.b.y += dy;
      page.rules.push_back(r);
    }
    for (auto& f : figures) {
      f.rect.y += dy;
      page.figures.push_back(f);
    }
    for (auto& t : texts) {
      t.baseline.y += dy;
      page.texts.push_back(std::move(t));
    }
    for (auto& q : codes) {
      q.rect.y += dy;
      page.codes.push_back(std::move(q));
    }
  }
};

// The unit of page breaking: a line of a paragraph, a heading, a row of fields, a figure.
struct Atom {
  double height = 0;
  double space_before = 0;   // dropped at the top of a page
  bool break_before = true;  // a page may end just before this atom
  bool section_start = false;
  std::size_t head_atoms = 0;  // on a section's first atom: how many atoms its statement takes
  int section = -1, block = -1;
  // The blocks set beside a figure in this atom, with rectangles from the atom's top.
  std::vector<PlacedBlock> side_blocks;
  bool wrapped = false;  // a key's answer broken over lines it does not ask for
  bool follows_heading = false;  // right after a heading: a page may not end before it
  Fragment content;
};

// What a wrapped text is remembered by: the text, its size and its width. Looked up through a view,
// so that a lookup copies nothing.
struct WrapView {
  std::string_view text;
  double size = 0, width = 0;
};
// The same width is the same bits: a memo, not a tolerance (the options ask the widths they
// computed the same way).
inline std::uint64_t bits(double x) { return portable::bit_cast<std::uint64_t>(x); }
// Boost's hash_combine: the memo keys below hash several fields.
inline std::size_t hash_combine(std::size_t h, std::uint64_t v) {
  return h ^ (std::hash<std::uint64_t>{}(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}
inline bool operator==(const WrapView& a, const WrapView& b) {
  return a.text == b.text && bits(a.size) == bits(b.size) && bits(a.width) == bits(b.width);
}
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

// A text wrapped at a width: its lines' markup, enough to count them, and their runs once a
// line is set.
struct Wrapped {
  std::vector<std::string> lines;
  std::optional<std::vector<std::vector<TextRun>>> runs;
};

// A row of fields or of a key's answers, measured with a given geometry (see Builder::replay).
struct RowKey {
  const void* block = nullptr;
  std::uint64_t left = 0, width = 0, column = 0;
  bool follows = false, in_column = false;
  friend bool operator==(const RowKey&, const RowKey&) = default;
};
struct RowHash {
  std::size_t operator()(const RowKey& k) const {
    std::size_t h = std::hash<const void*>{}(k.block);
    for (std::uint64_t v : {k.left, k.width, k.column, std::uint64_t{k.follows} * 2 + k.in_column}) h = hash_combine(h, v);
    return h;
  }
};

class Builder {
 public:
  Builder(const Document& doc, const LayoutStyle& style)
      : doc_(doc),
        s_(style),
        left_(style.margin_left),
        right_(doc.page.width_pt - style.margin_right),
        width_(right_ - left_),
        top_(style.margin_top + style.header_height + style.header_gap),
        bottom_(doc.page.height_pt - style.margin_bottom),
        body_line_(style.body_size * style.line_height) {}

  std::vector<LaidOutPage> run() {
    first_page();
    for (std::size_t s = 0; s < doc_.sections.size(); ++s) section(static_cast<int>(s));
    flow();
    for (auto& page : pages_) header(page);
    return std::move(pages_);
  }

 private:
  // ---- measuring: Document → atoms -------------------------------------------------------

  // wrap_rich_text, remembered: the options tried for a figure and its neighbours (and a
  // section's fallback) wrap the same texts at the same widths again and again.
  // The lines' markup is enough to count them; their runs are parsed when a line is set.
  Wrapped& wrapped(const RichText& text, double size, double width) {
    const WrapView view{text, size, width};
    auto it = wrapped_.find(view);
    if (it == wrapped_.end())
      it = wrapped_.emplace(WrapKey{text, size, width}, Wrapped{wrap_measured(measured(text, size), width), {}}).first;
    return it->second;
  }
  std::size_t line_count(const RichText& text, double size, double width) {
    return wrapped(text, size, width).lines.size();
  }
  const std::vector<std::vector<TextRun>>& wrap(const RichText& text, double size, double width) {
    Wrapped& w = wrapped(text, size, width);
    if (!w.runs) {
      w.runs.emplace();
      for (const auto& line : w.lines) w.runs->push_back(parse_rich_text(line));
    }
    return *w.runs;
  }
  // A text's words and their widths, measured once for all the widths it is wrapped at.
  const MeasuredText& measured(const RichText& text, double size) {
    const WrapView view{text, size, 0};
    auto it = measured_.find(view);
    if (it == measured_.end()) it = measured_.emplace(WrapKey{text, size, 0}, measure_text(text, size)).first;
    return it->second;
  }
  // wrap_rich_source at the text width, remembered for the same reason.
  const std::vector<std::string>& wrap_source(const RichText& text) {
    const WrapView view{text, s_.body_size, width_};
    auto it = sources_.find(view);
    if (it == sources_.end())
      it = sources_.emplace(WrapKey{text, s_.body_size, width_}, wrap_measured(measured(text, s_.body_size), width_)).first;
    return it->second;
  }

  // An option only measured keeps no text, so the atom of a row of fields or answers is the
  // same each time the same block is measured with the same geometry: the options for a figure
  // and its neighbours measure the same rows many times. True when the row was pushed again.
  RowKey row_key(const void* block, double column, bool follows) const {
    return {block, bits(left_), bits(width_), bits(column), follows, in_column_};
  }
  bool replay(const RowKey& key) {
    if (!measuring_) return false;
    auto it = measured_rows_.find(key);
    if (it == measured_rows_.end()) return false;
    push(it->second);
    return true;
  }
  void remember(const RowKey& key, const Atom& a) {
    if (measuring_) measured_rows_.emplace(key, a);
  }

  // An atom for the current mode: a measured option keeps no text, a column's atoms note how far
  // their texts reach.
  Atom new_atom() const {
    Atom a;
    a.content.keep_texts = !measuring_;
    a.content.track_extents = in_column_;
    return a;
  }

  void push(Atom atom) {
    if (after_heading_) atom.break_before = false;  // a heading never ends a page
    atom.follows_heading = after_heading_;
    if (after_figure_) atom.space_before = std::max(atom.space_before, s_.figure_space);
    after_heading_ = false;
    after_figure_ = false;
    atoms_.push_back(std::move(atom));
  }

  void first_page() {
    if (doc_.student_fields) {
      Atom a = new_atom();
      a.height = s_.name_row_height;
      // The sheet id's QR code at the right end of the row (its quiet zone is its margin), the
      // writing lines in what is left.
      double fields_right = right_;
      if (!doc_.sheet_id.empty()) {
        QrCode code = encode_qr(doc_.sheet_id);
        const double side = s_.qr_module * (code.size + 2 * kQrQuietZone);
        const double quiet = s_.qr_module * kQrQuietZone;
        a.height = std::max(a.height, side - quiet);  // the top quiet zone may reach into header_gap
        a.content.codes.push_back({{right_ - side + quiet, -quiet, side, side}, std::move(code)});
        fields_right = right_ - side + quiet - kHeaderGap;
      }
      const double size = s_.body_size;
      const double baseline = s_.name_row_height - kWritingLineGap - kWritingLineDrop;
      const double line_y = baseline + kWritingLineDrop;
      auto name = plain(doc_.words.name);
      auto number = plain(doc_.words.student_number);
      const double name_w = text_width(name, size);
      const double number_w = text_width(number, size);
      const double split = left_ + (fields_right - left_) * kNameShare;
      a.content.text(std::move(name), left_, baseline, size);
      a.content.rules.push_back({{left_ + name_w + kWritingLineGap, line_y}, {split - kHeaderGap, line_y}, 0.6, Ink::text});
      a.content.text(std::move(number), split, baseline, size);
      a.content.rules.push_back({{split + number_w + kWritingLineGap, line_y}, {fields_right, line_y}, 0.6, Ink::text});
      push(std::move(a));
    }
    if (!doc_.header_note.empty()) paragraph(-1, -1, doc_.header_note, false);
  }

  // The builder's state before a block: undoing a block's atoms goes back to it.
  struct Mark {
    std::size_t atoms = 0;
    bool after_heading = false, after_figure = false;
  };
  Mark mark() const { return {atoms_.size(), after_heading_, after_figure_}; }
  void undo(const Mark& m) {
    atoms_.resize(m.atoms);
    after_heading_ = m.after_heading;
    after_figure_ = m.after_figure;
  }

  // A section's atoms. When a statement or steps went beside a figure, open_section may lay the
  // section out again without that (fallback), from the builder's state at its start.
  void section(int si) {
    const Mark start = mark();
    side_used_ = false;
    allow_side_ = true;
    build_section(si);
    if (side_used_) fallback_.emplace(si, start);
  }

  // The section laid out with no paragraph beside a figure.
  std::vector<Atom> fallback(int si, const Mark& start) {
    const Mark now = mark();
    after_heading_ = start.after_heading;
    after_figure_ = start.after_figure;
    allow_side_ = false;
    build_section(si);
    allow_side_ = true;
    std::vector<Atom> atoms(std::make_move_iterator(atoms_.begin() + static_cast<std::ptrdiff_t>(now.atoms)),
                            std::make_move_iterator(atoms_.end()));
    undo(now);
    return atoms;
  }

  void build_section(int si) {
    const auto& blocks = doc_.sections[static_cast<std::size_t>(si)].blocks;
    section_begin_ = atoms_.size();
    marks_.clear();
    // The statement: from the heading to the first figure, or to the first field or answer.
    std::size_t head_end = 0;
    for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
      const Block& block = blocks[bi];
      const Block* before = bi > 0 ? &blocks[bi - 1] : nullptr;
      const int b = static_cast<int>(bi);
      const bool answers = std::holds_alternative<AnswerField>(block) || std::holds_alternative<AnswerLine>(block);
      if (head_end == 0 && answers) head_end = atoms_.size();
      if (marks_.size() <= bi) marks_.resize(bi + 1);
      marks_[bi] = mark();
      if (const auto* h = std::get_if<Heading>(&block)) {
        heading(si, b, *h);
      } else if (const auto* p = std::get_if<Paragraph>(&block)) {
        paragraph(si, b, p->text, p->emphasis);
      } else if (const auto* f = std::get_if<Figure>(&block)) {
        const std::size_t figure_atom = figure_with_neighbours(si, bi, *f, blocks);
        if (head_end == 0) head_end = figure_atom;
        bi = answers_run_end(blocks, bi + 1) - 1;  // the fields or answers are placed
      } else if (const auto* field = std::get_if<AnswerField>(&block)) {
        const bool follows = before && std::holds_alternative<AnswerField>(*before);
        if (!follows) field_column_ = field_prompt_column(blocks, bi);
        answer_field(si, b, *field, follows);
      } else if (const auto* line = std::get_if<AnswerLine>(&block)) {
        const bool follows = before && std::holds_alternative<AnswerLine>(*before);
        if (!follows) key_column_ = key_prompt_column(blocks, bi);
        answer_line(si, b, *line, follows);
      }
    }
    if (atoms_.size() > section_begin_) {
      Atom& first = atoms_[section_begin_];
      first.section_start = true;
      first.head_atoms = (head_end > section_begin_ ? head_end : atoms_.size()) - section_begin_;
    }
  }

  // A figure, the run of fields or answers after it, and the plain paragraphs just before it:
  // the answers beside the figure when they fit (else under it), and, when that makes the whole
  // shorter by more than half a line, the last paragraphs before the figure in the column beside it
  // too, above the answers (or with the answers under the figure): a statement read beside the
  // figure it describes, a key's last steps beside their construction. The figure keeps the width
  // its kind asks for. Returns the index of the atom after the figure's.
  std::size_t figure_with_neighbours(int si, std::size_t fi, const Figure& f, const std::vector<Block>& blocks) {
    const std::size_t run_end = answers_run_end(blocks, fi + 1);
    // The plain paragraphs right before the figure (not the heading, not a shaded box).
    std::size_t first = fi;
    while (first > 0 && fi - first < kMaxSideParagraphs) {
      const auto* p = std::get_if<Paragraph>(&blocks[first - 1]);
      if (!p || p->emphasis) break;
      --first;
    }
    const Mark start = marks_[first];
    const bool follows = fi > 0 && std::holds_alternative<Paragraph>(blocks[fi - 1]);
    // Option (k, answers_beside): the last k paragraphs beside the figure, with the answers in
    // the column too or under the figure; k = 0 is the figure with its answers beside or under it.
    // With `split` lines, the paragraph just before the figure keeps its first `split` lines
    // across the page and sets the rest in the column (k is then 1): the statement flows around
    // the figure, into the room its answers leave.
    std::vector<std::string> source;
    auto joined = [&](std::size_t from, std::size_t to) {
      std::string text;
      for (std::size_t l = from; l < to; ++l) text += (l > from ? " " : "") + source[l];
      return text;
    };
    auto emit = [&](std::size_t k, bool answers_beside, std::size_t split = 0) -> std::optional<std::size_t> {
      undo(start);
      for (std::size_t p = first; p < fi - k; ++p) {
        const auto& para = std::get<Paragraph>(blocks[p]);
        paragraph(si, static_cast<int>(p), para.text, para.emphasis);
      }
      std::optional<RichText> tail;
      if (split > 0) {
        // Its first `split` lines are the paragraph's own first lines: measured, they are only
        // counted.
        if (measuring_) line_atoms(si, static_cast<int>(fi - 1), split, nullptr);
        else paragraph(si, static_cast<int>(fi - 1), joined(0, split), false);
        tail = joined(split, source.size());
      }
      std::vector<std::size_t> side;
      for (std::size_t p = fi - k; p < fi; ++p) side.push_back(p);
      const bool with_answers = k == 0 || answers_beside;
      if (with_answers)
        for (std::size_t a = fi + 1; a < run_end; ++a) side.push_back(a);
      bool placed = false;
      if (!side.empty())
        placed = beside(si, static_cast<int>(fi), f, k > 0 && split == 0 ? false : follows, blocks, side, k > 0 && split == 0, tail);
      if (!placed) {
        if (k > 0) return std::nullopt;
        figure(si, static_cast<int>(fi), f, follows);
      }
      const std::size_t after_figure = atoms_.size();
      if (!(placed && with_answers)) emit_answers(si, blocks, fi + 1, run_end);
      return after_figure;
    };
    auto height = [&]() { return span(start.atoms, atoms_.size()) + (atoms_.size() > start.atoms ? atoms_[start.atoms].space_before : 0); };
    double best = 0;
    std::size_t best_k = 0;
    bool best_beside = false;
    // Every option is built only to be measured (no text kept); the best is then built in full.
    measuring_ = true;
    if (!emit(0, false)) {  // never: k = 0 always places
      measuring_ = false;
      return atoms_.size();
    }
    best = height() - kSideSaving * body_line_;  // the paragraphs beside must save something
    // More paragraphs make the column only taller: once none fits beside the figure, stop.
    for (std::size_t k = 1; allow_side_ && k <= fi - first; ++k) {
      bool any = false;
      for (bool answers_beside : {true, false}) {
        if (!answers_beside && run_end == fi + 1) continue;
        if (!emit(k, answers_beside)) continue;
        any = true;
        const double h = height();
        if (h < best - kFitSlack) {
          best = h;
          best_k = k;
          best_beside = answers_beside;
        }
      }
      if (!any) break;
    }
    std::size_t best_split = 0;
    if (allow_side_ && fi > first && run_end > fi + 1) {
      const RichText& text = std::get<Paragraph>(blocks[fi - 1]).text;
      if (text.find('\n') == RichText::npos) source = wrap_source(text);
      // From the shortest rest up: a longer one only makes the column taller, so once it no
      // longer fits beside the figure, stop.
      double previous = 0;
      for (std::size_t split = source.size() < 3 ? 0 : source.size() - 2; split >= 1; --split) {
        if (!emit(1, true, split)) break;  // the rest too tall for the column
        const double h = height();
        // Lines move from above the figure into the room beside it until the column outgrows
        // the figure; past that the whole only grows.
        if (previous > 0 && h > previous + kFitSlack) break;
        previous = h;
        if (h < best - kFitSlack) {
          best = h;
          best_k = 1;
          best_beside = true;
          best_split = split;
        }
      }
    }
    side_used_ = side_used_ || best_k > 0;
    measuring_ = false;
    return *emit(best_k, best_beside, best_split);
  }

  // A run of fields or a key's answer lines, in the text column.
  void emit_answers(int si, const std::vector<Block>& blocks, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      const int b = static_cast<int>(i);
      if (const auto* field = std::get_if<AnswerField>(&blocks[i])) {
        if (i == from) field_column_ = field_prompt_column(blocks, i);
        answer_field(si, b, *field, i > from);
      } else {
        if (i == from) key_column_ = key_prompt_column(blocks, i);
        answer_line(si, b, std::get<AnswerLine>(blocks[i]), i > from);
      }
    }
  }

  void heading(int si, int bi, const Heading& h) {
    const bool major = h.level <= 1;
    const double size = major ? s_.heading1_size : s_.heading2_size;
    const double line = size * s_.line_height;
    Atom a = new_atom();
    a.section = si;
    a.block = bi;
    a.space_before = major ? s_.heading1_space : s_.heading2_space;
    double y = 0;
    for (auto& runs : wrap_rich_text(h.text, size, width_, Weight::bold)) {
      a.content.text(std::move(runs), left_, y + size * kBaseline, size);
      y += line;
    }
    a.height = y;
    push(std::move(a));
    after_heading_ = true;
  }

  // A plain paragraph gives one atom per line, breakable but never leaving a single line on
  // either side of a break; an emphasised one is one atom on its shade.
  void paragraph(int si, int bi, const RichText& text, bool emphasis) {
    const double size = s_.body_size;
    if (emphasis) {
      const double pad = s_.shade_padding;
      const auto& lines = wrap(text, size, width_ - 2 * pad);
      Atom a = new_atom();
      a.section = si;
      a.block = bi;
      a.space_before = s_.block_space;
      a.height = static_cast<double>(lines.size()) * body_line_ + 2 * pad;
      a.content.box({{left_, 0, width_, a.height}, BoxKind::shade, {}, {}});
      double y = pad;
      for (const auto& runs : lines) {
        a.content.text(runs, left_ + pad, y + size * kBaseline, size);
        y += body_line_;
      }
      push(std::move(a));
      return;
    }
    // An option only measured, outside a column, needs the lines' number and nothing of them.
    const auto* lines = measuring_ && !in_column_ ? nullptr : &wrap(text, size, width_);
    line_atoms(si, bi, lines ? lines->size() : line_count(text, size, width_), lines);
  }

  // A plain paragraph's `n` lines as atoms; set from `lines` when given.
  void line_atoms(int si, int bi, std::size_t n, const std::vector<std::vector<TextRun>>* lines) {
    const double size = s_.body_size;
    for (std::size_t i = 0; i < n; ++i) {
      Atom a = new_atom();
      a.section = si;
      a.block = bi;
      a.height = body_line_;
      if (i == 0) {
        a.space_before = s_.block_space;
      } else {
        a.break_before = i >= 2 && n - i >= 2;  // no orphan, no widow
      }
      if (lines) a.content.text((*lines)[i], left_, size * kBaseline, size);
      push(std::move(a));
    }
  }

  // A figure's size at most `w` wide and figure_max_height of the page high.
  std::pair<double, double> figure_size(const Figure& f, double w) {
    // remembered, like wrap: the options for a figure ask its size at the same widths
    const std::pair<const Scene*, double> key{&f.scene, w};
    if (auto it = figure_sizes_.find(key); it != figure_sizes_.end()) return it->second;
    return figure_sizes_[key] = measure_figure(f, w);
  }
  std::pair<double, double> measure_figure(const Figure& f, double w) const {
    double h = scene_height(f.scene, w);
    const double max_h = (bottom_ - top_) * s_.figure_max_height;
    // The panels' height is proportional to the width, the captions' is not: a few narrowings
    // bring the whole under max_h.
    for (int i = 0; i < 8 && h > max_h; ++i) {
      w *= max_h / h;
      h = scene_height(f.scene, w);
    }
    return {w, h};
  }

  // Where the run of answer fields, or of a key's answer lines, that starts at `from` ends
  // (`from` itself when there is none).
  static std::size_t answers_run_end(const std::vector<Block>& blocks, std::size_t from) {
    if (from >= blocks.size()) return from;
    const bool fields = std::holds_alternative<AnswerField>(blocks[from]);
    if (!fields && !std::holds_alternative<AnswerLine>(blocks[from])) return from;
    std::size_t end = from;
    while (end < blocks.size() && (fields ? std::holds_alternative<AnswerField>(blocks[end])
                                          : std::holds_alternative<AnswerLine>(blocks[end])))
      ++end;
    return end;
  }

  // The figure on the left and the fields (or the key's answers) that follow it in a column on
  // its right, as one atom: half the paper of a figure above its fields, and the student writes
  // beside what they read. Tried with the column at its natural width, then wider (the figure
  // narrower, never below figure_min_share of the text width); false, with nothing pushed, when
  // the fields do not fit the column or would make the pair taller than a figure may be.
  bool beside(int si, int bi, const Figure& f, bool follows_paragraph, const std::vector<Block>& blocks,
              const std::vector<std::size_t>& side_blocks, bool natural_only,
              const std::optional<RichText>& first_text = std::nullopt) {
    const double full_left = left_, full_right = right_, full_width = width_;
    const double natural = figure_size(f, full_width * std::clamp(f.width_fraction, 0.05, 1.0)).first;
    const double max_h = (bottom_ - top_) * s_.figure_max_height;
    for (double column : {full_width - kSideGap - natural, full_width * 0.45, full_width * 0.5}) {
      const double figure_w = std::min(natural, full_width - kSideGap - column);
      if (natural_only && figure_w < natural - kFitSlack) break;
      // (a figure its height already narrows below that share is not narrowed further)
      if (figure_w < std::min(natural, full_width * s_.figure_min_share) - kFitSlack) break;
      // Panels side by side (a world frame and a canonical one) share the figure's width: one
      // narrowed for a column would leave each a few centimetres wide, so it keeps its width
      // and the answers go under it when they do not fit beside it.
      if (f.scene.panels.size() > 1 && figure_w < natural - kFitSlack) break;
      // The column's atoms, made by the usual code with the geometry narrowed to the column.
      const std::size_t mark = atoms_.size();
      const bool heading_flag = after_heading_, figure_flag = after_figure_;
      left_ = full_left + figure_w + kSideGap;
      width_ = full_right - left_;
      // A narrow column keeps its boxes whole and wraps its long prompts instead.
      prompt_share_ = kSidePromptShare;
      in_column_ = true;
      for (std::size_t n = 0; n < side_blocks.size(); ++n) {
        const std::size_t i = side_blocks[n];
        const int b = static_cast<int>(i);
        const bool run_start = n == 0 || side_blocks[n - 1] + 1 != i || std::holds_alternative<Paragraph>(blocks[i - 1]);
        if (const auto* p = std::get_if<Paragraph>(&blocks[i])) {
          paragraph(si, b, n == 0 && first_text ? *first_text : p->text, p->emphasis);
        } else if (const auto* field = std::get_if<AnswerField>(&blocks[i])) {
          if (run_start) field_column_ = field_prompt_column(blocks, i);
          answer_field(si, b, *field, !run_start);
        } else {
          if (run_start) key_column_ = key_prompt_column(blocks, i);
          answer_line(si, b, std::get<AnswerLine>(blocks[i]), !run_start);
        }
      }
      const double column_left = left_;
      left_ = full_left;
      width_ = full_width;
      prompt_share_ = s_.prompt_column_max;
      in_column_ = false;
      std::vector<Atom> side(std::make_move_iterator(atoms_.begin() + static_cast<std::ptrdiff_t>(mark)),
                             std::make_move_iterator(atoms_.end()));
      atoms_.resize(mark);
      after_heading_ = heading_flag;
      after_figure_ = figure_flag;

      double height = 0;
      bool fits = true;
      for (std::size_t k = 0; k < side.size(); ++k) {
        height += (k > 0 ? side[k].space_before : 0) + side[k].height;
        // Everything left of the question id (the one muted text of a row), set flush right.
        const Fragment& content = side[k].content;
        const double room = std::min(right_, content.muted_left - kIdGap / 2);
        fits = fits && content.box_right_edge <= room + kFitSlack && content.text_right_edge <= room + kFitSlack;
      }
      // A value wrapped to fit the column is worse than the answers under the figure.
      for (const Atom& atom : side) fits = fits && !atom.wrapped;
      if (!fits) continue;
      const auto [w, h] = figure_size(f, figure_w);
      if (height > std::max(h, max_h)) return false;  // a wider column would not be shorter by much

      Atom a = new_atom();
      a.section = si;
      a.block = bi;
      a.space_before = s_.figure_space;
      a.break_before = !follows_paragraph;
      a.height = std::max(h, height);
      a.content.figures.push_back({{full_left, 0, w, h}, &f.scene});
      double y = 0;
      for (std::size_t k = 0; k < side.size(); ++k) {
        if (k > 0) y += side[k].space_before;
        if (!a.side_blocks.empty() && a.side_blocks.back().block == side[k].block)
          a.side_blocks.back().rect.height = y + side[k].height - a.side_blocks.back().rect.y;
        else
          a.side_blocks.push_back({{column_left, y, right_ - column_left, side[k].height}, si, side[k].block});
        a.content.append(std::move(side[k].content), y);
        y += side[k].height;
      }
      push(std::move(a));
      after_figure_ = true;
      return true;
    }
    return false;
  }

  void figure(int si, int bi, const Figure& f, bool follows_paragraph) {
    const auto [w, h] = figure_size(f, width_ * std::clamp(f.width_fraction, 0.05, 1.0));
    Atom a = new_atom();
    a.section = si;
    a.block = bi;
    a.space_before = s_.figure_space;
    a.height = h;
    a.break_before = !follows_paragraph;
    a.content.figures.push_back({{left_ + (width_ - w) / 2, 0, w, h}, &f.scene});
    push(std::move(a));
    after_figure_ = true;
  }

  // The prompt column shared by a run of consecutive fields, so that their boxes line up.
  // The prompt columns depend on the run and the column's width only: remembered.
  double field_prompt_column(const std::vector<Block>& blocks, std::size_t from) {
    const RowKey key{&blocks[from], 0, bits(width_), bits(prompt_share_), false, false};
    if (auto it = prompt_columns_.find(key); it != prompt_columns_.end()) return it->second;
    return prompt_columns_[key] = measure_field_prompt_column(blocks, from);
  }
  double key_prompt_column(const std::vector<Block>& blocks, std::size_t from) {
    const RowKey key{&blocks[from], 0, bits(width_), 0, true, false};
    if (auto it = prompt_columns_.find(key); it != prompt_columns_.end()) return it->second;
    return prompt_columns_[key] = measure_key_prompt_column(blocks, from);
  }
  double measure_field_prompt_column(const std::vector<Block>& blocks, std::size_t from) const {
    double widest = 0;
    // What the run's boxes need right of the prompts: a point's "( □ ; □ )", a number's box, a
    // single tick option (options wrap to more rows), and the question id at the right edge.
    double body = 0;
    const double size = s_.body_size;
    using K = AnswerField::Kind;
    for (std::size_t i = from; i < blocks.size(); ++i) {
      const auto* f = std::get_if<AnswerField>(&blocks[i]);
      if (!f) break;
      widest = std::max(widest, text_width(f->prompt, size));
      const double id = f->question_id.empty() ? 0 : text_width(f->question_id, s_.id_size) + kIdGap;
      double need = s_.number_box_width;
      if (f->kind == K::point || f->kind == K::point3) {
        const int n = f->kind == K::point3 ? 3 : 2;
        const double box = f->kind == K::point3 ? s_.point3_box_width : s_.point_box_width;
        need = text_width("(", size) + text_width(")", size) + (n - 1) * text_width(";", size) +
               n * box + 2 * n * kBoxGap;
      } else if (f->kind != K::number) {
        need = 0;
        for (const auto& c : f->choices) need = std::max(need, s_.tick_size + kTickGap + text_width(c, size));
        if (f->kind == K::boolean)
          for (const auto& w : {doc_.words.yes, doc_.words.no})
            need = std::max(need, s_.tick_size + kTickGap + text_width(w, size));
      }
      body = std::max(body, need + id);
    }
    // The prompts take what the boxes leave, and at least their usual share: a narrow column
    // beside a figure no longer wraps "If they do not intersect, why?" over four lines when the
    // boxes leave room for two.
    const double room = std::max(width_ * prompt_share_, width_ - body - kFitSlack);
    return std::min(widest + kPromptGap, room);
  }

  double measure_key_prompt_column(const std::vector<Block>& blocks, std::size_t from) const {
    double widest = 0;
    for (std::size_t i = from; i < blocks.size(); ++i) {
      const auto* l = std::get_if<AnswerLine>(&blocks[i]);
      if (!l) break;
      widest = std::max(widest, text_width(l->prompt, s_.body_size));
    }
    return std::clamp(widest + kPromptGap, s_.key_prompt_column_min, width_ * s_.key_prompt_column_max);
  }

  void answer_field(int si, int bi, const AnswerField& f, bool follows_field) {
    const RowKey key = row_key(&f, field_column_, follows_field);
    if (replay(key)) return;
    const double size = s_.body_size;
    Atom a = new_atom();
    a.section = si;
    a.block = bi;
    a.space_before = follows_field ? s_.row_space : s_.block_space;
    a.break_before = !follows_field;  // a run of fields stays whole where a page holds it

    auto id = plain(f.question_id);
    const double id_w = f.question_id.empty() ? 0 : text_width(id, s_.id_size);
    const double limit = right_ - (id_w > 0 ? id_w + kIdGap : 0);
    const double x0 = left_ + field_column_;

    using K = AnswerField::Kind;
    const bool ticks = f.kind == K::choice || f.kind == K::faces || f.kind == K::boolean;
    const double row_h = ticks ? s_.tick_row_height : s_.field_box_height;
    const double baseline = row_h / 2 + size * kCentredBaseline;
    double body_h = row_h;

    if (!ticks) {
      const double bh = s_.field_box_height;
      auto box = [&](double x, double w, std::string value) {
        a.content.box({{x, 0, w, bh}, BoxKind::answer, f.question_id, std::move(value)});
      };
      auto glyph = [&](const char* s, double x) {
        auto runs = plain(s);
        const double w = text_width(runs, size);
        a.content.text(std::move(runs), x, baseline, size);
        return x + w;
      };
      if (f.kind == K::number) {
        box(x0, s_.number_box_width, {});
      } else {
        const bool three = f.kind == K::point3;
        const double w = three ? s_.point3_box_width : s_.point_box_width;
        static constexpr const char* kAxes[] = {"x", "y", "z"};
        double x = glyph("(", x0) + kBoxGap;
        for (int k = 0; k < (three ? 3 : 2); ++k) {
          if (k > 0) x = glyph(";", x + kBoxGap) + kBoxGap;
          box(x, w, kAxes[k]);
          x += w;
        }
        glyph(")", x + kBoxGap);
      }
    }

    // The prompt, left of the boxes, wrapped if wider than its column. A question asked as a
    // question ("Is A inside the ellipse?") would stand in a thin column of words beside its
    // ticks: it reads better, and takes less height, on lines of its own above them.
    const auto* prompt_lines = &wrap(f.prompt, size, field_column_ - kPromptGap);
    bool prompt_above = false;
    if (ticks && prompt_lines->size() > 2) {
      const auto& wide = wrap(f.prompt, size, limit - left_);
      if (wide.size() < prompt_lines->size()) {
        prompt_lines = &wide;
        prompt_above = true;
      }
    }
    const double ticks_top = prompt_above ? static_cast<double>(prompt_lines->size()) * body_line_ : 0;

    if (ticks) {
      std::vector<std::pair<std::string, std::string>> options;  // (printed, value)
      if (f.kind == K::boolean) {
        options = {{doc_.words.yes, "true"}, {doc_.words.no, "false"}};
      } else {
        for (const auto& c : f.choices) options.emplace_back(c, c);
      }
      // The options on as few rows as fit, in aligned columns: six faces become two rows of
      // three rather than five and a lonely one. A last choice set apart ("none" after the
      // sides) gets a row of its own.
      std::vector<std::vector<TextRun>> labels;
      std::vector<double> widths;
      for (const auto& o : options) {
        labels.push_back(parse_rich_text(o.first));
        widths.push_back(s_.tick_size + kTickGap + text_width(labels.back(), size));
      }
      const std::size_t n = options.size();
      const std::size_t grid = f.last_choice_apart && n > 1 ? n - 1 : n;
      std::size_t per_row = grid;
      std::vector<double> columns;
      for (std::size_t rows = 1; rows <= grid; ++rows) {
        per_row = (grid + rows - 1) / rows;
        columns.assign(per_row, 0);
        for (std::size_t i = 0; i < grid; ++i) columns[i % per_row] = std::max(columns[i % per_row], widths[i]);
        double total = kOptionGap * static_cast<double>(per_row - 1);
        for (double c : columns) total += c;
        if (x0 + total <= limit + kFitSlack) break;
      }
      const std::size_t grid_rows = grid == 0 ? 1 : (grid + per_row - 1) / per_row;
      for (std::size_t i = 0; i < n; ++i) {
        double x = x0;
        std::size_t row = grid_rows;  // the option after the grid
        if (i < grid) {
          for (std::size_t c = 0; c < i % per_row; ++c) x += columns[c] + kOptionGap;
          row = i / per_row;
        }
        const double top = ticks_top + static_cast<double>(row) * s_.tick_row_height;
        const double ty = top + (s_.tick_row_height - s_.tick_size) / 2;
        a.content.box({{x, ty, s_.tick_size, s_.tick_size}, BoxKind::tick, f.question_id,
                                   std::move(options[i].second)});
        a.content.text(std::move(labels[i]), x + s_.tick_size + kTickGap, top + baseline, size);
      }
      const std::size_t rows = grid_rows + (grid < n ? 1 : 0);
      body_h = ticks_top + static_cast<double>(rows) * s_.tick_row_height;
    }

    double prompt_h = 0;
    double y = prompt_above ? size * kBaseline : baseline;
    for (const auto& runs : *prompt_lines) {
      a.content.text(runs, left_, y, size);
      prompt_h = y + size * (s_.line_height - kBaseline);
      y += body_line_;
    }
    if (id_w > 0) a.content.text_right(std::move(id), right_, prompt_above ? size * kBaseline : baseline, s_.id_size, Ink::muted);
    a.height = std::max(body_h, prompt_h);
    remember(key, a);
    push(std::move(a));
  }

  void answer_line(int si, int bi, const AnswerLine& l, bool follows_line) {
    const RowKey key = row_key(&l, key_column_, follows_line);
    if (replay(key)) return;
    const double size = s_.body_size;
    const double pad = s_.key_row_padding;
    Atom a = new_atom();
    a.section = si;
    a.block = bi;
    a.space_before = follows_line ? 0 : s_.block_space;
    a.break_before = !follows_line;  // so does a key's table

    auto id = plain(l.question_id);
    const double id_w = l.question_id.empty() ? 0 : text_width(id, s_.id_size);
    const double id_room = id_w > 0 ? id_w + kIdGap : 0;
    double answer_x = left_ + key_column_;
    double prompt_w = key_column_ - kPromptGap;
    const auto* answer = &wrap(l.answer, size, right_ - answer_x - id_room);
    const std::size_t own_lines = line_count(l.answer, size, kUnbounded);
    bool stacked = false;
    if (answer->size() > own_lines) {
      // Prompt on its line, the answer under it with the column's whole width.
      answer_x = left_ + kStackIndent;
      const auto& under = wrap(l.answer, size, right_ - answer_x - id_room);
      if (under.size() < answer->size()) {
        answer = &under;
        prompt_w = right_ - left_ - id_room;
        stacked = true;
      } else {
        answer_x = left_ + key_column_;
      }
    }
    a.wrapped = answer->size() > own_lines;

    double y = pad + size * kBaseline;
    std::size_t rows = 0;
    for (const auto& runs : wrap(l.prompt, size, prompt_w)) {
      a.content.text(runs, left_, y + static_cast<double>(rows++) * body_line_, size);
    }
    const std::size_t first_answer_row = stacked ? std::max<std::size_t>(rows, 1) : 0;
    std::size_t answer_rows = first_answer_row;
    for (const auto& runs : *answer) {
      a.content.text(runs, answer_x, y + static_cast<double>(answer_rows++) * body_line_,
                     size, Ink::answer);
    }
    if (id_w > 0) a.content.text_right(std::move(id), right_, y, s_.id_size, Ink::muted);
    a.height = static_cast<double>(std::max<std::size_t>({rows, answer_rows, 1})) * body_line_ + 2 * pad;
    // A table: a rule above the first row and under every row.
    if (!follows_line) a.content.rules.push_back({{left_, 0}, {right_, 0}, 0.4, Ink::muted});
    a.content.rules.push_back({{left_, a.height}, {right_, a.height}, 0.4, Ink::muted});
    remember(key, a);
    push(std::move(a));
  }

  // ---- placing: atoms → pages ------------------------------------------------------------

  void new_page() {
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

  // Height from the start of atoms[from] to the end of atoms[to - 1], on a page already begun.
  double span(std::size_t from, std::size_t to) const {
    double h = 0;
    for (std::size_t i = from; i < to; ++i) h += (i > from ? atoms_[i].space_before : 0) + atoms_[i].height;
    return h;
  }

  bool fits(double h) const { return y_ + h <= bottom_ + kFitSlack; }

  // The atoms on pages. A section whose statement was set beside its figure and whose opening
  // does not fit in what is left of a page has two ways to go (see open_section): whole to the
  // next page, or laid out again with the statement above the figure, which may end this page.
  // Taking the second every time, as one page alone would choose, can leave a sheet one page
  // longer than it needs: a statement ends a page whose next figure does not fit. So every
  // combination of these choices is tried on the atoms' heights alone (a sheet has at most
  // seven such sections), and the one that gives the fewest pages, none of them but the last
  // less than half full, is set; on a tie, the page-by-page choice.
  void flow() {
    choose_fallbacks();
    run_flow();
  }

  // The sections with a fallback, each a bit of a choice mask (set: take the fallback when its
  // opening does not fit), and the fallback's atoms, built once in full.
  void choose_fallbacks() {
    fallback_mask_ = ~std::uint32_t{0};
    if (fallback_.empty() || fallback_.size() > kMaxFallbackChoices) return;
    std::uint32_t bit = 0;
    for (const auto& [si, start] : fallback_) {
      fallback_bit_[si] = bit++;
      const auto& built = fallback_atoms_.emplace(si, fallback(si, start)).first->second;
      fallback_shapes_.emplace(si, geometry(built));
    }
    const std::vector<Atom> shapes = geometry(atoms_);
    const std::uint32_t all = (std::uint32_t{1} << bit) - 1;
    std::size_t best_pages = trial_pages(all, shapes);
    std::uint32_t best = all;
    for (std::uint32_t mask = all; mask-- > 0;) {
      const std::size_t pages = trial_pages(mask, shapes);
      const bool filled = std::all_of(dry_fills_.begin(), dry_fills_.end(), [](double f) { return f >= kMinPageFill; });
      if (pages < best_pages && filled) {
        best_pages = pages;
        best = mask;
      }
    }
    fallback_mask_ = best;
  }

  // How many pages the atoms take with this choice mask (dry_fills_: how full each page but the
  // last ends), placed from a copy of `shapes`, the atoms' geometry (placing edits the atoms).
  std::size_t trial_pages(std::uint32_t mask, const std::vector<Atom>& shapes) {
    std::vector<Atom> copies = shapes;
    std::swap(atoms_, copies);
    fallback_mask_ = mask;
    dry_ = true;
    dry_pages_ = 0;
    dry_fills_.clear();
    run_flow();
    dry_ = false;
    std::swap(atoms_, copies);
    return dry_pages_;
  }

  // An atom without its content: what placing it needs (a figure's presence, for open_section).
  static Atom geometry(const Atom& a) {
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
    g.content.keep_texts = false;
    g.content.figures = a.content.figures;
    return g;
  }
  static std::vector<Atom> geometry(const std::vector<Atom>& atoms) {
    std::vector<Atom> g;
    g.reserve(atoms.size());
    for (const Atom& a : atoms) g.push_back(geometry(a));
    return g;
  }

  void run_flow() {
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
  void open_section(std::size_t i, double space) {
    std::size_t end = i + 1;
    while (end < atoms_.size() && !atoms_[end].section_start) ++end;
    // A section whose statement was set beside its figure is one tall group: when it does not
    // fit here and would leave much of this page empty, it is laid out as the statement above
    // the figure instead, which may end this page between the two.
    if (auto alt = fallback_.find(atoms_[i].section); alt != fallback_.end()) {
      const bool little_left = bottom_ - y_ <= kMaxOpeningWaste * (bottom_ - top_);
      std::size_t head_end = std::min(i + atoms_[i].head_atoms, end);
      const auto bit = fallback_bit_.find(alt->first);
      const bool chosen = bit == fallback_bit_.end() || ((fallback_mask_ >> bit->second) & 1) != 0;
      if (!fits(space + span(i, head_end)) && !little_left && chosen) {
        std::vector<Atom> other;
        if (auto built = fallback_atoms_.find(alt->first); built == fallback_atoms_.end()) {
          other = fallback(alt->first, alt->second);
        } else if (dry_) {
          other = fallback_shapes_.at(alt->first);
        } else {
          other = std::move(built->second);
        }
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
    if (head <= bottom_ - top_ + kFitSlack && little_left) {
      new_page();
      return;
    }
    const std::size_t figure = i + atom.head_atoms - 1;
    if (atom.head_atoms > 1 && figure < end && !atoms_[figure].content.figures.empty() &&
        !atoms_[figure].follows_heading && fits(space + span(i, figure)))
      atoms_[figure].break_before = true;
  }

  void place(Atom& atom) {
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

  // Course and title on the left, sheet id and "page i/n" on the right, a rule under them.
  void header(LaidOutPage& page) {
    page.count = static_cast<int>(pages_.size());
    const double top = s_.margin_top;
    const double big = s_.header_title_size, small = s_.header_small_size;
    const double first = top + big * kBaseline;
    const double second = first + small * s_.line_height + 2;

    Fragment f;
    auto id = plain(doc_.sheet_id, true);
    auto count = plain(fmt::format("{} {}/{}", doc_.words.page, page.number, page.count));
    const double right_w = std::max(text_width(id, big), text_width(count, small));
    f.text_right(std::move(id), right_, first, big, Ink::text);
    f.text_right(std::move(count), right_, second, small, Ink::muted);

    // A long title or course is set smaller rather than run into the right column.
    const double room = width_ - right_w - kHeaderGap;
    auto fitted = [&](std::vector<TextRun> runs, double size) {
      const double w = text_width(runs, size);
      return std::pair{std::move(runs), w > room && w > 0 ? size * room / w : size};
    };
    auto [title, title_size] = fitted(plain(doc_.title, true), big);
    auto [course, course_size] = fitted(plain(doc_.course), small);
    f.text(std::move(title), left_, first, title_size);
    f.text(std::move(course), left_, second, course_size, Ink::muted);
    const double rule_y = top + s_.header_height;
    f.rules.push_back({{left_, rule_y}, {right_, rule_y}, 0.6, Ink::muted});

    // The header goes first, so that it is also first in every list of the page.
    LaidOutPage head;
    f.move_into(head, 0);
    page.texts.insert(page.texts.begin(), head.texts.begin(), head.texts.end());
    page.rules.insert(page.rules.begin(), head.rules.begin(), head.rules.end());
    page.blocks.insert(page.blocks.begin(), PlacedBlock{{left_, top, width_, s_.header_height}, -1, -1});
  }

  const Document& doc_;
  const LayoutStyle& s_;
  // The text column; `beside` narrows left_ and width_ for the fields set beside a figure.
  double left_;
  const double right_;
  double width_;
  const double top_, bottom_, body_line_;
  double prompt_share_ = s_.prompt_column_max;  // of width_, at most, for the fields' prompts

  std::vector<Atom> atoms_;
  bool after_heading_ = false;
  bool after_figure_ = false;
  std::size_t section_begin_ = 0;
  std::vector<Mark> marks_;  // the state before each block of the section being measured
  bool allow_side_ = true, side_used_ = false;
  std::map<int, Mark> fallback_;  // the sections with paragraphs beside a figure: the state at their start
  std::map<int, std::uint32_t> fallback_bit_;    // their bit in a choice mask
  std::map<int, std::vector<Atom>> fallback_atoms_;  // their fallback, built once
  std::map<int, std::vector<Atom>> fallback_shapes_;  // and its geometry, for the trials
  std::uint32_t fallback_mask_ = ~std::uint32_t{0};  // set: the fallback is taken (see flow)
  bool dry_ = false;                // placing copies only to count pages (see trial_pages)
  std::size_t dry_pages_ = 0;
  std::vector<double> dry_fills_;   // a trial's pages but the last: the share of the text height used
  std::unordered_map<WrapKey, Wrapped, WrapHash, std::equal_to<>> wrapped_;
  std::unordered_map<WrapKey, std::vector<std::string>, WrapHash, std::equal_to<>> sources_;
  std::unordered_map<WrapKey, MeasuredText, WrapHash, std::equal_to<>> measured_;
  bool measuring_ = false;  // building an option only to measure it
  std::unordered_map<RowKey, Atom, RowHash> measured_rows_;
  std::unordered_map<RowKey, double, RowHash> prompt_columns_;
  bool in_column_ = false;  // building the column beside a figure
  std::map<std::pair<const Scene*, double>, std::pair<double, double>> figure_sizes_;  // by section: its atoms without paragraphs beside figures
  double field_column_ = 0, key_column_ = 0;

  std::vector<LaidOutPage> pages_;
  double y_ = 0;
  bool empty_ = true;
};

}  // namespace

std::vector<LaidOutPage> layout_document(const Document& doc, const LayoutStyle& style) {
  std::vector<LaidOutPage> pages = Builder(doc, style).run();
  const auto budget = static_cast<std::size_t>(std::max(doc.page_budget, 0));
  if (budget == 0 || pages.size() <= budget || !(style.figure_height_step > 0)) return pages;
  // The caps in whole steps from the first, so that every platform tries the same doubles.
  for (int step = 1;; ++step) {
    LayoutStyle lower = style;
    lower.figure_max_height = style.figure_max_height - step * style.figure_height_step;
    if (lower.figure_max_height < style.figure_min_height - kFitSlack) break;
    std::vector<LaidOutPage> fewer = Builder(doc, lower).run();
    if (fewer.size() <= budget) return fewer;
  }
  return pages;
}

}  // namespace epure::render
