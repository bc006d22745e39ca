#pragma once
// cairo writes a PDF's numbers with snprintf (through glibc's fortified __snprintf_chk), and
// glibc's printf formats a double in arbitrary precision: 10-15 % of the time of a class set's
// PDFs went there. cairo_printf.cpp defines __snprintf_chk in the executable, which the dynamic
// linker then binds cairo's calls to, and writes the formats cairo uses for numbers ("%f",
// "%.*f", "%.18f", "%d") itself, byte for byte as glibc would (fixed_decimal.h); every other
// format, and these in a locale whose decimal point is not '.' or under another rounding mode,
// go on to glibc's __vsnprintf_chk. Only targets that link the object library
// epure::cairo_printf have it (epure and the unit tests).
#include <cstdint>

namespace epure::render {

// How many snprintf calls of this thread the fast path has written (for the test that cairo's
// calls do reach it).
std::uint64_t cairo_printf_fast_calls() noexcept;

}  // namespace epure::render
