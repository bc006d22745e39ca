#include "render/row_shapes.h"

#include <cstring>
#include <functional>
#include <memory>
#include <string_view>
#include <type_traits>

#include "render/text_measure.h"

namespace epure::render::layout_detail {
namespace {

// A course's sheets ask a few hundred rows (each exercise's fields at the widths its options
// try); past this many (a spec of many exercises) the rows start again, which bounds their memory.
constexpr std::size_t kSharedRows = 4096;
constexpr std::size_t kBuckets = 1024;

// The same style is the same bytes (a memo, not a tolerance). LayoutStyle is only doubles today;
// a member of another type could bring padding bytes into the comparison: a miss (the rows
// measured again), never a row taken for another's.
bool same_style(const LayoutStyle& a, const LayoutStyle& b) {
  static_assert(std::is_trivially_copyable_v<LayoutStyle>);
  return std::memcmp(&a, &b, sizeof(LayoutStyle)) == 0;
}

}  // namespace

RowShapes& RowShapes::for_document(const Document& doc, const LayoutStyle& style) {
  // On the heap, made at a thread's first document: the static TLS block every thread of the
  // process gets stays a pointer larger.
  thread_local std::unique_ptr<RowShapes> made;
  if (!made) made = std::make_unique<RowShapes>();
  RowShapes& rows = *made;
  if (rows.buckets_.empty() || !same_style(rows.style_, style) || rows.decimal_separator_ != doc.decimal_separator ||
      rows.yes_ != doc.words.yes || rows.no_ != doc.words.no) {
    rows.buckets_.assign(kBuckets, {});
    rows.count_ = 0;
    rows.style_ = style;
    rows.decimal_separator_ = doc.decimal_separator;
    rows.yes_ = doc.words.yes;
    rows.no_ = doc.words.no;
  }
  return rows;
}

std::size_t RowShapes::hash(const AnswerField& f, const RowGeometry& g) {
  std::size_t h = std::hash<std::string_view>{}(f.prompt);
  h = hash_combine(h, std::hash<std::string_view>{}(f.question_id));
  for (const auto& c : f.choices) h = hash_combine(h, std::hash<std::string_view>{}(c));
  h = hash_combine(h, static_cast<std::uint64_t>(f.kind) | std::uint64_t{f.last_choice_apart} << 8 |
                          static_cast<std::uint64_t>(static_cast<std::uint32_t>(f.integer_cells)) << 16 |
                          static_cast<std::uint64_t>(static_cast<std::uint32_t>(f.decimals)) << 40);
  for (std::uint64_t v : {g.left, g.width, g.right, g.column, std::uint64_t{g.follows} * 2 + g.in_column})
    h = hash_combine(h, v);
  return h;
}

bool RowShapes::same(const Row& r, const AnswerField& f, const RowGeometry& g) {
  return r.geometry == g && r.kind == f.kind && r.integer_cells == f.integer_cells &&
         r.decimals == f.decimals && r.last_choice_apart == f.last_choice_apart && r.prompt == f.prompt && r.question_id == f.question_id &&
         r.choices == f.choices;
}

const Atom* RowShapes::find(const AnswerField& f, const RowGeometry& g) const {
  for (const Row& r : buckets_[hash(f, g) % kBuckets])
    if (same(r, f, g)) return &r.shape;
  return nullptr;
}

void RowShapes::add(const AnswerField& f, const RowGeometry& g, const Atom& shape) {
  if (count_ >= kSharedRows) {
    for (auto& b : buckets_) b.clear();
    count_ = 0;
  }
  Row r;
  r.question_id = f.question_id;
  r.prompt = f.prompt;
  r.kind = f.kind;
  r.choices = f.choices;
  r.last_choice_apart = f.last_choice_apart;
  r.integer_cells = f.integer_cells;
  r.decimals = f.decimals;
  r.geometry = g;
  r.shape = shape;
  buckets_[hash(f, g) % kBuckets].push_back(std::move(r));
  ++count_;
}

}  // namespace epure::render::layout_detail
