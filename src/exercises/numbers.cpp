#include "exercises/numbers.h"

#include <fmt/format.h>

#include <cmath>

namespace epure {

namespace {

// Rounds half away from zero at `decimals` and prints with exactly that many decimals. fmt's
// fixed format rounds the binary value correctly (2.675 is 2.67499…: 2.67), which is what a
// calculator shows too; we only fold −0.00 into 0.00.
std::string fixed(double x, int decimals) {
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
