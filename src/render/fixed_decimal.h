#pragma once
// A double written as printf's "%.Nf" writes it, without printf. cairo writes every coordinate
// and glyph position of a PDF page that way (about 2,000 snprintf calls a page), and glibc's
// printf takes a tenth of a PDF class set's time doing it, in arbitrary precision. Here the exact
// product of the double and 10^N fits in 128 bits, so one shift rounds it, with glibc's result:
// the exact value rounded to nearest, ties to even, "-" whenever the sign bit is set.
// cairo_printf.cpp gives cairo this path (the bytes of the PDFs do not change).
#include <cstddef>
#include <optional>

namespace epure::render {

// Longest text fixed_decimal writes: a sign, 16 integer digits, the point, 18 decimals.
inline constexpr std::size_t fixed_decimal_max = 36;

// Writes `value` with `precision` decimals into out[0, fixed_decimal_max) as "%.*f" would in
// the C locale when rounding to nearest (no NUL), and returns the length; nullopt for what this
// path does not cover and printf must write: |value| ≥ 2^53, NaN, infinities, precision
// outside [0, 18].
std::optional<std::size_t> fixed_decimal(double value, int precision, char* out) noexcept;

}  // namespace epure::render
