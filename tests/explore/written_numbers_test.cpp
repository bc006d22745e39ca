// The numbers of an instance as written, carried through the core's rewriting
// (src/explore/written_numbers.h).
#include <doctest/doctest.h>

#include <string>

#include "explore/written_numbers.h"

using epure::explore::with_written_numbers;

TEST_CASE("written numbers: a number of the same double keeps its text; the others, the order and the rest stay") {
  SUBCASE("1. more digits than a double holds, in a field and in an array") {
    CHECK(with_written_numbers(R"({"kind":"ray_circle","A":[0.1,2],"u":[1,0],"C":[0,0],"r":3})",
                               R"({"r":3.0000000000000000001,"A":[0.1000000000000000055511151231257827,2],"kind":"ray_circle","u":[1,0],"C":[0,0]})") ==
          R"({"kind":"ray_circle","A":[0.1000000000000000055511151231257827,2],"u":[1,0],"C":[0,0],"r":3.0000000000000000001})");
  }
  SUBCASE("2. a moved number (another double) is the canonical one") {
    CHECK(with_written_numbers(R"({"kind":"projection","A":[0.25,1],"B":[2,0],"C":[1,5]})",
                               R"({"kind":"projection","A":[1.00000000000000000001,1],"B":[2,0],"C":[1,5]})") ==
          R"({"kind":"projection","A":[0.25,1],"B":[2,0],"C":[1,5]})");
  }
  SUBCASE("3. exponent forms and -0: the text written, but -0 is not 0") {
    CHECK(with_written_numbers(R"({"u":[1e-07,0],"v":[-0.0,2]})", R"({"u":[1.0e-7,-0.0],"v":[0.0,2E0]})") ==
          R"({"u":[1.0e-7,0],"v":[-0.0,2E0]})");
  }
  SUBCASE("4. a field the written line lacks, or gives in another shape, keeps the canonical text") {
    CHECK(with_written_numbers(R"({"A":[1.5,2],"r":0.5})", R"({"A":1.50,"s":0.50})") == R"({"A":[1.5,2],"r":0.5})");
  }
  SUBCASE("5. written text that is no JSON object: the canonical text as it is") {
    CHECK(with_written_numbers(R"({"r":0.5})", "not json") == R"({"r":0.5})");
    CHECK(with_written_numbers(R"({"r":0.5})", "[0.50]") == R"({"r":0.5})");
  }
  SUBCASE("6. strings with quotes and colons are copied, not read as fields") {
    CHECK(with_written_numbers(R"({"kind":"a\":[1","x":0.5})", R"({"kind":"a\":[1","x":0.50})") ==
          R"({"kind":"a\":[1","x":0.50})");
  }
}
