// The solve contract's dispatch and line reader: the contract's kinds are the registry's (one list
// of kinds), each read by its schema (a missing field named in the schema's order, whatever the
// compiler's order of evaluation), the preamble in space found by its dimension, and a line read
// to the same fields flat or through nlohmann::json.
#include <doctest/doctest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "exercises/exercise.h"
#include "solve/line_reader.h"
#include "solve/solve.h"

namespace {

using namespace epure;

std::string solved(std::string_view line) {
  fmt::memory_buffer out;
  solve::solve_line(line, out);
  return std::string(out.data(), out.size());
}

}  // namespace

TEST_CASE("solve: the contract's kinds are the registry's, in its order") {
  const std::vector<std::string_view> expected = {"vectors",    "projection",    "segments",
                                                  "ray_circle", "ray_square",    "ray_ellipse",
                                                  "ray_rectangle", "ray_sphere", "ray_cube"};
  CHECK(solve::contract_kinds() == expected);
  for (const ExerciseKind* kind : all_kinds()) {
    CAPTURE(kind->name());
    bool listed = false;
    for (auto name : solve::contract_kinds()) listed = listed || name == kind->contract_kind();
    CHECK(listed);
  }
  CHECK(solved(R"({"kind":"ray_torus"})") == R"({"error":"field 'kind': unknown kind 'ray_torus'"})");
}

TEST_CASE("solve: vectors in the plane and in space, by the dimension of u") {
  CHECK(solved(R"({"kind":"vectors","u":[1,0],"v":[0,1]})").find("\"angle_deg\":90") != std::string::npos);
  const std::string space = solved(R"({"kind":"vectors","u":[1,0,0],"v":[0,1,0]})");
  CHECK(space.find("\"cross\":[0,0,1]") != std::string::npos);
  CHECK(space.find("\"orthogonal\":true") != std::string::npos);
  // u decides: in space, v must be too
  CHECK(solved(R"({"kind":"vectors","u":[1,2,3],"v":[1,2]})") ==
        R"({"error":"field 'v': expected 3 numbers, got 2"})");
  CHECK(solved(R"({"kind":"vectors","v":[1,2,3]})") == R"({"error":"field 'u': missing"})");
}

TEST_CASE("solve: fields are read in the schema's order, the first one off is named") {
  CHECK(solved(R"({"kind":"projection","B":[1,0]})") == R"({"error":"field 'A': missing"})");
  CHECK(solved(R"({"kind":"projection","A":[0,0]})") == R"({"error":"field 'B': missing"})");
  CHECK(solved(R"({"kind":"segments","A":[0,0],"B":[1,1]})") == R"({"error":"field 'C': missing"})");
  CHECK(solved(R"({"kind":"ray_circle","A":[0,0],"u":[1,0],"C":[3,0],"r":"x"})") ==
        R"({"error":"field 'r': expected a number, got a string"})");
  CHECK(solved(R"({"kind":"ray_ellipse","A":[0,0],"u":[1,0],"C":[3,0],"radii":[1,2,3],"angle":0})") ==
        R"({"error":"field 'radii': expected 2 numbers, got 3"})");
  CHECK(solved(R"({"kind":"ray_circle","A":[0,0],"u":[0,0],"C":[3,0],"r":1})").rfind(R"({"error":"field 'u': )", 0) == 0);
}

TEST_CASE("solve: a line reads to the same fields flat and through nlohmann::json") {
  for (const char* line : {R"({"kind":"ray_circle","A":[-5,1],"u":[2,0],"C":[0,0],"r":3})",
                           R"({"kind":"ray_cube","A":[3,0.5,0.25],"u":[-1,-1e-3,0]})"}) {
    CAPTURE(line);
    const solve::LineReader flat(line);
    const nlohmann::json j = nlohmann::json::parse(line);
    const auto parsed = solve::fields_of(j);
    REQUIRE(flat.fields().size() == parsed.size());
    for (const auto& f : parsed) {
      const solve::Value* v = solve::find(flat.fields(), f.key);
      REQUIRE(v);
      CHECK(v->type == f.value.type);
      CHECK(geo::same_value(v->number, f.value.number));
      CHECK(v->size == f.value.size);
      for (std::size_t i = 0; i < v->size; ++i) CHECK(geo::same_value(v->items[i], f.value.items[i]));
    }
  }
  // Either reader keeps each number's text: the decisions are the decimals' (README, "What a
  // number means"). The issue's segments, parallel as written and not as doubles, flat and
  // through nlohmann (an escape in a key), and a number longer than a double's digits.
  const std::string parallel = R"({"kind":"segments","intersects":false,"reason":"parallel"})";
  CHECK(solved(R"({"kind":"segments","A":[9.217,-2.43],"B":[8.593,-1.674],"C":[8.547,-2.17],"D":[7.247,-0.595]})") == parallel);
  CHECK(solved(R"({"k\u0069nd":"segments","A":[9.217,-2.43],"B":[8.593,-1.674],"C":[8.547,-2.17],"D":[7.247,-0.595]})") == parallel);
  for (const char* line : {R"({"kind":"vectors","u":[1,0.10000000000000000000001],"v":[10,1]})",
                           R"({"kind":"vectors","u":[1,0.10000000000000000000001],"v":[10,1],"x":"\u00e9"})"}) {
    CAPTURE(line);
    const std::string out = solved(line);
    // 1 − 10·(0.1 + 1e-23) = −1e-22, not 0, and exactly rounded: the product is made of the
    // 23rd digit, beyond the double-double of the decimals (−1.000000000004848e-22 from it)
    CHECK(out.find(R"("cross":-1e-22,)") != std::string::npos);
  }
  // not flat (an escape): read by nlohmann, the same result
  CHECK(solved(R"({"kind":"ray_c\u0069rcle","A":[-5,1],"u":[2,0],"C":[0,0],"r":3})") ==
        solved(R"({"kind":"ray_circle","A":[-5,1],"u":[2,0],"C":[0,0],"r":3})"));
  CHECK(solved("[1,2]") == R"({"error":"line: expected a JSON object"})");
  // a number whose exact arithmetic would grow without bound is refused, at once (the fuzzer's
  // slow unit: 56e-0838478), flat or not; 1e-1400 is still a number
  const std::string beyond =
      R"({"error":"field 'C': more than 1000 significant digits, or a digit below 1e-1500: beyond exact decisions"})";
  CHECK(solved(R"({"kind":"ray_circle","A":[0,0],"u":[1,0],"C":[3,56e-0838478],"r":1})") == beyond);
  CHECK(solved(R"({"kind":"ray_circle","A":[0,0],"u":[1,0],"C":[3,56e-0838478],"r":1,"x":"\u00e9"})") == beyond);
  CHECK(solved(R"({"kind":"ray_circle","A":[0,0],"u":[1,0],"C":[3,0.)" + std::string(1200, '1') + R"(],"r":1})") == beyond);
  CHECK(solved(R"({"kind":"ray_circle","A":[0,0],"u":[1,0],"C":[3,1e-1400],"r":1})").find("\"hit\":true") != std::string::npos);
  CHECK(solved("{").rfind(R"({"error":"line: not valid JSON)", 0) == 0);
}

// The one limit of exact decisions (solve/number_span.h): a number whose square, scaled like the
// largest it is scaled with, is below 2^-969 makes products underflow; that line is refused,
// naming the field, and a figure small as a whole is answered.
TEST_CASE("solve: a subnormal beside ordinary numbers is refused, a tiny figure answered") {
  SUBCASE("1. a subnormal coordinate beside 3: refused, the field named") {
    const std::string out = solved(R"({"kind":"segments","A":[0,0],"B":[3,1e-320],"C":[0,1],"D":[3,2]})");
    CHECK(out.rfind(R"({"error":"field 'B': 1e-320 beside 3 )", 0) == 0);
    CHECK(out.find("underflow") != std::string::npos);
  }
  SUBCASE("2. the whole figure near 1e-310: scaled with its numbers, answered as at unit size") {
    const std::string tiny = solved(R"({"kind":"segments","A":[0,0],"B":[3e-310,1e-310],"C":[0,1e-310],"D":[3e-310,0]})");
    const std::string unit = solved(R"({"kind":"segments","A":[0,0],"B":[3,1],"C":[0,1],"D":[3,0]})");
    CHECK(tiny.find("\"error\"") == std::string::npos);
    CHECK(tiny.find("\"t_ab\":0.5") != std::string::npos);
    CHECK(unit.find("\"t_ab\":0.5") != std::string::npos);
  }
  SUBCASE("3. the bound: 2^-484 of the largest is kept, 2^-485 refused") {
    // (2^-484)² = 2^-968 ≥ 2^-969; (2^-485)² = 2^-970 below it
    const std::string kept = fmt::format(R"({{"kind":"projection","A":[0,0],"B":[1,0],"C":[0.5,{}]}})", 0x1p-484);
    const std::string refused = fmt::format(R"({{"kind":"projection","A":[0,0],"B":[1,0],"C":[0.5,{}]}})", 0x1p-485);
    CHECK(solved(kept).find("\"error\"") == std::string::npos);
    CHECK(solved(refused).rfind(R"({"error":"field 'C': )", 0) == 0);
  }
  SUBCASE("4. a direction is scaled alone, a figure's point with its size") {
    // u = (1e-310, 1e-310) beside A at 1: u is rescaled on its own, answered
    CHECK(solved(R"({"kind":"ray_circle","A":[-5,0],"u":[1e-310,1e-310],"C":[0,0],"r":1})").find("\"error\"") ==
          std::string::npos);
    // u's own components 1 and 1e-310: refused
    CHECK(solved(R"({"kind":"ray_circle","A":[-5,0],"u":[1,1e-310],"C":[0,0],"r":1})").rfind(
              R"({"error":"field 'u': )", 0) == 0);
    // the square's half side 1 is a size of its figure: A = (1e-320, 0.5) is refused
    CHECK(solved(R"({"kind":"ray_square","A":[1e-320,0.5],"u":[1,0]})").rfind(R"({"error":"field 'A': )", 0) == 0);
    // an angle is no length: 1e-320 degrees beside radii of 1 is answered
    CHECK(solved(R"({"kind":"ray_ellipse","A":[-5,0],"u":[1,0],"C":[0,0],"radii":[2,1],"angle":1e-320})")
              .find("\"error\"") == std::string::npos);
  }
  SUBCASE("5. the kind's own refusal says more, and comes first") {
    CHECK(solved(R"({"kind":"ray_circle","A":[-5,1],"u":[1,0],"C":[0,0],"r":-1e-300})") ==
          R"({"error":"field 'r': must be > 0"})");
  }
}
