// The class roster (src/grading/roster.cpp, over csv_reader.cpp): never an exception for
// content; every student has a number, numbers are unique as compared, lines go forward, an
// e-mail kept has its '@'; each student is found by their number; known problem codes that read
// in both languages; the students written back as a quoted CSV with a header read back the same.
#include <cstdint>
#include <set>

#include "fuzz_support.h"
#include "grading/roster.h"

using namespace epure;
using namespace epure::grading;

namespace {
std::string csv_quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Roster r;
  try {
    r = read_roster_text(text, "r.csv");
  } catch (const std::runtime_error&) {
    return 0;  // UTF-16: refused as the answers' reader refuses it
  }
  static const std::set<std::string> known = {"malformed", "no_number_column", "no_number", "duplicate", "no_name",
                                              "bad_email", "unreadable", "empty"};
  for (const auto& p : r.problems) {
    fuzz::check(known.count(p.code) == 1, "an unknown problem code", p.code);
    for (const char* language : {"en", "fr"}) {
      const std::string said = describe(p, Texts::builtin(language));
      // every placeholder filled (the input's own text may hold "${", quoted in a message)
      fuzz::check(said.find("${") == std::string::npos || text.find("${") != std::string::npos, "a problem that does not read",
                  said);
    }
  }
  std::set<std::string> keys;
  int last = 0;
  std::string back = "student number,name,e-mail\n";
  for (const auto& s : r.students) {
    fuzz::check(!s.number.empty(), "a student without a number");
    fuzz::check(keys.insert(roster_number_key(s.number)).second, "two students with one number", s.number);
    fuzz::check(s.line > last, "lines out of order");
    last = s.line;
    fuzz::check(s.email.empty() || s.email.find('@') != std::string::npos, "an e-mail without @", s.email);
    fuzz::check(r.by_number(s.number) == &s, "a student not found by their number", s.number);
    back += csv_quoted(s.number) + "," + csv_quoted(s.name) + "," + csv_quoted(s.email) + "\n";
  }
  if (r.students.empty()) return 0;
  const Roster again = read_roster_text(back, "back.csv");
  fuzz::check(again.students.size() == r.students.size(), "students lost on the way back", back);
  for (std::size_t i = 0; i < r.students.size(); ++i) {
    const auto &a = r.students[i], &b = again.students[i];
    fuzz::check(a.number == b.number && a.name == b.name && a.email == b.email, "a student read back differently", a.number);
  }
  return 0;
}
