#pragma once
// From a Document's sections to atoms (internal to layout.cpp): each block measured at the text
// column's width and broken into the units a page may end between — a line of a paragraph, a
// heading, a row of fields or of a key's table, a figure with what stands beside it. The options
// for a figure and its neighbours (fields beside or under it, paragraphs beside it) are measured
// and the shortest is built (section_atoms.cpp); rows of fields and of a key's answers are made in
// field_rows.cpp. Putting the atoms on pages is paginate.h's job.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "render/layout.h"
#include "render/layout_atoms.h"
#include "render/text_measure.h"

namespace epure::render::layout_detail {

class SectionAtoms {
 public:
  SectionAtoms(const Document& doc, const LayoutStyle& style);

  // The name row and header note (a student's first page), then every section's atoms.
  void build();
  std::vector<Atom>& atoms() { return atoms_; }

  // The sections whose paragraphs went beside a figure: each may be laid out again without that
  // (fallback), from the builder's state at its start.
  std::vector<int> sections_with_fallback() const;
  // The section laid out with no paragraph beside a figure.
  std::vector<Atom> fallback(int si);

 private:
  // The builder's state before a block: undoing a block's atoms goes back to it.
  struct Mark {
    std::size_t atoms = 0;
    bool after_heading = false, after_figure = false;
  };
  // A row of fields or of a key's answers, measured with a given geometry (see replay).
  struct RowKey {
    const void* block = nullptr;
    std::uint64_t left = 0, width = 0, column = 0;
    bool follows = false, in_column = false;
    friend bool operator==(const RowKey&, const RowKey&) = default;
  };
  struct RowHash {
    std::size_t operator()(const RowKey& k) const;
  };

  Mark mark() const { return {atoms_.size(), after_heading_, after_figure_}; }
  void undo(const Mark& m);
  Atom new_atom() const;
  void push(Atom atom);
  RowKey row_key(const void* block, double column, bool follows) const;
  bool replay(const RowKey& key);
  void remember(const RowKey& key, const Atom& a);

  void section(int si);
  void build_section(int si);
  std::size_t figure_with_neighbours(int si, std::size_t fi, const Figure& f, const std::vector<Block>& blocks);
  void emit_answers(int si, const std::vector<Block>& blocks, std::size_t from, std::size_t to);
  void heading(int si, int bi, const Heading& h);
  void paragraph(int si, int bi, const RichText& text, bool emphasis);
  void line_atoms(int si, int bi, std::size_t n, const std::vector<std::vector<TextRun>>* lines);
  std::pair<double, double> figure_size(const Figure& f, double w);
  std::pair<double, double> measure_figure(const Figure& f, double w) const;
  static std::size_t answers_run_end(const std::vector<Block>& blocks, std::size_t from);
  bool beside(int si, int bi, const Figure& f, bool follows_paragraph, const std::vector<Block>& blocks,
              const std::vector<std::size_t>& side_blocks, bool natural_only,
              const std::optional<RichText>& first_text = std::nullopt);
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
  const TextArea area_;
  // The text column; `beside` narrows left_ and width_ for the fields set beside a figure.
  double left_;
  const double right_;
  double width_;
  const double top_, bottom_, body_line_;
  double prompt_share_;  // of width_, at most, for the fields' prompts

  TextMeasure text_;
  std::vector<Atom> atoms_;
  bool after_heading_ = false;
  bool after_figure_ = false;
  std::size_t section_begin_ = 0;
  std::vector<Mark> marks_;  // the state before each block of the section being measured
  bool allow_side_ = true, side_used_ = false;
  std::map<int, Mark> fallback_;  // the sections with paragraphs beside a figure: the state at their start
  bool measuring_ = false;  // building an option only to measure it
  std::unordered_map<RowKey, Atom, RowHash> measured_rows_;
  std::unordered_map<RowKey, double, RowHash> prompt_columns_;
  bool in_column_ = false;  // building the column beside a figure
  std::map<std::pair<const Scene*, double>, std::pair<double, double>> figure_sizes_;
  double field_column_ = 0, key_column_ = 0;
};

}  // namespace epure::render::layout_detail
