#include "render/fixed_decimal.h"

#include <charconv>
#include <cstdint>
#include <cstring>

#include "support/portable.h"

namespace epure::render {
namespace {

__extension__ typedef unsigned __int128 u128;  // GCC and clang both have it

constexpr std::uint64_t power_of_ten[19] = {
    1ull,
    10ull,
    100ull,
    1000ull,
    10000ull,
    100000ull,
    1000000ull,
    10000000ull,
    100000000ull,
    1000000000ull,
    10000000000ull,
    100000000000ull,
    1000000000000ull,
    10000000000000ull,
    100000000000000ull,
    1000000000000000ull,
    10000000000000000ull,
    100000000000000000ull,
    1000000000000000000ull,
};

// The decimal digits of n, most significant first, at out (room for 20); returns their count.
std::size_t write_digits(std::uint64_t n, char* out) {
  return static_cast<std::size_t>(std::to_chars(out, out + 20, n).ptr - out);
}

}  // namespace

std::optional<std::size_t> fixed_decimal(double value, int precision, char* out) noexcept {
  if (precision < 0 || precision > 18) return std::nullopt;
  const auto bits = portable::bit_cast<std::uint64_t>(value);
  const bool negative = (bits >> 63) != 0;
  const auto biased_exponent = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  // value = ±mantissa · 2^exponent exactly.
  std::uint64_t mantissa;
  int exponent;
  if (biased_exponent == 0) {
    mantissa = fraction;
    exponent = -1074;
  } else {
    mantissa = fraction | (std::uint64_t{1} << 52);
    exponent = biased_exponent - 1075;
  }
  // |value| < 2^53 ⇔ exponent ≤ 0 (a normal mantissa is at least 2^52); NaN and the infinities
  // have the largest exponent.
  if (exponent > 0) return std::nullopt;

  // round(|value| · 10^precision), exactly: mantissa · 10^p < 2^53 · 2^60 fits in 128 bits.
  const u128 scaled = static_cast<u128>(mantissa) * power_of_ten[precision];
  const int shift = -exponent;
  u128 rounded;
  if (shift == 0) {
    rounded = scaled;
  } else if (shift >= 114) {
    rounded = 0;  // scaled < 2^113 ≤ half of 2^shift: rounds down
  } else {
    rounded = scaled >> shift;
    const u128 remainder = scaled - (rounded << shift);
    const u128 half = u128{1} << (shift - 1);
    if (remainder > half || (remainder == half && (rounded & 1) != 0)) ++rounded;
  }

  // The integer part is at most 2^53 (after rounding up), the decimals below 10^18. cairo's
  // numbers are below 2^64 once scaled, and mostly have 6 decimals: a division by a constant.
  const std::uint64_t unit = power_of_ten[precision];
  std::uint64_t integer_part, decimals;
  if ((rounded >> 64) != 0) {
    integer_part = static_cast<std::uint64_t>(rounded / unit);
    decimals = static_cast<std::uint64_t>(rounded % unit);
  } else if (precision == 6) {
    integer_part = static_cast<std::uint64_t>(rounded) / 1000000;
    decimals = static_cast<std::uint64_t>(rounded) % 1000000;
  } else {
    integer_part = static_cast<std::uint64_t>(rounded) / unit;
    decimals = static_cast<std::uint64_t>(rounded) % unit;
  }
  std::size_t length = 0;
  if (negative) out[length++] = '-';
  length += write_digits(integer_part, out + length);
  if (precision > 0) {
    out[length++] = '.';
    char digits[20];
    const std::size_t count = write_digits(decimals, digits);
    const auto zeros = static_cast<std::size_t>(precision) - count;
    std::memset(out + length, '0', zeros);
    std::memcpy(out + length + zeros, digits, count);
    length += static_cast<std::size_t>(precision);
  }
  return length;
}

}  // namespace epure::render
