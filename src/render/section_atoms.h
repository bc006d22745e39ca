#pragma once
// From a Document's sections to atoms (internal to layout.cpp): each block measured at the text
// column's width and broken into the units a page may end between — a line of a paragraph, a
// heading, a row of fields or of a key's table, a figure with what stands beside it. The options
// for a figure and its neighbours (fields beside or under it, paragraphs beside it) are measured
// as tallies (their atoms' heights summed as they come, no atom kept) and only the shortest is
// built (section_atoms.cpp); rows of fields and of a key's answers are made in field_rows.cpp.
// Putting the atoms on pages is paginate.h's job.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "render/layout.h"
#include "render/layout_atoms.h"
#include "render/row_shapes.h"
#include "render/text_measure.h"

namespace epure::render::layout_detail {

// A row of fields or of a key's answers, measured with a given geometry.
struct RowKey {
  const void* block = nullptr;
  std::uint64_t left = 0, width = 0, column = 0;
  bool follows = false, in_column = false;
  friend bool operator==(const RowKey&, const RowKey&) = default;
};
struct RowHash {
  std::size_t operator()(const RowKey& k) const;
};

// What measuring a document's blocks leaves behind, kept for the whole of its layout: the page
// budget's trials measure the same texts, rows and figures at the same widths again.
struct LayoutMemo {
  TextMeasure text;
  std::unordered_map<RowKey, Atom, RowHash> rows;  // a row's shape at a geometry
  std::unordered_map<RowKey, double, RowHash> prompt_columns;
  // a figure's size: (scene, width asked, height cap) → (width, height)
  std::map<std::tuple<const Scene*, std::uint64_t, std::uint64_t>, std::pair<double, double>> figure_sizes;
  // The option taken for a figure and its neighbours (see figure_with_neighbours), by (figure,
  // scale, paragraphs allowed beside it): measured once, as shapes, and built from that.
  struct Option {
    std::size_t beside_paragraphs = 0;
    bool answers_beside = false;
    std::size_t split = 0;
  };
  std::map<std::tuple<const Figure*, std::uint64_t, bool>, Option> options;
};

class SectionAtoms {
 public:
  SectionAtoms(const Document& doc, const LayoutStyle& style, LayoutMemo& memo);

  // The first page's name row and the header note under it.
  std::vector<Atom> opening(bool shapes_only);

  // A section's atoms, its figures at `scale` of the size they would have (width and height cap
  // alike). With `shapes_only`, the atoms carry their geometry and no content: enough to count
  // pages. With `allow_side` false, no paragraph goes beside a figure (a section's fallback).
  struct Built {
    std::vector<Atom> atoms;
    bool side_used = false;  // a paragraph went beside a figure: the section has a fallback
  };
  Built section(int si, double scale, bool shapes_only, bool allow_side = true);

 private:
  // The builder's state before a block: undoing a block's atoms goes back to it.
  struct Mark {
    std::size_t atoms = 0;
    bool after_heading = false, after_figure = false;
  };
  // The column beside a figure, as measured: the figure's width and where the column starts.
  struct Column {
    double figure_w = 0, left = 0;
    std::vector<Atom> atoms;  // none when measured as a tally
    double height = 0;        // the column's atoms stacked, as beside() sets them
  };
  // What a measure needs of the atoms it pushes, kept instead of the atoms: an option's height
  // (span() of its atoms and the first one's space), the column's two sums (column_beside's
  // and beside()'s, in their orders of addition, so that the same doubles come out as from
  // the atoms) and whether every atom of a column fits it. An option measured, or a column of
  // a shape, is then made of no atom: the same sums, without making, moving and dropping one
  // atom per line for every option and every width tried.
  struct Tally {
    std::size_t count = 0;
    double first_space = 0;
    double span = 0;     // layout_detail::span() of the atoms
    double stacked = 0;  // beside()'s y: each atom's space before it, then its height
    bool fits = true;    // (a column's) every atom left of its question id, none wrapped
    double height() const { return span + (count > 0 ? first_space : 0); }
  };

  Mark mark() const { return {atoms_.size(), after_heading_, after_figure_}; }
  void undo(const Mark& m);
  Atom new_atom() const;
  void push(Atom&& atom);
  // push() into the tally: the atom's space as push() would set it, its height and extents.
  void fold(const Atom& atom);
  void fold(double space_before, double height, double box_right, double text_right, double muted_left, bool wrapped);
  RowKey row_key(const void* block, double column, bool follows) const;
  bool replay(const RowKey& key);
  void remember(const RowKey& key, const Atom& a);
  // A row's shape from an earlier document (RowShapes), if any, pushed as this block's and
  // remembered: true when pushed.
  bool reuse(const Atom* shared, const RowKey& key, int si, int bi);

  void build_section(int si);
  std::size_t figure_with_neighbours(int si, std::size_t fi, const Figure& f, const std::vector<Block>& blocks);
  void emit_answers(int si, const std::vector<Block>& blocks, std::size_t from, std::size_t to);
  void heading(int si, int bi, const Heading& h);
  // From its `from`-th word on, when given: the rest of a paragraph beside its figure.
  void paragraph(int si, int bi, const RichText& text, bool emphasis, std::size_t from = 0);
  void line_atoms(int si, int bi, const WrappedText& wrapped, std::size_t n,
                  const std::vector<std::vector<TextRun>>* lines);
  // A figure's size at most `w` wide (× the section's scale) and its cap of the page high.
  std::pair<double, double> figure_size(const Figure& f, double w);
  std::pair<double, double> measure_figure(const Figure& f, double w, double max_h) const;
  static std::size_t answers_run_end(const std::vector<Block>& blocks, std::size_t from);
  bool beside(int si, int bi, const Figure& f, bool follows_paragraph, const std::vector<Block>& blocks,
              const std::vector<std::size_t>& side_blocks, bool natural_only, std::size_t first_from);
  std::optional<Column> column_beside(int si, const Figure& f, const std::vector<Block>& blocks,
                                      const std::vector<std::size_t>& side_blocks, bool natural_only,
                                      std::size_t first_from);
  void figure(int si, int bi, const Figure& f, bool follows_paragraph);

  // field_rows.cpp
  double field_prompt_column(const std::vector<Block>& blocks, std::size_t from);
  double key_prompt_column(const std::vector<Block>& blocks, std::size_t from);
  double measure_field_prompt_column(const std::vector<Block>& blocks, std::size_t from) const;
  double measure_key_prompt_column(const std::vector<Block>& blocks, std::size_t from) const;
  void answer_field(int si, int bi, const AnswerField& f, bool follows_field);
  void answer_line(int si, int bi, const AnswerLine& l, bool follows_line);

  const Document& doc_;
  const LayoutStyle& s_;
  LayoutMemo& memo_;
  TextMeasure& text_;
  RowShapes& rows_;  // field rows' shapes, shared with the thread's earlier documents
  const TextArea area_;
  // The text column; `beside` narrows left_ and width_ for the fields set beside a figure.
  double left_;
  const double right_;
  double width_;
  const double top_, bottom_, body_line_;
  double prompt_share_;  // of width_, at most, for the fields' prompts

  // The section being built.
  std::vector<Atom> atoms_;
  double scale_ = 1;
  bool after_heading_ = false;
  bool after_figure_ = false;
  std::vector<Mark> marks_;  // the state before each block of the section
  bool allow_side_ = true, side_used_ = false;
  bool shapes_ = false;     // atoms with their geometry only: an option measured, or pages counted
  bool in_column_ = false;  // building the column beside a figure
  Tally* tally_ = nullptr;  // set: push() folds its atoms into it instead of keeping them
  double field_column_ = 0, key_column_ = 0;
};

}  // namespace epure::render::layout_detail
