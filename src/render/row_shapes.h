#pragma once
// The shapes of answer-field rows, shared by content with a thread's later documents (internal
// to the layout). A row's shape (its height, and how far its boxes and texts reach) depends only
// on the field's printed content and the geometry it is measured at, while the layout's own memo
// (LayoutMemo::rows) knows a row by its block's address, new in every document: a set's sheets
// ask the same fields ("t =", "I = ( □ ; □ )", the faces to tick) at the same column widths, and
// the options for a figure and its neighbours measure them at each width they try. Only shapes
// are shared: a row set on a page is built from its own field. A key's answer lines are not:
// their answers carry the instance's numbers, so few come again (shared too, they saved 0.3 % of
// the instructions for 3 MB more memory with two jobs).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "render/layout.h"
#include "render/layout_atoms.h"

namespace epure::render::layout_detail {

// Where a row is measured: the column's edges, the shared prompt column, whether it follows
// another field of its run and stands in a column beside a figure. (Bits: a memo key.)
struct RowGeometry {
  std::uint64_t left = 0, width = 0, right = 0, column = 0;
  bool follows = false, in_column = false;
  friend bool operator==(const RowGeometry&, const RowGeometry&) = default;
};

class RowShapes {
 public:
  // The thread's rows, for a document of `doc` laid out with `style`: rows measured with another
  // style, decimal separator or yes/no words are dropped first (a set has one of each).
  static RowShapes& for_document(const Document& doc, const LayoutStyle& style);

  // The shape of `f`'s row at `g`, if measured before (its section and block are the earlier
  // document's).
  const Atom* find(const AnswerField& f, const RowGeometry& g) const;
  void add(const AnswerField& f, const RowGeometry& g, const Atom& shape);

 private:
  // What of a field its row's shape reads: not the values its boxes stand for.
  struct Row {
    std::string question_id, prompt;
    AnswerField::Kind kind = AnswerField::Kind::number;
    std::vector<std::string> choices;
    bool last_choice_apart = false;
    int integer_cells = 0, decimals = 0;
    RowGeometry geometry;
    Atom shape;
  };
  static std::size_t hash(const AnswerField& f, const RowGeometry& g);
  static bool same(const Row& r, const AnswerField& f, const RowGeometry& g);

  LayoutStyle style_;
  std::string decimal_separator_, yes_, no_;
  std::vector<std::vector<Row>> buckets_;  // by hash
  std::size_t count_ = 0;
};

}  // namespace epure::render::layout_detail
