#pragma once
// Sheet ids: short, printable, typeable, self-checking. An id carries everything needed to
// rebuild its sheet from the spec: the generator's draw version, the set's seed and the sheet's
// index. Crockford's base-32 alphabet (no I, L, O, U: nothing to confuse with 1, 0 or V) in three
// groups of four, the last character a Luhn mod 32 check that catches every single mistyped
// character and every swap of two adjacent characters:
//
//   VSSS-SSSS-IIIC    V draw version (5 bits), S seed (35 bits), I index (15 bits), C check
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace epure {

// The generator's draw version: bump it whenever a change makes the same spec and seed draw a
// different sheet. A sheet id made under another version is refused on rebuild.
inline constexpr int kDrawVersion = 2;

inline constexpr std::uint64_t kMaxSeed = (1ULL << 35) - 1;
inline constexpr int kMaxSheets = 1 << 15;

struct SheetId {
  int version = kDrawVersion;
  std::uint64_t seed = 0;  // ≤ kMaxSeed
  int index = 0;           // 0-based, < kMaxSheets

  std::string str() const;  // "1ABC-DEFG-HJK7"
};

struct SheetIdError {
  std::string message;  // why it was refused
  // the same as a code, for a message in another language: "character" (one that no id
  // holds), "length" (fewer than 12 characters), "too_long", "check" (the check character does not match)
  std::string_view code;
  std::string detail;  // "character": the character; "length": the count
};

// Reads an id as a person may type it: any case, with or without dashes and spaces, O for 0,
// I and L for 1. Returns the id, or why not.
struct ParsedSheetId {
  std::optional<SheetId> id;
  SheetIdError error;
};
ParsedSheetId parse_sheet_id(std::string_view text);

}  // namespace epure
