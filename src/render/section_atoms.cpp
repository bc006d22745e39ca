#include "render/section_atoms.h"

#include <algorithm>
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

}  // namespace

SectionAtoms::SectionAtoms(const Document& doc, const LayoutStyle& style)
    : doc_(doc),
      s_(style),
      area_(doc, style),
      left_(area_.left),
      right_(area_.right),
      width_(area_.width),
      top_(area_.top),
      bottom_(area_.bottom),
      body_line_(style.body_size * style.line_height),
      prompt_share_(style.prompt_column_max) {}

void SectionAtoms::build() {
  if (doc_.student_fields) push(name_row(doc_, s_, area_));
  if (!doc_.header_note.empty()) paragraph(-1, -1, doc_.header_note, false);
  for (std::size_t s = 0; s < doc_.sections.size(); ++s) section(static_cast<int>(s));
}

std::vector<int> SectionAtoms::sections_with_fallback() const {
  std::vector<int> out;
  for (const auto& [si, start] : fallback_) out.push_back(si);
  return out;
}

std::size_t SectionAtoms::RowHash::operator()(const RowKey& k) const {
  std::size_t h = std::hash<const void*>{}(k.block);
  for (std::uint64_t v : {k.left, k.width, k.column, std::uint64_t{k.follows} * 2 + k.in_column}) h = hash_combine(h, v);
  return h;
}

// An option only measured keeps no text, so the atom of a row of fields or answers is the
// same each time the same block is measured with the same geometry: the options for a figure
// and its neighbours measure the same rows many times. True when the row was pushed again.
SectionAtoms::RowKey SectionAtoms::row_key(const void* block, double column, bool follows) const {
  return {block, bits(left_), bits(width_), bits(column), follows, in_column_};
}

bool SectionAtoms::replay(const RowKey& key) {
  if (!measuring_) return false;
  auto it = measured_rows_.find(key);
  if (it == measured_rows_.end()) return false;
  push(it->second);
  return true;
}

void SectionAtoms::remember(const RowKey& key, const Atom& a) {
  if (measuring_) measured_rows_.emplace(key, a);
}

// An atom for the current mode: a measured option keeps no text, a column's atoms note how far
// their texts reach.
Atom SectionAtoms::new_atom() const {
  Atom a;
  a.content.keep_texts = !measuring_;
  a.content.track_extents = in_column_;
  return a;
}

void SectionAtoms::push(Atom atom) {
  if (after_heading_) atom.break_before = false;  // a heading never ends a page
  atom.follows_heading = after_heading_;
  if (after_figure_) atom.space_before = std::max(atom.space_before, s_.figure_space);
  after_heading_ = false;
  after_figure_ = false;
  atoms_.push_back(std::move(atom));
}

void SectionAtoms::undo(const Mark& m) {
  atoms_.resize(m.atoms);
  after_heading_ = m.after_heading;
  after_figure_ = m.after_figure;
}

// A section's atoms. When a statement or steps went beside a figure, open_section may lay the
// section out again without that (fallback), from the builder's state at its start.
void SectionAtoms::section(int si) {
  const Mark start = mark();
  side_used_ = false;
  allow_side_ = true;
  build_section(si);
  if (side_used_) fallback_.emplace(si, start);
}

// The section laid out with no paragraph beside a figure.
std::vector<Atom> SectionAtoms::fallback(int si) {
  const Mark start = fallback_.at(si);
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

void SectionAtoms::build_section(int si) {
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
  auto height = [&]() { return span(atoms_, start.atoms, atoms_.size()) + (atoms_.size() > start.atoms ? atoms_[start.atoms].space_before : 0); };
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
    if (text.find('\n') == RichText::npos) source = text_.wrap_source(text, s_.body_size, width_);
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
void SectionAtoms::paragraph(int si, int bi, const RichText& text, bool emphasis) {
  const double size = s_.body_size;
  if (emphasis) {
    const double pad = s_.shade_padding;
    const auto& lines = text_.wrap(text, size, width_ - 2 * pad);
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
  const auto* lines = measuring_ && !in_column_ ? nullptr : &text_.wrap(text, size, width_);
  line_atoms(si, bi, lines ? lines->size() : text_.line_count(text, size, width_), lines);
}

// A plain paragraph's `n` lines as atoms; set from `lines` when given.
void SectionAtoms::line_atoms(int si, int bi, std::size_t n, const std::vector<std::vector<TextRun>>* lines) {
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
std::pair<double, double> SectionAtoms::figure_size(const Figure& f, double w) {
  // remembered, like wrap: the options for a figure ask its size at the same widths
  const std::pair<const Scene*, double> key{&f.scene, w};
  if (auto it = figure_sizes_.find(key); it != figure_sizes_.end()) return it->second;
  return figure_sizes_[key] = measure_figure(f, w);
}

std::pair<double, double> SectionAtoms::measure_figure(const Figure& f, double w) const {
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

// The figure on the left and the fields (or the key's answers) that follow it in a column on
// its right, as one atom: half the paper of a figure above its fields, and the student writes
// beside what they read. Tried with the column at its natural width, then wider (the figure
// narrower, never below figure_min_share of the text width); false, with nothing pushed, when
// the fields do not fit the column or would make the pair taller than a figure may be.
bool SectionAtoms::beside(int si, int bi, const Figure& f, bool follows_paragraph, const std::vector<Block>& blocks,
            const std::vector<std::size_t>& side_blocks, bool natural_only,
            const std::optional<RichText>& first_text) {
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

void SectionAtoms::figure(int si, int bi, const Figure& f, bool follows_paragraph) {
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

}  // namespace epure::render::layout_detail
