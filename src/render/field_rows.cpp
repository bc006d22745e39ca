// Rows of answer fields (a student's sheet) and of a key's answer table: the atoms of
// SectionAtoms for AnswerField and AnswerLine blocks, with the prompt columns a run shares.
#include <algorithm>
#include <string>
#include <utility>
#include <variant>

#include "render/section_atoms.h"

namespace epure::render::layout_detail {
namespace {

// Horizontal gaps, in points.
constexpr double kPromptGap = 8;    // after a prompt column
constexpr double kBoxGap = 3;       // between a box and the "(", ";" around it
constexpr double kTickGap = 3;      // between a tick box and its option (10 + 3: the 9 + 4 of old, rows unchanged)
constexpr double kOptionGap = 16;   // between two options
// A key's answer too long for the cell beside its prompt goes on the line under the prompt, this
// much indented, when that wraps it less (a point or a value is then on one line).
constexpr double kStackIndent = 12;
// Wider than any line a page holds: what wrapping gives for this width is the text's own lines
// (only its '\n' break it).
constexpr double kUnbounded = 1e9;
// A crop of what was read (AnswerLine::shown) is set two lines high, or as high as it was on
// paper (a column of tick boxes) up to four.
constexpr double kShownLines = 2;
constexpr double kShownMaxLines = 4;

// A comb's width: its sign cell, integer and decimal cells, and the separator's gap.
double comb_width(const LayoutStyle& s, const AnswerField& f) {
  return s.comb_cell_width * (1 + f.integer_cells + f.decimals) + (f.decimals > 0 ? s.comb_separator_gap : 0);
}

}  // namespace

// The prompt column shared by a run of consecutive fields, so that their boxes line up.
// The prompt columns depend on the run and the column's width only: remembered.
double SectionAtoms::field_prompt_column(const std::vector<Block>& blocks, std::size_t from) {
  const RowKey key{&blocks[from], 0, bits(width_), bits(prompt_share_), false, false};
  if (auto it = memo_.prompt_columns.find(key); it != memo_.prompt_columns.end()) return it->second;
  return memo_.prompt_columns[key] = measure_field_prompt_column(blocks, from);
}

double SectionAtoms::key_prompt_column(const std::vector<Block>& blocks, std::size_t from) {
  const RowKey key{&blocks[from], 0, bits(width_), 0, true, false};
  if (auto it = memo_.prompt_columns.find(key); it != memo_.prompt_columns.end()) return it->second;
  return memo_.prompt_columns[key] = measure_key_prompt_column(blocks, from);
}

double SectionAtoms::measure_field_prompt_column(const std::vector<Block>& blocks, std::size_t from) const {
  double widest = 0;
  // What the run's boxes need right of the prompts: a point's "( □ ; □ )", a number's box, a
  // single tick option (options wrap to more rows), and the question id at the right edge.
  double body = 0;
  const double size = s_.body_size;
  using K = AnswerField::Kind;
  // The boxes line up after the prompts of the fields that have boxes; a question answered by
  // ticks sets its own (answer_field), unless the run has only ticks.
  bool any_boxes = false;
  for (std::size_t i = from; i < blocks.size(); ++i) {
    const auto* f = std::get_if<AnswerField>(&blocks[i]);
    if (!f) break;
    any_boxes = any_boxes || f->kind == K::number || f->kind == K::point || f->kind == K::point3;
  }
  for (std::size_t i = from; i < blocks.size(); ++i) {
    const auto* f = std::get_if<AnswerField>(&blocks[i]);
    if (!f) break;
    const bool boxes = f->kind == K::number || f->kind == K::point || f->kind == K::point3;
    if (boxes || !any_boxes) widest = std::max(widest, text_width(f->prompt, size));
    const double id = f->question_id.empty() ? 0 : text_width(f->question_id, s_.id_size) + kIdGap;
    const bool comb = f->integer_cells > 0;
    double need = comb ? comb_width(s_, *f) : s_.number_box_width;
    if (f->kind == K::point || f->kind == K::point3) {
      const int n = f->kind == K::point3 ? 3 : 2;
      const double box = comb ? comb_width(s_, *f) : f->kind == K::point3 ? s_.point3_box_width : s_.point_box_width;
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

double SectionAtoms::measure_key_prompt_column(const std::vector<Block>& blocks, std::size_t from) const {
  double widest = 0;
  for (std::size_t i = from; i < blocks.size(); ++i) {
    const auto* l = std::get_if<AnswerLine>(&blocks[i]);
    if (!l) break;
    widest = std::max(widest, text_width(l->prompt, s_.body_size));
  }
  return std::clamp(widest + kPromptGap, s_.key_prompt_column_min, width_ * s_.key_prompt_column_max);
}

void SectionAtoms::answer_field(int si, int bi, const AnswerField& f, bool follows_field) {
  const RowKey key = row_key(&f, field_column_, follows_field);
  if (replay(key)) return;
  const RowGeometry geometry{bits(left_), bits(width_), bits(right_), bits(field_column_), follows_field, in_column_};
  if (shapes_ && reuse(rows_.find(f, geometry), key, si, bi)) return;
  const double size = s_.body_size;
  Atom a = new_atom();
  a.section = si;
  a.block = bi;
  a.space_before = follows_field ? s_.row_space : s_.block_space;
  a.break_before = !follows_field;  // a run of fields stays whole where a page holds it

  auto id = plain(f.question_id);
  const double id_w = f.question_id.empty() ? 0 : text_width(id, s_.id_size);
  const double limit = right_ - (id_w > 0 ? id_w + kIdGap : 0);
  double x0 = left_ + field_column_;  // where the boxes, or the ticks, start

  using K = AnswerField::Kind;
  const bool ticks = f.kind == K::choice || f.kind == K::faces || f.kind == K::boolean;
  const double row_h = ticks ? s_.tick_row_height : s_.field_box_height;
  const double baseline = row_h / 2 + size * kCentredBaseline;
  double body_h = row_h;

  if (!ticks) {
    const double bh = s_.field_box_height;
    const bool comb = f.integer_cells > 0;
    auto glyph = [&](const std::string& s, double x) {
      auto runs = plain(s);
      const double w = text_width(runs, size);
      a.content.text(std::move(runs), x, baseline, size);
      return x + w;
    };
    // A value's box, or its comb: the cells side by side, the separator printed in the gap
    // before the decimals.
    auto box = [&](double x, double w, std::string value) {
      if (!comb) {
        const PageRect rect{x, 0, w, bh};
        a.content.box(rect, [&] { return PlacedBox{rect, BoxKind::answer, f.question_id, std::move(value)}; });
        return;
      }
      const int n = 1 + f.integer_cells + f.decimals;
      const double top = (bh - s_.comb_cell_height) / 2;
      for (int i = 0; i < n; ++i) {
        if (i == n - f.decimals) {
          const double sep_w = text_width(plain(doc_.decimal_separator), size);
          glyph(doc_.decimal_separator, x + (s_.comb_separator_gap - sep_w) / 2);
          x += s_.comb_separator_gap;
        }
        const PageRect rect{x, top, s_.comb_cell_width, s_.comb_cell_height};
        a.content.box(rect, [&] { return PlacedBox{rect, BoxKind::cell, f.question_id, value, true, f.decimals}; });
        x += s_.comb_cell_width;
      }
    };
    if (f.kind == K::number) {
      box(x0, comb ? comb_width(s_, f) : s_.number_box_width, {});
    } else {
      const bool three = f.kind == K::point3;
      const double w = comb ? comb_width(s_, f) : three ? s_.point3_box_width : s_.point_box_width;
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

  // The prompt, left of the boxes, wrapped if wider than its column. A question answered by
  // ticks is set the shortest way (on a tie, the first): beside its ticks, on one or two lines, in
  // the boxes' column or a column as wide as it needs ("Does the ray hit the square?  □ yes
  // □ no" in a run of short prompts such as "t ="); or on lines of its own above them (a question
  // asked as a question, "Is A inside the ellipse?", would otherwise stand in a thin column of
  // words).
  const auto* prompt_lines = &text_.wrap(f.prompt, size, field_column_ - kPromptGap);
  bool prompt_above = false;

  std::vector<std::pair<std::string, std::string>> options;  // (printed, value)
  std::vector<std::vector<TextRun>> labels;
  std::vector<double> widths;
  // The options on as few rows as fit from `x`, in aligned columns: six faces become two rows
  // of three rather than five and a lonely one. A last choice set apart ("none" after the sides)
  // gets a row of its own.
  struct Grid {
    std::size_t per_row = 0, rows = 0, grid_rows = 0;
    std::vector<double> columns;
  };
  const std::size_t n_options = ticks ? (f.kind == K::boolean ? 2 : f.choices.size()) : 0;
  const std::size_t grid_n = f.last_choice_apart && n_options > 1 ? n_options - 1 : n_options;
  auto grid_from = [&](double x) {
    Grid g;
    g.per_row = grid_n;
    for (std::size_t rows = 1; rows <= grid_n; ++rows) {
      g.per_row = (grid_n + rows - 1) / rows;
      g.columns.assign(g.per_row, 0);
      for (std::size_t i = 0; i < grid_n; ++i) g.columns[i % g.per_row] = std::max(g.columns[i % g.per_row], widths[i]);
      double total = kOptionGap * static_cast<double>(g.per_row - 1);
      for (double c : g.columns) total += c;
      if (x + total <= limit + kFitSlack) break;
    }
    g.grid_rows = grid_n == 0 ? 1 : (grid_n + g.per_row - 1) / g.per_row;
    g.rows = g.grid_rows + (grid_n < n_options ? 1 : 0);
    return g;
  };
  Grid grid;
  if (ticks) {
    if (f.kind == K::boolean) {
      options = {{doc_.words.yes, "true"}, {doc_.words.no, "false"}};
    } else {
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        options.emplace_back(f.choices[i], i < f.choice_values.size() ? f.choice_values[i] : f.choices[i]);
    }
    for (const auto& o : options) {
      labels.push_back(parse_rich_text(o.first));
      widths.push_back(s_.tick_size + kTickGap + text_width(labels.back(), size));
    }
    const double tick_row = s_.tick_row_height;
    const auto lines_height = [&](std::size_t lines) { return static_cast<double>(lines) * body_line_; };
    // A prompt wrapped at `width` whose every line fits it (no word longer than the column), on
    // two lines at most: a longer question reads better above its ticks than in a thin column.
    const auto fits_in = [&](double width) {
      const WrappedText& w = text_.wrapped(f.prompt, size, width);
      return w.widest <= width + kFitSlack && w.count() <= 2;
    };
    constexpr double kNever = 1e300;
    double best = kNever;
    // Beside the ticks, in a column `column` wide (from the row's left): the boxes' column, or
    // one as wide as the prompt needs, leaving the options one to a row at least, or all on one.
    const double widest_option = *std::max_element(widths.begin(), widths.end());
    double one_row = kOptionGap * static_cast<double>(grid_n > 0 ? grid_n - 1 : 0);
    for (std::size_t i = 0; i < grid_n; ++i) one_row += widths[i];
    const double prompt_w = text_.wrapped(f.prompt, size, kUnbounded).widest + kPromptGap;
    const double room = limit - left_;
    for (const double column : {std::max(field_column_, std::min(prompt_w, room - widest_option)),
                                std::min(prompt_w, room - one_row)}) {
      if (column < field_column_ - kFitSlack || !fits_in(column - kPromptGap)) continue;
      const Grid g = grid_from(left_ + column);
      const auto& lines = text_.wrap(f.prompt, size, column - kPromptGap);
      const double h = std::max(static_cast<double>(g.rows) * tick_row, lines_height(lines.size()));
      if (h < best - kFitSlack) {
        best = h;
        grid = g;
        x0 = left_ + column;
        prompt_lines = &lines;
      }
    }
    // Above, across the row.
    const auto& wide = text_.wrap(f.prompt, size, limit - left_);
    const Grid under = grid_from(left_ + field_column_);
    const double h = lines_height(wide.size()) + static_cast<double>(under.rows) * tick_row;
    if (h < best - kFitSlack) {
      grid = under;
      x0 = left_ + field_column_;
      prompt_lines = &wide;
      prompt_above = true;
    }
  }
  const double ticks_top = prompt_above ? static_cast<double>(prompt_lines->size()) * body_line_ : 0;

  if (ticks) {
    for (std::size_t i = 0; i < n_options; ++i) {
      double x = x0;
      std::size_t row = grid.grid_rows;  // the option after the grid
      if (i < grid_n) {
        for (std::size_t c = 0; c < i % grid.per_row; ++c) x += grid.columns[c] + kOptionGap;
        row = i / grid.per_row;
      }
      const double top = ticks_top + static_cast<double>(row) * s_.tick_row_height;
      const double ty = top + (s_.tick_row_height - s_.tick_size) / 2;
      const PageRect rect{x, ty, s_.tick_size, s_.tick_size};
      a.content.box(rect, [&] {
        return PlacedBox{rect, BoxKind::tick, f.question_id, std::move(options[i].second), false, 0, f.kind == K::faces};
      });
      a.content.text(std::move(labels[i]), x + s_.tick_size + kTickGap, top + baseline, size);
    }
    body_h = ticks_top + static_cast<double>(grid.rows) * s_.tick_row_height;
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
  if (shapes_) rows_.add(f, geometry, a);
  push(std::move(a));
}

void SectionAtoms::answer_line(int si, int bi, const AnswerLine& l, bool follows_line) {
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
  const auto* answer = &text_.wrap(l.answer, size, right_ - answer_x - id_room);
  const std::size_t own_lines = text_.wrapped(l.answer, size, kUnbounded).count();
  bool stacked = false;
  if (answer->size() > own_lines) {
    // Prompt on its line, the answer under it with the column's whole width.
    answer_x = left_ + kStackIndent;
    const auto& under = text_.wrap(l.answer, size, right_ - answer_x - id_room);
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
  for (const auto& runs : text_.wrap(l.prompt, size, prompt_w)) {
    a.content.text(runs, left_, y + static_cast<double>(rows++) * body_line_, size);
  }
  const std::size_t first_answer_row = stacked ? std::max<std::size_t>(rows, 1) : 0;
  std::size_t answer_rows = first_answer_row;
  for (const auto& runs : *answer) {
    a.content.text(runs, answer_x, y + static_cast<double>(answer_rows++) * body_line_,
                   size, Ink::answer);
  }
  if (id_w > 0) a.content.text_right(std::move(id), right_, y, s_.id_size, Ink::muted);
  double text_h = static_cast<double>(std::max<std::size_t>({rows, answer_rows, 1})) * body_line_;
  if (!l.shown.empty()) {
    // What was read, two lines high (large enough to tell a 7 from a 1), under the prompt; one
    // too wide for the prompt's column (a row of tick boxes) goes under the whole row, with
    // the row's width, and so does every crop when the answer is set under the prompt.
    const double gap = 0.25 * body_line_;
    double h = std::clamp(l.shown.natural_height_pt, kShownLines * body_line_, kShownMaxLines * body_line_);
    double w = h * l.shown.width_px / l.shown.height_px;
    const bool under_row = stacked || w > prompt_w;
    if (const double room = under_row ? right_ - left_ - id_room : prompt_w; w > room) {
      w = room;
      h = w * l.shown.height_px / l.shown.width_px;
    }
    const std::size_t above = under_row ? std::max<std::size_t>({rows, answer_rows, 1}) : std::max<std::size_t>(rows, 1);
    const double top = pad + static_cast<double>(above) * body_line_ + gap;
    a.content.image({{left_, top, w, h}, l.shown});
    text_h = std::max(text_h, top - pad + h);
  }
  a.height = text_h + 2 * pad;
  // A table: a rule above the first row and under every row.
  if (!follows_line) a.content.rule({{left_, 0}, {right_, 0}, 0.4, Ink::muted});
  a.content.rule({{left_, a.height}, {right_, a.height}, 0.4, Ink::muted});
  remember(key, a);
  push(std::move(a));
}

}  // namespace epure::render::layout_detail
