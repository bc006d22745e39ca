#pragma once
// The one limit of exact decisions (README, "Accurate values"): the kernels bring a figure near
// unit size by a power of two, then take error-free products (fma) of its numbers; a product
// below 2^-969 underflows, and its rounding error is no longer a double, so a filter may certify
// a wrong sign and a value may lose its digits. Every product of two numbers of a line stays
// above that when its smallest non-zero number, scaled like its largest, is at least 2^-484.5 of
// unit size (the square of that is 2^-969): a subnormal (or 1e-200) beside ordinary numbers is
// not. Such a line is refused, naming the field, rather than answered perhaps wrongly; a figure
// small as a whole (every number near 1e-310) is scaled with its numbers, and answered.
//
// The numbers are grouped as the kernels scale them: the figure's points and sizes together
// (with the canonical figure's own size, 1 for the square and the cube, which the kernels do not
// scale away), each direction or vector alone; an angle, in degrees, is not a length.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "exercises/data_field.h"
#include "geometry/decimal.h"
#include "geometry/exponent.h"
#include "solve/fields.h"

namespace epure::solve {

namespace detail {

// The largest |hi| of a group and its smallest non-zero number, with the field that holds it.
struct Span {
  double largest = 0;
  double smallest = 0;  // 0: none yet
  std::string_view field;
  const geo::Decimal* number = nullptr;

  void add(const geo::Decimal& d, std::string_view name) {
    const double x = std::abs(d.hi);
    largest = std::max(largest, x);
    // a decimal whose double is zero but itself is not (1e-400) is below every double
    const double size = x != 0 ? x : d.lo != 0 ? std::abs(d.lo) * 0.5 : 0;
    if (size != 0 && (smallest == 0 || size < smallest)) {
      smallest = size;
      field = name;
      number = &d;
    }
  }
  void add(const Value& v, std::string_view name) {
    if (v.type == Type::number) add(v.number, name);
    if (v.type == Type::array)
      for (std::size_t i = 0; i < std::min(v.size, Value::kItems); ++i)
        if (v.item_types[i] == Type::number) add(v.items[i], name);
  }

  // Whether the square of the smallest number, scaled by the power of two that brings the
  // largest into [1, 2), is below 2^-969.
  bool beyond() const {
    constexpr double kLeast = 0x1p-969;
    const double scaled = largest > 0 ? geo::times_pow2(smallest, -geo::binary_exponent(largest)) : 0;
    return scaled * scaled < kLeast;
  }
  // Refuses the group when it is beyond.
  void check() const {
    if (smallest == 0 || !beyond()) return;
    fail(field, fmt::format("{} beside {} (the largest number scaled with it): below 2^-484 of it, products "
                            "of the line's numbers underflow and the answer could be wrong (README, Accurate values)",
                            number->hi != 0 ? fmt::format("{}", number->hi) : std::string("a number below every double"),
                            largest));
  }
};

}  // namespace detail

// Throws InputError naming the field of a number too small beside the others (above). `fields`
// are the kind's data fields (their roles say how the kernels scale them); `canonical_size` the
// figure's size that is no datum (0 when every size is one).
inline void check_number_span(std::span<const Field> line, const Fields& figure, std::span<const DataField> fields,
                              double canonical_size) {
  // Every line of a worksheet or of the bench: all its numbers (an angle's too) within 2^484 of
  // one another, so within every group; one pass, no field looked up.
  detail::Span all;
  if (canonical_size > 0) all.largest = canonical_size;
  for (const Field& f : line) all.add(f.value, f.key);
  if (all.smallest == 0 || !all.beyond()) return;
  detail::Span shape;
  if (canonical_size > 0) shape.largest = canonical_size;
  for (const DataField& f : fields) {
    const Value* v = figure.find(f.name);
    if (!v) continue;
    if (f.role.role == FieldRole::number) continue;  // an angle: degrees, not a length
    if (f.role.role == FieldRole::direction) {
      detail::Span alone;
      alone.add(*v, f.name);
      alone.check();
    } else {
      shape.add(*v, f.name);
    }
  }
  shape.check();
}

}  // namespace epure::solve
