// Numbers as sheets print them, in English and French.
#include <doctest/doctest.h>

#include "exercises/numbers.h"

TEST_CASE("English and French number forms") {
  const auto en = epure::NumberStyle::for_language("en");
  const auto fr = epure::NumberStyle::for_language("fr");
  CHECK(en.datum(1.5) == "1.5");
  CHECK(fr.datum(1.5) == "1,5");
  CHECK(en.datum(3) == "3");
  CHECK(en.datum(-2.25) == "\u22122.25");
  CHECK(en.rounded(2.1, 2) == "2.10");
  CHECK(fr.rounded(2.1, 2) == "2,10");
  CHECK(en.rounded(-0.001, 2) == "0.00");  // no "−0.00"
  CHECK(en.point(1.5, -2) == "(1.5, \u22122)");
  CHECK(fr.point(1.5, -2) == "(1,5\u00a0; \u22122)");
  CHECK(en.rounded_point(1.0 / 3, 2.0 / 3, 2) == "(0.33, 0.67)");
}
