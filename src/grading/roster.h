#pragma once
// A class roster as a spreadsheet exports it (CSV: student number; name; optional e-mail), read
// by `epure grade --roster` (marks to the gradebook by student number or e-mail) and, for
// `epure generate --roster`, to print each student's name and number on their sheet. One
// reader for both, so that a roster that generate reads, grade reads the same way.
//
// The columns are found by their header ("numéro d’étudiant", "student number", "nom", "name",
// "prénom"/"first name" and "nom de famille"/"last name" as two columns, "courriel", "e-mail",
// in any order, any case, with or without accents); a file without a header row is read as
// number, name, e-mail in that order. The CSV dialect is detected as for answers (csv_reader.h:
// comma, semicolon or tab, a BOM, CRLF, quotes). A student number is kept as written (leading
// zeros and all: "00412" is an id, not a number); two students with one number, a row without a
// number and an e-mail without '@' are said with their line, and the rest is read.
#include <filesystem>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "exercises/texts.h"

namespace epure::grading {

struct RosterEntry {
  int line = 0;
  std::string number;  // as written
  std::string name;
  std::string email;   // empty when the roster has none for this student
};

struct RosterProblem {
  int line = 0;      // 0: the file as a whole
  bool error = true;
  std::string code;  // "duplicate", "no_number", "no_name", "bad_email", "empty", "unreadable"
  TextVars vars;
};

struct Roster {
  std::string source;
  std::vector<RosterEntry> students;  // in the file's order
  std::vector<RosterProblem> problems;

  // The student with this number (compared without blanks, any case), or null.
  const RosterEntry* by_number(std::string_view number) const;
  // The student with this e-mail (any case), or null.
  const RosterEntry* by_email(std::string_view email) const;
  // The student with this name, compared as words in any order without case or accents
  // ("Lefèvre, Zoé" is "zoe lefevre"), or null; null too when two students share the name.
  const RosterEntry* by_name(std::string_view name) const;

  // Builds the lookups (read_roster does it).
  void index();

 private:
  std::unordered_map<std::string, std::size_t> numbers_, emails_, names_;
};

// A student number as it is compared: without blanks, upper case.
std::string roster_number_key(std::string_view number);
// A name as it is compared: its folded words, sorted ("Zoé Lefèvre" and "LEFEVRE, zoe" agree).
std::string roster_name_key(std::string_view name);

// Reads a roster file. Throws std::runtime_error naming the file when it cannot be opened (as
// the answers' reader does); everything else is in `problems`.
Roster read_roster(const std::filesystem::path& path);
// The same from text in memory, named `source` (tests, fuzzing).
Roster read_roster_text(std::string text, std::string_view source);

// The problem in words, for a message that names the file and the line.
std::string describe(const RosterProblem& p, const Texts& texts);

}  // namespace epure::grading
