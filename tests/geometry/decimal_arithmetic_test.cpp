// The exact decimal arithmetic of the core (big_integer.h, decimal.h): a few cases worked by
// hand, then the 1,000 cases of decimal_arithmetic.txt, which Python's exact integers and
// fractions answered (tests/tools/decimal_arithmetic.py: an independent reference), and the line
// reader's fast decimals (decimal_of_digits) against read_decimal on the same texts.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "geometry/decimal.h"
#include "solve/line_reader.h"

using namespace epure::geo;
using exact::BigInteger;
using exact::ExactDecimal;

namespace {

// A decimal text as an exact value, read here on its own (not by decimal.cpp): sign, digits with
// the point skipped, and the power of ten of the last digit.
ExactDecimal exact_text(const std::string& text) {
  std::size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) i = 1;
  std::string digits;
  long long fraction = -1;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    if (text[i] == '.') {
      fraction = 0;
      continue;
    }
    digits += text[i];
    if (fraction >= 0) ++fraction;
  }
  long long e = i < text.size() ? std::stoll(text.substr(i + 1)) : 0;
  if (fraction > 0) e -= fraction;
  const BigInteger m = BigInteger::from_digits(digits);
  return {negative ? -m : m, static_cast<int>(e)};
}

bool equal(const ExactDecimal& a, const ExactDecimal& b) { return (a - b).sign() == 0; }

// "M E": the value M·10^E, M without trailing zeros ("0 0" for zero), as the script writes it.
ExactDecimal exact_form(const std::string& m, const std::string& e) {
  return {BigInteger::from_digits(m[0] == '-' ? m.substr(1) : m) * BigInteger(m[0] == '-' ? -1 : 1), std::stoi(e)};
}

double hex(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

// The decimal of TEXT as `epure solve` reads it, through its line reader.
Decimal solve_reads(const std::string& text) {
  static std::string line;  // the decimal may keep a view of its text
  line = R"({"r":)" + text + "}";
  const epure::solve::LineReader reader(line);
  return reader.fields()[0].value.number;
}

}  // namespace

TEST_CASE("geometry/big_integer: sums, products, powers and digits") {
  CHECK(BigInteger().sign() == 0);
  CHECK(BigInteger(-7).to_string() == "-7");
  CHECK((BigInteger(5) - BigInteger(5)).sign() == 0);
  CHECK((-BigInteger(0)).sign() == 0);  // no negative zero
  const BigInteger max64 = BigInteger::from_unsigned(~std::uint64_t(0));
  CHECK((max64 + BigInteger(1)).to_string() == "18446744073709551616");
  CHECK((max64 * max64).to_string() == "340282366920938463426481119284349108225");
  CHECK(BigInteger(3).times_pow10(20).to_string() == "300000000000000000000");
  CHECK(BigInteger(1).times_pow2(100).to_string() == "1267650600228229401496703205376");
  CHECK(BigInteger(1).times_pow5(30).to_string() == "931322574615478515625");
  CHECK(BigInteger::from_digits("000123").to_string() == "123");
}

TEST_CASE("geometry/decimal: a number is the decimal it writes") {
  // 0.1 is one tenth: its double is 0.1000000000000000055511151231257827…, the rest −5.55e-18
  const Decimal tenth = read_decimal("0.1", 0.1);
  CHECK(tenth.hi == 0.1);
  CHECK(tenth.lo == doctest::Approx(-5.551115123125783e-18).epsilon(1e-15));
  CHECK(equal(exact::exact_value(tenth), ExactDecimal{BigInteger(1), -1}));
  // a double's exact decimal is itself: no rest
  CHECK(read_decimal("0.5", 0.5).lo == 0);
  CHECK(read_decimal("0.1000000000000000055511151231257827021181583404541015625", 0.1).lo == 0);
  // 9.217 − 8.593 and 8.547 − 7.247 as written: the issue's segments are parallel
  const auto d = [](const char* t) { return exact_text(t); };
  const ExactDecimal cross = (d("8.593") - d("9.217")) * (d("-0.595") - d("-2.17")) -
                             (d("-1.674") - d("-2.43")) * (d("7.247") - d("8.547"));
  CHECK(cross.sign() == 0);
  CHECK(compare(read_decimal("0.3", 0.3), Decimal::of(0.3)) == 1);  // 0.3 > its double
  CHECK(same_value(read_decimal("2.50", 2.5), read_decimal("25e-1", 2.5)));
}

TEST_CASE("geometry/decimal: the cases Python's exact arithmetic answered") {
  std::ifstream in(EPURE_SOURCE_DIR "/tests/geometry/decimal_arithmetic.txt");
  REQUIRE(in);
  std::string line;
  int count = 0;
  while (std::getline(in, line)) {
    CAPTURE(line);
    std::istringstream fields(line);
    std::string op, a, b;
    fields >> op >> a >> b;
    ++count;
    if (op == "read") {
      std::string rest;
      fields >> rest;
      const double hi = hex(b);
      const Decimal x = read_decimal(a, hi);
      CHECK(x.hi == hi);
      // hi + lo is the decimal within the bound the Decimal states, and lo the rounded rest's
      // neighbour at most
      const ExactDecimal off = exact::exact_value(x) - exact::exact_value(hi) - exact::exact_value(x.lo);
      const ExactDecimal bound = exact::exact_value(x.error());
      CHECK((off.sign() >= 0 ? bound - off : bound + off).sign() >= 0);
      CHECK(std::abs(x.lo - hex(rest)) <= x.error() + std::abs(hex(rest)) * 0x1p-52);
      CHECK(equal(exact::exact_value(x), exact_text(a)));
      // epure solve's reading of the same text: the same double and rest, bit for bit
      const Decimal solved = solve_reads(a);
      CHECK(solved.hi == x.hi);
      CHECK(solved.lo == x.lo);
      CHECK(same_value(solved, x));
    } else if (op == "add" || op == "mul" || op == "pow2") {
      std::string m, e;
      fields >> m >> e;
      const ExactDecimal expected = exact_form(m, e);
      if (op == "add") CHECK(equal(exact_text(a) + exact_text(b), expected));
      if (op == "mul") CHECK(equal(exact_text(a) * exact_text(b), expected));
      if (op == "pow2") CHECK(equal(exact::times_pow2(exact_text(a), std::stoi(b)), expected));
    } else if (op == "sign") {
      std::string c, dd;
      int s = 0;
      fields >> c >> dd >> s;
      CHECK((exact_text(a) * exact_text(b) - exact_text(c) * exact_text(dd)).sign() == s);
    } else {
      FAIL("unknown case");
    }
  }
  CHECK(count == 1000);
}
