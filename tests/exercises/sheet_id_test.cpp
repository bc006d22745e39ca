// Sheet ids: round trip, typing slack, and the check character catching every single mistyped
// character and every adjacent swap.
#include <doctest/doctest.h>

#include "exercises/rng.h"
#include "exercises/sheet_id.h"

using epure::parse_sheet_id;
using epure::SheetId;

TEST_CASE("sheet ids round-trip and look like VSSS-SSSS-IIIC") {
  epure::Rng rng(7);
  for (int i = 0; i < 2000; ++i) {
    SheetId id{epure::kDrawVersion, rng.next_u64() & epure::kMaxSeed,
               static_cast<int>(rng.integer(0, epure::kMaxSheets - 1))};
    const std::string text = id.str();
    CAPTURE(text);
    REQUIRE(text.size() == 14);
    CHECK(text[4] == '-');
    CHECK(text[9] == '-');
    auto parsed = parse_sheet_id(text);
    REQUIRE(parsed.id);
    CHECK(parsed.id->seed == id.seed);
    CHECK(parsed.id->index == id.index);
    CHECK(parsed.id->version == id.version);
  }
}

TEST_CASE("sheet ids are read as people type them") {
  const std::string id = SheetId{1, 123456789, 42}.str();
  std::string lower, spaced, bare;
  for (char c : id) {
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c != '-') bare += c;
    spaced += c == '-' ? ' ' : c;
  }
  for (const auto& form : {lower, spaced, bare}) {
    CAPTURE(form);
    auto parsed = parse_sheet_id(form);
    REQUIRE(parsed.id);
    CHECK(parsed.id->seed == 123456789u);
    CHECK(parsed.id->index == 42);
  }
  // O for 0 and I, L for 1 (Crockford)
  std::string confusable = id;
  for (char& c : confusable) {
    if (c == '0') c = 'O';
    if (c == '1') c = 'I';
  }
  auto parsed = parse_sheet_id(confusable);
  REQUIRE(parsed.id);
  CHECK(parsed.id->seed == 123456789u);
}

TEST_CASE("the check character catches single substitutions and adjacent swaps") {
  constexpr std::string_view alphabet = "0123456789ABCDEFGHJKMNPQRSTVWXYZ";
  epure::Rng rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    std::string id = SheetId{1, rng.next_u64() & epure::kMaxSeed, static_cast<int>(rng.integer(0, 999))}.str();
    CAPTURE(id);
    for (std::size_t pos = 0; pos < id.size(); ++pos) {
      if (id[pos] == '-') continue;
      for (char c : alphabet) {
        if (c == id[pos]) continue;
        std::string typo = id;
        typo[pos] = c;
        CHECK_FALSE(parse_sheet_id(typo).id);
      }
    }
    std::string bare;
    for (char c : id)
      if (c != '-') bare += c;
    for (std::size_t pos = 0; pos + 1 < bare.size(); ++pos) {
      if (bare[pos] == bare[pos + 1]) continue;
      std::string swapped = bare;
      std::swap(swapped[pos], swapped[pos + 1]);
      // Luhn mod N misses only swaps of a pair whose doubled values fold alike; report them
      auto parsed = parse_sheet_id(swapped);
      if (parsed.id) {
        CAPTURE(swapped);
        const int a = static_cast<int>(alphabet.find(bare[pos]));
        const int b = static_cast<int>(alphabet.find(bare[pos + 1]));
        CHECK(((a == 0 && b == 31) || (a == 31 && b == 0)));
      }
    }
  }
}

TEST_CASE("malformed ids are refused with a reason") {
  CHECK_FALSE(parse_sheet_id("").id);
  CHECK_FALSE(parse_sheet_id("ABCD-EFGH").id);
  CHECK_FALSE(parse_sheet_id("ABCD-EFGH-JKMN-P").id);
  auto bad_char = parse_sheet_id("ABCD-EFGH-JK!M");
  CHECK_FALSE(bad_char.id);
  CHECK(bad_char.error.message.find('!') != std::string::npos);
}
