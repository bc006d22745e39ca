#include "exercises/numbers.h"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <string>

namespace epure {

namespace {

// Rounds half away from zero at `decimals` and prints with exactly that many decimals. fmt's
// fixed format rounds the binary value correctly (2.675 is 2.67499…: 2.67), which is what a
// calculator shows too; we only fold −0.00 into 0.00.
std::string fixed(double x, int decimals) {
  constexpr long long kPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000};
  if (decimals >= 0 && decimals < static_cast<int>(std::size(kPow10))) {
    // x·10^d is off the product by half an ulp at most: when that lands within a quarter of an
    // integer n (far below 2^50), the exact x·10^d is nearer to n than to any other, and n is
    // the correct rounding fmt would print. Only values near a half go to fmt.
    const long long p = kPow10[decimals];
    const double y = x * static_cast<double>(p), n = std::nearbyint(y);
    if (std::abs(y - n) < 0.25 && std::abs(n) < 0x1p50) {
      const auto m = static_cast<long long>(std::abs(n));
      std::string s = n < 0 ? "-" : "";  // −0.00 is folded into 0.00, as below
      s += std::to_string(m / p);
      if (decimals > 0) {
        const std::string frac = std::to_string(m % p);
        s += '.';
        s.append(static_cast<std::size_t>(decimals) - frac.size(), '0');
        s += frac;
      }
      return s;
    }
  }
  std::string s = fmt::format("{:.{}f}", x, decimals);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string trim_zeros(std::string s) {
  if (s.find('.') == std::string::npos) return s;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

std::string NumberStyle::localise(std::string_view ascii) const {
  std::string out;
  out.reserve(ascii.size() + 2);
  for (std::size_t i = 0; i < ascii.size(); ++i) {
    char c = ascii[i];
    if (c == '-' && (i == 0 || ascii[i - 1] != 'e')) out += "\u2212";
    else if (c == '.' && decimal_comma) out += ',';
    else out += c;
  }
  return out;
}

std::string NumberStyle::datum(double x, int max_decimals) const {
  return localise(trim_zeros(fixed(x, max_decimals)));
}

std::string NumberStyle::rounded(double x, int decimals) const {
  return localise(fixed(x, decimals));
}

std::string NumberStyle::point(double x, double y, int max_decimals) const {
  return fmt::format("({}{} {})", datum(x, max_decimals), decimal_comma ? "\u00a0;" : ",",
                     datum(y, max_decimals));
}

std::string NumberStyle::point(double x, double y, double z, int max_decimals) const {
  const char* sep = decimal_comma ? "\u00a0;" : ",";
  return fmt::format("({}{} {}{} {})", datum(x, max_decimals), sep, datum(y, max_decimals), sep,
                     datum(z, max_decimals));
}

std::string NumberStyle::rounded_point(double x, double y, int decimals) const {
  return fmt::format("({}{} {})", rounded(x, decimals), decimal_comma ? "\u00a0;" : ",",
                     rounded(y, decimals));
}

std::string NumberStyle::rounded_point(double x, double y, double z, int decimals) const {
  const char* sep = decimal_comma ? "\u00a0;" : ",";
  return fmt::format("({}{} {}{} {})", rounded(x, decimals), sep, rounded(y, decimals), sep,
                     rounded(z, decimals));
}

}  // namespace epure
