#pragma once
// Numbers as a sheet prints them, per language: English "2.17" and "(1.5, 2)"; French "2,17" and
// "(1,5 ; 2)" (decimal comma, and a semicolon between coordinates so the comma is not ambiguous).
// Negative numbers take a true minus sign (U+2212). Answers are rounded to nearest from their
// binary value at the asked number of decimals (as a calculator shows them), and trailing zeros
// are dropped for data (which is exact) but kept for answers ("2.10" shows the precision asked).
#include <string>
#include <string_view>

namespace epure {

struct NumberStyle {
  bool decimal_comma = false;

  static NumberStyle for_language(std::string_view language) {
    return NumberStyle{language == "fr"};
  }

  // A datum: at most `max_decimals`, trailing zeros dropped ("3", "0.5", "−1.25").
  std::string datum(double x, int max_decimals = 6) const;
  // An answer rounded to exactly `decimals` ("2.17", "0.50").
  std::string rounded(double x, int decimals) const;
  // A point of data: "(1.5, −2)" / "(1,5 ; −2)".
  std::string point(double x, double y, int max_decimals = 6) const;
  std::string point(double x, double y, double z, int max_decimals = 6) const;
  // A point of answers, each coordinate rounded to `decimals`.
  std::string rounded_point(double x, double y, int decimals) const;
  std::string rounded_point(double x, double y, double z, int decimals) const;
  // Replaces '.' by ',' and '-' by '−' in an ASCII number ("1.5e-3" keeps its e).
  std::string localise(std::string_view ascii_number) const;
};

}  // namespace epure
