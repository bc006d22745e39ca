// The teacher's corrections file (src/grading/corrections.cpp): never an exception; a file that
// is not one has exactly one problem about the whole file and no entry; each entry kept has a
// sheet, a question and a value of at most 4096 bytes, entries in order; every problem is a known
// code and reads in both languages; the entries written back in the canonical shape read back the
// same, with no problem.
#include <cstdint>
#include <set>

#include "fuzz_support.h"
#include "grading/corrections.h"

using namespace epure;
using namespace epure::grading;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const Corrections c = read_corrections(text, "c.json");
  static const std::set<std::string> known = {"too_large", "not_json", "too_deep", "not_object", "bad_format", "bad_version",
                                              "no_list", "entry_not_object", "missing", "not_string", "value_not_string",
                                              "empty", "value_too_long"};
  for (const auto& p : c.problems) {
    fuzz::check(known.count(p.code) == 1, "an unknown problem code", p.code);
    fuzz::check(c.readable == (p.entry > 0), "a file-wide problem in a readable file, or an entry's in an unreadable one", p.code);
    for (const char* language : {"en", "fr"}) {
      const std::string said = describe(p, Texts::builtin(language));
      // every placeholder filled (the input's own text may hold "${", quoted in a message)
      fuzz::check(!said.empty() && (said.find("${") == std::string::npos || text.find("${") != std::string_view::npos),
                  "a problem that does not read", said);
    }
  }
  if (!c.readable) {
    fuzz::check(c.entries.empty() && c.problems.size() == 1, "an unreadable file with entries, or not one reason");
    return 0;
  }
  int last = 0;
  for (const auto& e : c.entries) {
    fuzz::check(e.entry > last, "entries out of order");
    last = e.entry;
    fuzz::check(!e.sheet.empty() && !e.question.empty(), "an entry without its sheet or question");
    fuzz::check(e.value.size() <= kMaxCorrectionValueBytes, "a value past the limit");
  }
  const std::string canonical = corrections_json(c.entries);
  const Corrections again = read_corrections(canonical, "c.json");
  fuzz::check(again.readable && again.problems.empty(), "the canonical shape does not read back", canonical);
  fuzz::check(again.entries.size() == c.entries.size(), "entries lost on the way back");
  for (std::size_t i = 0; i < c.entries.size(); ++i) {
    const auto &a = c.entries[i], &b = again.entries[i];
    fuzz::check(a.sheet == b.sheet && a.question == b.question && a.value == b.value && a.note == b.note,
                "an entry read back differently", a.sheet);
  }
  return 0;
}
