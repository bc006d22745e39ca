#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "scan/layout_file.h"

using namespace epure::scan;
using nlohmann::json;

namespace {

// layout.json's sheet as it was written before the direct writer: nlohmann's tree, dump(1). The
// direct writer must give these bytes for any sheet (README, "layout.json": the format does not
// change).
std::string by_nlohmann(const SheetLayout& s, bool first) {
  auto rect = [](const Rect& r) { return json::array({r.x, r.y, r.width, r.height}); };
  json pages = json::array();
  for (const auto& p : s.pages) {
    json fields = json::array();
    for (const auto& f : p.fields) {
      json cells = json::array();
      for (const auto& c : f.cells) cells.push_back(rect(c));
      json o = {{"question", f.question}, {"type", f.type == FieldType::comb ? "comb" : "tick"}, {"cells", cells}};
      if (f.type == FieldType::comb) {
        o["sign"] = f.sign;
        o["decimals"] = f.decimals;
      } else {
        o["values"] = f.values;
        o["select"] = f.multiple ? "any" : "one";
      }
      fields.push_back(std::move(o));
    }
    json marks = json::array();
    for (const auto& m : p.marks) marks.push_back(json::array({m.x, m.y}));
    pages.push_back({{"page", p.page}, {"width", p.width}, {"height", p.height}, {"marks", marks},
                     {"mark_size", p.mark_size}, {"code", rect(p.code)}, {"fields", fields}});
  }
  json sheet = {{"sheet", s.sheet}, {"pages", pages}};
  if (s.student) sheet["student"] = {{"number", s.student->number}, {"name", s.student->name}};
  return (first ? "" : ",\n") + sheet.dump(1);
}

// Doubles of every sort nlohmann writes differently: page coordinates (sums of lengths in mm
// converted to points, as layout computes them), integral values (`14.0`), any bit pattern
// (exponent forms, subnormals), signed zeros, tiny and huge powers of ten, non-finite values.
double random_double(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  switch (rng() % 8) {
    case 0: return 72.0 / 25.4 * std::round(unit(rng) * 2970) / 10 + 14 * static_cast<double>(rng() % 30);
    case 1: return static_cast<double>(static_cast<std::int64_t>(rng() % 2000000) - 1000000);
    case 2: {
      const double d = std::bit_cast<double>(static_cast<std::uint64_t>(rng()));
      return d;  // NaN and infinities among them
    }
    case 3: return (rng() % 2 ? -0.0 : 0.0);
    case 4: return std::pow(10.0, static_cast<double>(static_cast<int>(rng() % 40) - 20)) * (1 + static_cast<double>(rng() % 10));
    case 5: return unit(rng) * 1000;
    case 6: return std::round(unit(rng) * 1e6) / 1000;
    default: return (rng() % 2 ? 1 : -1) * unit(rng) * std::pow(10.0, static_cast<double>(rng() % 30));
  }
}

// Strings nlohmann writes as they are, escapes, or refuses (invalid UTF-8).
std::string random_text(std::mt19937_64& rng) {
  static const char* pieces[] = {"2.t", "student_number", "+x", "Zoé", "—", "\"", "\\", "\n", "\t", "\x01",
                                 "\x7f", "a b", "", "\xc3", "\xe2\x82\xac", "/"};
  std::string s;
  const int n = static_cast<int>(rng() % 4);
  for (int i = 0; i < n; ++i) s += pieces[rng() % std::size(pieces)];
  return s;
}

SheetLayout random_sheet(std::mt19937_64& rng) {
  auto rect = [&] { return Rect{random_double(rng), random_double(rng), random_double(rng), random_double(rng)}; };
  SheetLayout s;
  s.sheet = random_text(rng);
  if (rng() % 2) s.student = StudentLayout{random_text(rng), random_text(rng)};
  const int pages = 1 + static_cast<int>(rng() % 3);
  for (int i = 0; i < pages; ++i) {
    PageLayout p;
    p.page = static_cast<int>(rng() % 200) - 100;
    p.width = random_double(rng);
    p.height = random_double(rng);
    for (auto& m : p.marks) m = {random_double(rng), random_double(rng)};
    p.mark_size = random_double(rng);
    p.code = rect();
    const int fields = static_cast<int>(rng() % 4);  // a page without fields too
    for (int k = 0; k < fields; ++k) {
      FieldLayout f;
      f.question = random_text(rng);
      f.type = rng() % 2 ? FieldType::comb : FieldType::tick;
      const int cells = static_cast<int>(rng() % 4);
      for (int c = 0; c < cells; ++c) {
        f.cells.push_back(rect());
        if (f.type == FieldType::tick) f.values.push_back(random_text(rng));
      }
      f.sign = rng() % 2;
      f.decimals = static_cast<int>(rng() % 7) - 3;
      f.multiple = rng() % 2;
      p.fields.push_back(std::move(f));
    }
    s.pages.push_back(std::move(p));
  }
  return s;
}

}  // namespace

TEST_CASE("layout.json: a sheet is written byte for byte as nlohmann's dump(1) writes it") {
  std::mt19937_64 rng(34);
  int refused = 0;
  for (int i = 0; i < 3000; ++i) {
    const SheetLayout s = random_sheet(rng);
    const bool first = i % 2 == 0;
    std::string expected;
    try {
      expected = by_nlohmann(s, first);
    } catch (const json::type_error&) {
      // invalid UTF-8: refused the same way
      ++refused;
      CHECK_THROWS_AS(layout_json_sheet(s, first), json::type_error);
      continue;
    }
    const std::string written = layout_json_sheet(s, first);
    CAPTURE(i);
    REQUIRE(written == expected);
  }
  // the random strings reach both paths
  CHECK(refused > 0);
  CHECK(refused < 2000);
}

TEST_CASE("layout.json: every double of a page, as nlohmann writes it") {
  // The writer remembers numbers' texts by their bits: numbers come again (a tenth of them an
  // earlier one, from a short list), and others take their slots in between.
  std::mt19937_64 rng(35);
  std::vector<double> seen;
  for (int i = 0; i < 100000; ++i) {
    double d = random_double(rng);
    if (i % 10 == 0 && !seen.empty()) d = seen[rng() % seen.size()];
    else if (seen.size() < 64) seen.push_back(d);
    SheetLayout s;
    PageLayout p;
    p.width = d;
    s.pages.push_back(p);
    CAPTURE(d);
    REQUIRE(layout_json_sheet(s, true) == by_nlohmann(s, true));
  }
}
