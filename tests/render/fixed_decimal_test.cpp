#include "render/fixed_decimal.h"
#include "pdf_surface_into.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <doctest/doctest.h>

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "render/cairo_printf.h"
#include "support/portable.h"

using namespace epure::render;

extern "C" int __snprintf_chk(char* s, std::size_t maxlen, int flag, std::size_t slen, const char* format, ...);

namespace {

// glibc's own answer: vsnprintf is not the fortified entry point cairo_printf.cpp replaces.
std::string glibc_printf(const char* format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  REQUIRE(n >= 0);
  REQUIRE(static_cast<std::size_t>(n) < sizeof text);
  return std::string(text, static_cast<std::size_t>(n));
}

std::string ours(double value, int precision) {
  char text[fixed_decimal_max];
  const auto length = fixed_decimal(value, precision, text);
  REQUIRE(length.has_value());
  return std::string(text, *length);
}

void check(double value, int precision) {
  INFO("value ", glibc_printf("%a", value), " precision ", precision);
  CHECK(ours(value, precision) == glibc_printf("%.*f", precision, value));
}

}  // namespace

TEST_CASE("fixed_decimal: what glibc's %.*f writes") {
  SUBCASE("ties round to even on the exact value, as glibc does") {
    for (double v : {0.5, 1.5, 2.5, -2.5, 0.125, 0.375, 0.0078125, 0.0234375, 1e-6 * 0.5, 2.675, 1.005})
      for (int p = 0; p <= 18; ++p) check(v, p);
  }
  SUBCASE("zeros, signs, subnormals and the ends of the range") {
    const double values[] = {0.0, -0.0, 1e-7, -1e-7, -4e-7, 5e-7, -5e-7, 9.9999995e-7,
                             std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::min(),
                             0x1p53 - 1, -(0x1p53 - 1), 0x1p52 + 0.5, 999999.9999995, 0.1, 0.3, 1.0 / 3};
    for (double v : values)
      for (int p = 0; p <= 18; ++p) check(v, p);
  }
  SUBCASE("random doubles of every binade below 2^53, every precision") {
    std::mt19937_64 bits(20261203);  // the engine's output is specified; no distribution used
    for (int i = 0; i < 200000; ++i) {
      const std::uint64_t word = bits();
      // sign, an exponent from 2^-80 to 2^52, a random fraction
      const std::uint64_t exponent = 1023 - 80 + (word >> 11) % 133;
      const double v = epure::portable::bit_cast<double>((word & (std::uint64_t{1} << 63)) | (exponent << 52) |
                                                         (bits() & ((std::uint64_t{1} << 52) - 1)));
      check(v, static_cast<int>(word % 19));
    }
  }
  SUBCASE("numbers of a page: hundredths and thousandths of points, exact and not") {
    for (int i = -200000; i <= 200000; i += 7) {
      check(i / 1000.0, 6);
      check(i / 1000.0, 3);
      check(i * 0.001, 18);
    }
  }
  SUBCASE("what the path leaves to printf") {
    char text[fixed_decimal_max];
    CHECK_FALSE(fixed_decimal(0x1p53, 6, text));
    CHECK_FALSE(fixed_decimal(-0x1p60, 6, text));
    CHECK_FALSE(fixed_decimal(std::numeric_limits<double>::infinity(), 6, text));
    CHECK_FALSE(fixed_decimal(std::nan(""), 6, text));
    CHECK_FALSE(fixed_decimal(1.0, 19, text));
    CHECK_FALSE(fixed_decimal(1.0, -1, text));
    CHECK(ours(-(0x1p53 - 1), 18).size() == fixed_decimal_max);  // the longest text it writes
  }
}

TEST_CASE("cairo_printf: cairo's numbers reach the fast path, other formats reach glibc") {
  const std::uint64_t before = cairo_printf_fast_calls();
  std::string pdf;
  test::PdfInto into(pdf, 100, 100);
  cairo_pdf_surface_restrict_to_version(into.surface(), CAIRO_PDF_VERSION_1_5);
  cairo_t* cr = into.cr();
  cairo_move_to(cr, 10.125, 20.0625);
  cairo_line_to(cr, 0.0123456789, 90.5);
  cairo_stroke(cr);
  REQUIRE(into.finish() == CAIRO_STATUS_SUCCESS);
  CHECK(cairo_printf_fast_calls() > before);
  CHECK(pdf.rfind("%PDF-1.5", 0) == 0);

  // the fortified entry point itself, as a fortified caller reaches it (through a pointer, so
  // that the compiler cannot fold the call)
  int (*volatile snprintf_chk)(char*, std::size_t, int, std::size_t, const char*, ...) = &__snprintf_chk;
  char text[16];
  CHECK(snprintf_chk(text, sizeof text, 1, sizeof text, "%.*f", 3, 1.0005) == 5);
  CHECK(std::string(text) == "1.000");  // 1.0005 is 1.000499999… in binary
  CHECK(snprintf_chk(text, 4, 1, sizeof text, "%d", -12345) == 6);
  CHECK(std::string(text) == "-12");  // cut at the size given, the length of the whole returned
  CHECK(snprintf_chk(text, sizeof text, 1, sizeof text, "%s-%d", "ab", 7) == 4);
  CHECK(std::string(text) == "ab-7");
  CHECK(snprintf_chk(text, sizeof text, 1, sizeof text, "%f", 1e300) == 308);  // to glibc
}
