// Sheet ids (src/exercises/sheet_id.cpp): an id read prints back as an id that reads the same;
// a refusal gives one of its codes; any id written reads back; the check character catches every
// single mistyped character (src/exercises/sheet_id.h).
#include <cstdint>
#include <cstring>

#include "exercises/sheet_id.h"
#include "fuzz_support.h"

using namespace epure;

namespace {

constexpr std::string_view kAlphabet = "0123456789ABCDEFGHJKMNPQRSTVWXYZ";

bool same(const SheetId& a, const SheetId& b) { return a.version == b.version && a.seed == b.seed && a.index == b.index; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const ParsedSheetId p = parse_sheet_id(text);
  if (p.id) {
    const SheetId& id = *p.id;
    fuzz::check(id.version >= 0 && id.version < 32 && id.seed <= kMaxSeed && id.index >= 0 && id.index < kMaxSheets,
                "an id read out of range", text);
    const std::string s = id.str();
    fuzz::check(s.size() == 14 && s[4] == '-' && s[9] == '-', "an id printed not as XXXX-XXXX-XXXX", s);
    const ParsedSheetId back = parse_sheet_id(s);
    fuzz::check(back.id && same(*back.id, id), "an id printed does not read back", s);
  } else {
    const auto code = p.error.code;
    fuzz::check(code == "character" || code == "length" || code == "too_long" || code == "check", "an unknown code", code);
    fuzz::check(!p.error.message.empty(), "a refusal without a message");
  }
  // An id made from the bytes: written, read back, and every single substitution refused.
  if (size >= 9) {
    SheetId id;
    std::uint64_t seed;
    std::memcpy(&seed, data, 8);
    id.version = data[8] % 32;
    id.seed = seed & kMaxSeed;
    id.index = static_cast<int>((seed >> 35) % kMaxSheets);
    const std::string s = id.str();
    const ParsedSheetId back = parse_sheet_id(s);
    fuzz::check(back.id && same(*back.id, id), "an id written does not read back", s);
    if (size >= 11) {
      std::string typo = s;
      std::size_t pos = data[9] % 12;
      pos += pos / 4;  // skip the dashes
      const char was = typo[pos];
      const char now = kAlphabet[data[10] % 32];
      if (now != was) {
        typo[pos] = now;
        const ParsedSheetId wrong = parse_sheet_id(typo);
        fuzz::check(!wrong.id, "a mistyped character was not caught", s + " → " + typo);
      }
    }
  }
  return 0;
}
