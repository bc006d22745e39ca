#include "render/section_atoms.h"

#include <algorithm>
#include <cassert>
#include <iterator>
#include <string>
#include <variant>

#include "render/page_furniture.h"
#include "render/scene_painter.h"

namespace epure::render::layout_detail {
namespace {

// Paragraphs go beside a figure when that makes the exercise shorter by more than this many
// lines: half a line is enough to be worth the narrower column (a whole line cost sheets pages).
constexpr double kSideSaving = 0.5;
// At most this many paragraphs before a figure are tried in the column beside it.
constexpr std::size_t kMaxSideParagraphs = 8;
// Of the column beside a figure, at most this share for the fields' prompts.
constexpr double kSidePromptShare = 0.3;
// A course's section is 10 to 50 atoms (a line of a paragraph, a row of fields or of a key's
// table, a figure with its neighbours).
constexpr std::size_t kSectionAtoms = 48;

// Whether an atom of a column beside a figure, ending `right`, fits it: everything left of the
// question id (the one muted text of a row, set flush right), and no value wrapped to fit the
// column (worse than the answers under the figure).
bool fits_column(double right, double box_right, double text_right, double muted_left, bool wrapped) {
  const double room = std::min(right, muted_left - kIdGap / 2);
  return box_right <= room + kFitSlack && text_right <= room + kFitSlack && !wrapped;
}

}  // namespace

std::size_t RowHash::operator()(const RowKey& k) const {
  std::size_t h = std::hash<const void*>{}(k.block);
  for (std::uint64_t v : {k.left, k.width, k.column, std::uint64_t{k.follows} * 2 + k.in_column}) h = hash_combine(h, v);
  return h;
}

SectionAtoms::SectionAtoms(const Document& doc, const LayoutStyle& style, LayoutMemo& memo)
    : doc_(doc),
      s_(style),
      memo_(memo),
      text_(memo.text),
      rows_(RowShapes::for_document(doc, style)),
      area_(doc, style),
      left_(area_.left),
      right_(area_.right),
      width_(area_.width),
      top_(area_.top),
      bottom_(area_.bottom),
      body_line_(style.body_size * style.line_height),
      prompt_share_(style.prompt_column_max) {}

std::vector<Atom> SectionAtoms::opening(bool shapes_only) {
  atoms_.clear();
  after_heading_ = after_figure_ = false;
  shapes_ = shapes_only;
  if (doc_.student_fields) {
    Atom row = name_row(doc_, s_, area_);
    if (shapes_only) row.content = Fragment{};
    push(std::move(row));
  }
  if (!doc_.header_note.empty()) paragraph(-1, -1, doc_.header_note, false);
  return std::move(atoms_);
}

SectionAtoms::Built SectionAtoms::section(int si, double scale, bool shapes_only, bool allow_side) {
  atoms_.clear();
  // (the last section's atoms were moved out: room for a usual section's, not grown from one
  // atom by doubling, each growth moving every atom)
  atoms_.reserve(kSectionAtoms);
  after_heading_ = after_figure_ = false;
  scale_ = scale;
  shapes_ = shapes_only;
  allow_side_ = allow_side;
  side_used_ = false;
  build_section(si);
  return {std::move(atoms_), side_used_};
}

// A row of fields or answers is the same atom each time the same block is measured with the
// same geometry: the options for a figure and its neighbours, and the page budget's trials,
// measure the same rows many times. Their shapes are remembered; true when the row was pushed
// again.
RowKey SectionAtoms::row_key(const void* block, double column, bool follows) const {
  return {block, bits(left_), bits(width_), bits(column), follows, in_column_};
}

bool SectionAtoms::replay(const RowKey& key) {
  if (!shapes_) return false;
  auto it = memo_.rows.find(key);
  if (it == memo_.rows.end()) return false;
  if (tally_) {
    fold(it->second);  // (no copy of the row to fold it)
  } else {
    push(Atom(it->second));
  }
  return true;
}

bool SectionAtoms::reuse(const Atom* shared, const RowKey& key, int si, int bi) {
  if (!shared) return false;
  Atom a(*shared);
  a.section = si;
  a.block = bi;
  remember(key, a);
  push(std::move(a));
  return true;
}

void SectionAtoms::remember(const RowKey& key, const Atom& a) {
  if (shapes_) memo_.rows.emplace(key, a);
}

// An atom for the current mode: a shape keeps no content; a column's atoms note how far their
// texts reach.
Atom SectionAtoms::new_atom() const {
  Atom a;
  a.content.keep_texts = !shapes_;
  a.content.track_extents = in_column_;
  return a;
}

void SectionAtoms::push(Atom&& atom) {
  if (tally_) {
    fold(atom);
    return;
  }
  if (after_heading_) atom.break_before = false;  // a heading never ends a page
  atom.follows_heading = after_heading_;
  if (after_figure_) atom.space_before = std::max(atom.space_before, s_.figure_space);
  after_heading_ = false;
  after_figure_ = false;
  atoms_.push_back(std::move(atom));
}

void SectionAtoms::fold(const Atom& atom) {
  const Fragment& c = atom.content;
  fold(atom.space_before, atom.height, c.box_right_edge, c.text_right_edge, c.muted_left, atom.wrapped);
}

void SectionAtoms::fold(double space_before, double height, double box_right, double text_right, double muted_left,
                        bool wrapped) {
  // push()'s space, and span()'s and beside()'s sums
  const double space = after_figure_ ? std::max(space_before, s_.figure_space) : space_before;
  after_heading_ = false;
  after_figure_ = false;
  Tally& t = *tally_;
  t.span += (t.count > 0 ? space : 0) + height;
  if (t.count > 0) t.stacked += space;
  t.stacked += height;
  if (t.count == 0) t.first_space = space;
  ++t.count;
  if (in_column_) t.fits = t.fits && fits_column(right_, box_right, text_right, muted_left, wrapped);
}

void SectionAtoms::undo(const Mark& m) {
  atoms_.resize(m.atoms);
  after_heading_ = m.after_heading;
  after_figure_ = m.after_figure;
  if (tally_) *tally_ = Tally{};
}

void SectionAtoms::build_section(int si) {
  const auto& blocks = doc_.sections[static_cast<std::size_t>(si)].blocks;
  marks_.assign(blocks.size() + 1, Mark{});
  // The statement: from the heading to the first figure, or to the first field or answer.
  std::size_t head_end = 0;
  for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
    const Block& block = blocks[bi];
    const Block* before = bi > 0 ? &blocks[bi - 1] : nullptr;
    const int b = static_cast<int>(bi);
    const bool answers = std::holds_alternative<AnswerField>(block) || std::holds_alternative<AnswerLine>(block);
    if (head_end == 0 && answers) head_end = atoms_.size();
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
  if (!atoms_.empty()) {
    Atom& first = atoms_.front();
    first.section_start = true;
    first.head_atoms = head_end > 0 ? head_end : atoms_.size();
  }
}

// A figure, the run of fields or answers after it, and the plain paragraphs just before it:
// the answers beside the figure when they fit (else under it), and, when that makes the whole
// shorter by more than half a line, the last paragraphs before the figure in the column beside it
// too, above the answers (or with the answers under the figure): a statement read beside the
// figure it describes, a key's last steps beside their construction. The figure keeps the width
// its kind asks for. Every option is measured as a tally (its height, without its atoms); only
// the shortest is built. Returns the index of the atom after the figure's.
std::size_t SectionAtoms::figure_with_neighbours(int si, std::size_t fi, const Figure& f, const std::vector<Block>& blocks) {
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
  const RichText* before_text = follows ? &std::get<Paragraph>(blocks[fi - 1]).text : nullptr;
  const WrappedText* before_lines = nullptr;
  auto emit = [&](std::size_t k, bool answers_beside, std::size_t split = 0) -> std::optional<std::size_t> {
    undo(start);
    for (std::size_t p = first; p < fi - k; ++p) {
      const auto& para = std::get<Paragraph>(blocks[p]);
      paragraph(si, static_cast<int>(p), para.text, para.emphasis);
    }
    std::size_t tail = 0;  // the paragraph's rest, from this word, beside the figure
    if (split > 0) {
      // Its first `split` lines are the paragraph's own first lines, set across the page.
      line_atoms(si, static_cast<int>(fi - 1), *before_lines, split,
                 shapes_ ? nullptr : &text_.wrap(*before_text, s_.body_size, width_));
      tail = before_lines->lines[split].first;
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
    // Fields or answers under the figure stay with it: a key's table with the construction it
    // sums up, a sheet's fields with the figure they are read from.
    if (!(placed && with_answers)) {
      emit_answers(si, blocks, fi + 1, run_end);
      if (run_end > fi + 1 && after_figure < atoms_.size()) atoms_[after_figure].break_before = false;
    }
    return after_figure;
  };
  // The options are measured as tallies, once for a figure at a scale: their heights without
  // their atoms. The best is then built in the section's mode.
  Tally tally;
  const auto height = [&]() { return tally.height(); };
  const auto key = std::tuple{&f, bits(scale_), allow_side_};
  auto known = memo_.options.find(key);
  if (known == memo_.options.end() && scale_ != 1) {
    // At a smaller scale (a page budget's trial), the arrangement chosen at full size, where it
    // still places: the figure narrower, the column beside it only wider. A figure keeps its
    // arrangement as it shrinks, and the options are not measured again for every scale.
    const auto full = memo_.options.find(std::tuple{&f, bits(1.0), allow_side_});
    if (full != memo_.options.end()) {
      const LayoutMemo::Option& o = full->second;
      if (o.split > 0) before_lines = &text_.wrapped(*before_text, s_.body_size, width_);
      const bool shapes = shapes_;
      shapes_ = true;
      tally_ = &tally;
      const bool places = emit(o.beside_paragraphs, o.answers_beside, o.split).has_value();
      tally_ = nullptr;
      shapes_ = shapes;
      if (places) known = memo_.options.emplace(key, o).first;
    }
  }
  if (known == memo_.options.end()) {
    const bool shapes = shapes_;
    shapes_ = true;
    tally_ = &tally;
    LayoutMemo::Option best_option;
    emit(0, false);  // k = 0 always places
    double best = height() - kSideSaving * body_line_;  // the paragraphs beside must save something
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
          best_option = {k, answers_beside, 0};
        }
      }
      if (!any) break;
    }
    if (allow_side_ && fi > first && run_end > fi + 1 && before_text->find('\n') == RichText::npos) {
      before_lines = &text_.wrapped(*before_text, s_.body_size, width_);
      const std::size_t n = before_lines->count();
      // From the shortest rest up: a longer one only makes the column taller, so once it no
      // longer fits beside the figure, stop.
      double previous = 0;
      for (std::size_t split = n < 3 ? 0 : n - 2; split >= 1; --split) {
        if (!emit(1, true, split)) break;  // the rest too tall for the column
        const double h = height();
        // Lines move from above the figure into the room beside it until the column outgrows
        // the figure; past that the whole only grows.
        if (previous > 0 && h > previous + kFitSlack) break;
        previous = h;
        if (h < best - kFitSlack) {
          best = h;
          best_option = {1, true, split};
        }
      }
    }
    tally_ = nullptr;
    shapes_ = shapes;
    known = memo_.options.emplace(key, best_option).first;
  }
  const LayoutMemo::Option& chosen = known->second;
  if (chosen.split > 0) before_lines = &text_.wrapped(*before_text, s_.body_size, width_);
  side_used_ = side_used_ || chosen.beside_paragraphs > 0;
  return *emit(chosen.beside_paragraphs, chosen.answers_beside, chosen.split);
}

// A run of fields or a key's answer lines, in the text column.
void SectionAtoms::emit_answers(int si, const std::vector<Block>& blocks, std::size_t from, std::size_t to) {
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

void SectionAtoms::heading(int si, int bi, const Heading& h) {
  const bool major = h.level <= 1;
  const double size = major ? s_.heading1_size : s_.heading2_size;
  const double line = size * s_.line_height;
  Atom a = new_atom();
  a.section = si;
  a.block = bi;
  a.space_before = major ? s_.heading1_space : s_.heading2_space;
  if (shapes_) {
    a.height = static_cast<double>(text_.wrapped(h.text, size, width_, Weight::bold).count()) * line;
  } else {
    double y = 0;
    for (const auto& runs : text_.wrap(h.text, size, width_, Weight::bold)) {
      a.content.text(runs, left_, y + size * kBaseline, size);
      y += line;
    }
    a.height = y;
  }
  push(std::move(a));
  after_heading_ = true;
}

// A plain paragraph gives one atom per line, a page ending only where a sentence ends (never
// leaving a single line on either side); an emphasised one is one atom on its shade.
void SectionAtoms::paragraph(int si, int bi, const RichText& text, bool emphasis, std::size_t from) {
  const double size = s_.body_size;
  if (emphasis) {
    const double pad = s_.shade_padding;
    const double inner = width_ - 2 * pad;
    Atom a = new_atom();
    a.section = si;
    a.block = bi;
    a.space_before = s_.block_space;
    const WrappedText& wrapped = text_.wrapped(text, size, inner);
    a.height = static_cast<double>(wrapped.count()) * body_line_ + 2 * pad;
    a.content.box({{left_, 0, width_, a.height}, BoxKind::shade, {}, {}});
    if (!shapes_) {
      a.content.track_extents = false;  // the lines' widths are the ones the breaking measured
      double y = pad;
      for (const auto& runs : text_.wrap(text, size, inner)) {
        a.content.text(runs, left_ + pad, y + size * kBaseline, size);
        y += body_line_;
      }
    }
    if (in_column_) a.content.text_right_edge = left_ + pad + wrapped.widest;
    push(std::move(a));
    return;
  }
  const WrappedText& wrapped = text_.wrapped(text, size, width_, Weight::regular, from);
  line_atoms(si, bi, wrapped, wrapped.count(),
             shapes_ ? nullptr : &text_.wrap(text, size, width_, Weight::regular, from));
}

// The first `n` lines of a plain paragraph as atoms; set from `lines` when given (a shape
// without). A page may end before line i only after a sentence's end, with two lines at least on
// either side.
void SectionAtoms::line_atoms(int si, int bi, const WrappedText& wrapped, std::size_t n,
                              const std::vector<std::vector<TextRun>>* lines) {
  const double size = s_.body_size;
  if (tally_) {
    // a line as fold() would read its atom: its space, height and (in a column) its right end
    const Fragment none;  // a line's atom's extents but its text's right end
    for (std::size_t i = 0; i < n; ++i)
      fold(i == 0 ? s_.block_space : 0, body_line_, none.box_right_edge,
           in_column_ ? left_ + wrapped.lines[i].width : none.text_right_edge, none.muted_left, false);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    Atom a = new_atom();
    a.section = si;
    a.block = bi;
    a.height = body_line_;
    if (i == 0) {
      a.space_before = s_.block_space;
    } else {
      a.break_before = i >= 2 && n - i >= 2 && wrapped.ends_sentence[i - 1];
    }
    if (lines) {
      a.content.track_extents = false;  // the line's width is the one the breaking measured
      a.content.text((*lines)[i], left_, size * kBaseline, size);
    }
    if (in_column_) a.content.text_right_edge = left_ + wrapped.lines[i].width;
    push(std::move(a));
  }
}

// A figure's size at most `w` wide and its share of the page (× the section's scale) high.
std::pair<double, double> SectionAtoms::figure_size(const Figure& f, double w) {
  const double max_h = (bottom_ - top_) * s_.figure_max_height * scale_;
  // remembered, like the texts: the options for a figure ask its size at the same widths
  const auto key = std::tuple{&f.scene, bits(w), bits(max_h)};
  if (auto it = memo_.figure_sizes.find(key); it != memo_.figure_sizes.end()) return it->second;
  return memo_.figure_sizes[key] = measure_figure(f, w, max_h);
}

std::pair<double, double> SectionAtoms::measure_figure(const Figure& f, double w, double max_h) const {
  double h = scene_height(f.scene, w);
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
std::size_t SectionAtoms::answers_run_end(const std::vector<Block>& blocks, std::size_t from) {
  if (from >= blocks.size()) return from;
  const bool fields = std::holds_alternative<AnswerField>(blocks[from]);
  if (!fields && !std::holds_alternative<AnswerLine>(blocks[from])) return from;
  std::size_t end = from;
  while (end < blocks.size() && (fields ? std::holds_alternative<AnswerField>(blocks[end])
                                        : std::holds_alternative<AnswerLine>(blocks[end])))
    ++end;
  return end;
}

// The column beside a figure: its atoms made by the usual code with the geometry narrowed to the
// column, tried with the column at its natural width, then wider (the figure narrower, never
// below figure_min_share of the text width); nothing when the fields do not fit the column or
// would make the pair taller than a figure may be. What fits is decided from the atoms' extents,
// which shapes keep, so a shape and the atom built from it choose the same column.
std::optional<SectionAtoms::Column> SectionAtoms::column_beside(int si, const Figure& f,
                                                                const std::vector<Block>& blocks,
                                                                const std::vector<std::size_t>& side_blocks,
                                                                bool natural_only,
                                                                std::size_t first_from) {
  // The width that fits is found as a shape finds it (a tally: the same extents, so the same
  // width), and a column in full is built at that width only, not at the widths that fail first.
  std::optional<std::uint64_t> only;
  if (!shapes_) {
    shapes_ = true;
    const std::optional<Column> measured = column_beside(si, f, blocks, side_blocks, natural_only, first_from);
    shapes_ = false;
    if (!measured) return std::nullopt;
    only = bits(measured->figure_w);
  }
  const double full_left = left_, full_right = right_, full_width = width_;
  const double natural = figure_size(f, full_width * std::clamp(f.width_fraction, 0.05, 1.0) * scale_).first;
  const double max_h = (bottom_ - top_) * s_.figure_max_height;
  for (double column : {full_width - kSideGap - natural, full_width * 0.45, full_width * 0.5}) {
    const double figure_w = std::min(natural, full_width - kSideGap - column);
    if (natural_only && figure_w < natural - kFitSlack) break;
    // (a figure its height already narrows below that share is not narrowed further)
    if (figure_w < std::min(natural, full_width * s_.figure_min_share * scale_) - kFitSlack) break;
    // Panels side by side (a world frame and a canonical one) share the figure's width: one
    // narrowed for a column would leave each a few centimetres wide, so it keeps its width
    // and the answers go under it when they do not fit beside it.
    if (f.scene.panels.size() > 1 && figure_w < natural - kFitSlack) break;
    if (only && bits(figure_w) != *only) continue;
    const Mark before = mark();
    left_ = full_left + figure_w + kSideGap;
    width_ = full_right - left_;
    // A narrow column keeps its boxes whole and wraps its long prompts instead.
    prompt_share_ = kSidePromptShare;
    in_column_ = true;
    // Whether the column's atoms so far fit it (fits_column). The first block that does not fit
    // ends this width's try: the blocks after it would be built only to be dropped. A shape's
    // column is a tally, fold() testing each atom as it comes: a shape keeps only the pair's
    // height.
    Tally column_tally;
    Tally* const outer = tally_;
    if (shapes_) tally_ = &column_tally;
    bool fits = true;
    std::size_t checked = before.atoms;
    for (std::size_t n = 0; n < side_blocks.size() && fits; ++n) {
      const std::size_t i = side_blocks[n];
      const int b = static_cast<int>(i);
      const bool run_start = n == 0 || side_blocks[n - 1] + 1 != i || std::holds_alternative<Paragraph>(blocks[i - 1]);
      if (const auto* p = std::get_if<Paragraph>(&blocks[i])) {
        paragraph(si, b, p->text, p->emphasis, n == 0 ? first_from : 0);
      } else if (const auto* field = std::get_if<AnswerField>(&blocks[i])) {
        if (run_start) field_column_ = field_prompt_column(blocks, i);
        answer_field(si, b, *field, !run_start);
      } else {
        if (run_start) key_column_ = key_prompt_column(blocks, i);
        answer_line(si, b, std::get<AnswerLine>(blocks[i]), !run_start);
      }
      if (shapes_) fits = column_tally.fits;
      for (; checked < atoms_.size(); ++checked) {
        const Fragment& c = atoms_[checked].content;
        fits = fits && fits_column(right_, c.box_right_edge, c.text_right_edge, c.muted_left, atoms_[checked].wrapped);
      }
    }
    const double column_left = left_;
    left_ = full_left;
    width_ = full_width;
    prompt_share_ = s_.prompt_column_max;
    in_column_ = false;
    if (shapes_) {
      tally_ = outer;
      after_heading_ = before.after_heading;
      after_figure_ = before.after_figure;
      if (!fits) continue;
      if (column_tally.span > std::max(figure_size(f, figure_w).second, max_h)) return std::nullopt;
      return Column{figure_w, column_left, {}, column_tally.stacked};
    }
    // Built in full only at the width the shapes found fitting, from the same extents: a column
    // that does not fit it, or is too tall, is the two passes diverging (the column would
    // silently go under the figure).
    assert(fits);
    if (!fits) {
      undo(before);
      continue;
    }
    Column out{figure_w, column_left, {}, 0};
    out.atoms.assign(std::make_move_iterator(atoms_.begin() + static_cast<std::ptrdiff_t>(before.atoms)),
                     std::make_move_iterator(atoms_.end()));
    undo(before);

    double height = 0;
    for (std::size_t k = 0; k < out.atoms.size(); ++k) height += (k > 0 ? out.atoms[k].space_before : 0) + out.atoms[k].height;
    const double tallest = std::max(figure_size(f, figure_w).second, max_h);
    assert(height <= tallest);  // (the shapes' span: the same sums in the same order)
    if (height > tallest) return std::nullopt;  // a wider column would not be shorter by much
    return out;
  }
  assert(shapes_);  // in full, the width the shapes found is always tried
  return std::nullopt;
}

// The figure on the left and the fields (or the key's answers, or paragraphs) that follow it in
// a column on its right, as one atom: half the paper of a figure above its fields, and the
// student writes beside what they read. False, with nothing pushed, when there is no such column.
bool SectionAtoms::beside(int si, int bi, const Figure& f, bool follows_paragraph, const std::vector<Block>& blocks,
                          const std::vector<std::size_t>& side_blocks, bool natural_only,
                          std::size_t first_from) {
  std::optional<Column> column = column_beside(si, f, blocks, side_blocks, natural_only, first_from);
  if (!column) return false;
  const auto [w, h] = figure_size(f, column->figure_w);
  std::vector<Atom>& side = column->atoms;
  Atom a = new_atom();
  a.section = si;
  a.block = bi;
  a.space_before = s_.figure_space;
  a.break_before = !follows_paragraph;
  a.figure = true;
  double y = shapes_ ? column->height : 0;  // a shape's column is a tally, summed as below
  for (std::size_t k = 0; k < side.size(); ++k) {
    if (k > 0) y += side[k].space_before;
    if (!shapes_) {
      if (!a.side_blocks.empty() && a.side_blocks.back().block == side[k].block)
        a.side_blocks.back().rect.height = y + side[k].height - a.side_blocks.back().rect.y;
      else
        a.side_blocks.push_back({{column->left, y, right_ - column->left, side[k].height}, si, side[k].block});
      a.content.append(std::move(side[k].content), y);
    }
    y += side[k].height;
  }
  a.height = std::max(h, y);
  if (!shapes_) a.content.kept().figures.push_back({{left_, 0, w, h}, &f.scene});
  push(std::move(a));
  after_figure_ = true;
  return true;
}

void SectionAtoms::figure(int si, int bi, const Figure& f, bool follows_paragraph) {
  const auto [w, h] = figure_size(f, width_ * std::clamp(f.width_fraction, 0.05, 1.0) * scale_);
  Atom a = new_atom();
  a.section = si;
  a.block = bi;
  a.space_before = s_.figure_space;
  a.height = h;
  a.break_before = !follows_paragraph;
  a.figure = true;
  if (!shapes_) a.content.kept().figures.push_back({{left_ + (width_ - w) / 2, 0, w, h}, &f.scene});
  push(std::move(a));
  after_figure_ = true;
}

}  // namespace epure::render::layout_detail
