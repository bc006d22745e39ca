#include "render/cairo_printf.h"

#include <langinfo.h>

#include <cfenv>
#include <charconv>
#include <cstdarg>
#include <cstddef>
#include <cstring>
#include <optional>

#include "render/fixed_decimal.h"

extern "C" {
// glibc's, exported for fortified callers.
int __vsnprintf_chk(char* s, std::size_t maxlen, int flag, std::size_t slen, const char* format, va_list args);
[[noreturn]] void __chk_fail(void);
int __snprintf_chk(char* s, std::size_t maxlen, int flag, std::size_t slen, const char* format, ...);
}

namespace epure::render {
namespace {

thread_local std::uint64_t fast_calls = 0;

enum class NumberFormat { other, fixed_6, fixed_18, fixed_star, decimal_int };

// Read character by character rather than compared with strcmp: this runs for every number of
// every page, and all but a few of cairo's calls are one of these formats. (The && stop at
// the format's end: nothing past its NUL is read.)
NumberFormat classify(const char* format) {
  if (format[0] != '%') return NumberFormat::other;
  switch (format[1]) {
    case 'f': return format[2] == '\0' ? NumberFormat::fixed_6 : NumberFormat::other;
    case 'd': return format[2] == '\0' ? NumberFormat::decimal_int : NumberFormat::other;
    case '.':
      if (format[2] == '*' && format[3] == 'f' && format[4] == '\0') return NumberFormat::fixed_star;
      if (format[2] == '1' && format[3] == '8' && format[4] == 'f' && format[5] == '\0') return NumberFormat::fixed_18;
      return NumberFormat::other;
    default: return NumberFormat::other;
  }
}

// What printf would write for `format` and its one argument, or nullopt if it must write it.
std::optional<std::size_t> format_number(NumberFormat format, va_list args, char* text) {
  switch (format) {
    case NumberFormat::decimal_int: {
      const int value = va_arg(args, int);
      return static_cast<std::size_t>(std::to_chars(text, text + fixed_decimal_max, value).ptr - text);
    }
    case NumberFormat::fixed_6: return fixed_decimal(va_arg(args, double), 6, text);
    case NumberFormat::fixed_18: return fixed_decimal(va_arg(args, double), 18, text);
    case NumberFormat::fixed_star: {
      const int precision = va_arg(args, int);
      return fixed_decimal(va_arg(args, double), precision, text);
    }
    case NumberFormat::other: break;
  }
  return std::nullopt;
}

// printf's decimal point is the locale's, and it rounds in the current rounding mode.
bool c_numbers() {
  const char* point = nl_langinfo(RADIXCHAR);
  return point[0] == '.' && point[1] == '\0' && std::fegetround() == FE_TONEAREST;
}

}  // namespace

std::uint64_t cairo_printf_fast_calls() noexcept { return fast_calls; }

}  // namespace epure::render

using namespace epure::render;

extern "C" int __snprintf_chk(char* s, std::size_t maxlen, int flag, std::size_t slen, const char* format, ...) {
  va_list args;
  va_start(args, format);
  const NumberFormat kind = classify(format);
  if (kind != NumberFormat::other && c_numbers()) {
    if (slen < maxlen) __chk_fail();  // as glibc's: the caller's buffer is smaller than it says
    // Straight into the caller's buffer when the longest number and its NUL fit (cairo's is
    // 512 bytes), else through a buffer of our own, cut as snprintf cuts.
    char own[fixed_decimal_max];
    const bool direct = maxlen > fixed_decimal_max;
    char* text = direct ? s : own;
    va_list copy;
    va_copy(copy, args);
    const std::optional<std::size_t> length = format_number(kind, copy, text);
    va_end(copy);
    if (length) {
      if (direct) {
        s[*length] = '\0';
      } else if (maxlen > 0) {
        const std::size_t kept = *length < maxlen ? *length : maxlen - 1;
        std::memcpy(s, text, kept);
        s[kept] = '\0';
      }
      va_end(args);
      ++fast_calls;
      return static_cast<int>(*length);
    }
  }
  const int result = __vsnprintf_chk(s, maxlen, flag, slen, format, args);
  va_end(args);
  return result;
}
