#include <doctest/doctest.h>

#include "scan/layout_file.h"
#include "scan_fixture.h"

using namespace epure::scan;

namespace {

SetLayout sample() {
  SetLayout l;
  l.language = "fr";
  l.decimal_separator = ",";
  l.seed = 5;
  SheetLayout s;
  s.sheet = "1000-0005-000S";
  s.student = StudentLayout{"20260001", "Zoé Lefèvre"};
  s.pages = fixture::lay_out_fields({{"student_number", FieldType::comb, 8, 0, false, {}, false},
                                     {"2.t", FieldType::comb, 3, 2, true, {}, false},
                                     {"2.position", FieldType::tick, 0, 0, false, {"before", "between", "after"}, false},
                                     {"5.faces", FieldType::tick, 0, 0, false, {"+x", "-x", "+y", "-y"}, true}});
  l.sheets.emplace(s.sheet, s);
  return l;
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
  const auto at = text.find(what);
  REQUIRE(at != std::string::npos);
  return text.replace(at, what.size(), with);
}

}  // namespace

TEST_CASE("layout.json: written and read back") {
  const SetLayout l = sample();
  const SetLayout back = read_layout(layout_json(l), "layout.json");
  REQUIRE(back.sheets.size() == 1);
  const SheetLayout& s = back.sheets.begin()->second;
  CHECK(s.student->name == "Zoé Lefèvre");
  CHECK(back.decimal_separator == ",");
  REQUIRE(s.pages.size() == 1);
  const auto& f = s.pages[0].fields;
  REQUIRE(f.size() == 4);
  CHECK(f[1].cells.size() == 6);
  CHECK(f[1].sign);
  CHECK(f[1].decimals == 2);
  CHECK(f[2].values == std::vector<std::string>{"before", "between", "after"});
  CHECK_FALSE(f[2].multiple);
  CHECK(f[3].multiple);
  CHECK(layout_json(back) == layout_json(l));
}

TEST_CASE("layout.json: a bad file is refused with where and why") {
  const std::string good = layout_json(sample());
  auto message = [](const std::string& text) {
    try {
      read_layout(text, "layout.json");
    } catch (const LayoutError& e) {
      return std::string(e.what());
    }
    return std::string("(read)");
  };
  CHECK(message("[1, 2") .rfind("layout.json: not JSON", 0) == 0);
  CHECK(message("{}") == "layout.json: not a layout.json (\"format\": \"epure-layout\" is missing)");
  // a member of another type is refused the same way, not by the JSON library's own type_error
  // (the fuzzer's {"format": 1, ...})
  CHECK(message(replaced(good, "\"format\": \"epure-layout\"", "\"format\": 1")) ==
        "layout.json: not a layout.json (\"format\": \"epure-layout\" is missing)");
  CHECK(message(replaced(good, "\"version\": 1", "\"version\": \"1\"")) ==
        "layout.json: a layout.json of another version: this epure reads version 1");
  CHECK(message(replaced(good, "\"version\": 1", "\"version\": 2")) == "layout.json: a layout.json of another version: this epure reads version 1");
  CHECK(message(replaced(good, "\"type\": \"tick\"", "\"type\": \"circle\"")) ==
        "layout.json: sheet 1000-0005-000S, page 1, field 2.position: 'type' must be \"comb\" or \"tick\", not \"circle\"");
  CHECK(message(replaced(good, "\"decimals\": 2", "\"decimals\": 6")) ==
        "layout.json: sheet 1000-0005-000S, page 1, field 2.t: the sign and decimal cells leave no cell for the integer part");
  CHECK(message(replaced(good, "\"mark_size\": 14.17", "\"mark_size\": \"big\"")) ==
        "layout.json: sheet 1000-0005-000S, page 1: 'mark_size' must be a number");
  std::string deep(40, '[');
  CHECK(message(deep) == "layout.json: nested deeper than 16 levels: not a layout.json");
}
