// A class roster as spreadsheets export it: columns found by their header in either language
// (or number, name, e-mail without one), numbers kept as written, problems said with their line.
#include <doctest/doctest.h>

#include "grading/roster.h"

using namespace epure::grading;

namespace {
bool has(const Roster& r, int line, const std::string& code) {
  for (const auto& p : r.problems)
    if (p.line == line && p.code == code) return true;
  return false;
}
}  // namespace

TEST_CASE("a French roster with its header, in any order") {
  const Roster r = read_roster_text("\xef\xbb\xbf" "Courriel;Nom;Prénom;N° étudiant\r\n"
                                    "zoe.lefevre@univ.fr;Lefèvre;Zoé;00412\r\n"
                                    "leo.martin@univ.fr;Martin;Léo;21804512\r\n",
                                    "classe.csv");
  CHECK(r.problems.empty());
  REQUIRE(r.students.size() == 2);
  CHECK(r.students[0].number == "00412");  // an id, leading zeros kept
  CHECK(r.students[0].name == "Zoé Lefèvre");
  CHECK(r.students[0].email == "zoe.lefevre@univ.fr");
  CHECK(r.students[0].line == 2);
  SUBCASE("found by number (any blanks, any case), e-mail, or name in any order without accents") {
    CHECK(r.by_number(" 004 12") == &r.students[0]);
    CHECK(r.by_email("Leo.Martin@univ.fr") == &r.students[1]);
    CHECK(r.by_name("LEFEVRE, zoe") == &r.students[0]);
    CHECK(r.by_name("Léo Martin") == &r.students[1]);
    CHECK(r.by_name("Zoé") == nullptr);
  }
}

TEST_CASE("without a header: number, name, e-mail") {
  const Roster r = read_roster_text("21800001,\"Dupont, Jean\",jean@u.fr\n21800002,Marie Curie\n", "r.csv");
  CHECK(r.problems.empty());
  REQUIRE(r.students.size() == 2);
  CHECK(r.students[0].name == "Dupont, Jean");
  CHECK(r.students[1].email.empty());
}

TEST_CASE("problems, each with its line; the rest is read") {
  const Roster r = read_roster_text("student number,name,e-mail\n"
                                    "1,Ann,ann@u.edu\n"
                                    "1,Bob,bob@u.edu\n"
                                    ",Carl,carl@u.edu\n"
                                    "4,,dan@u.edu\n"
                                    "5,Eve,eve-at-u.edu\n"
                                    "6,Ann,ann2@u.edu\n",
                                    "r.csv");
  CHECK(has(r, 3, "duplicate"));
  CHECK(has(r, 4, "no_number"));
  CHECK(has(r, 5, "no_name"));
  CHECK(has(r, 6, "bad_email"));
  REQUIRE(r.students.size() == 4);  // 1 Ann, 4, 5 Eve (without e-mail), 6 Ann
  CHECK(r.students[2].email.empty());
  CHECK(r.by_name("Ann") == nullptr);  // two students named Ann: never matched by name
  for (const char* language : {"en", "fr"})
    for (const auto& p : r.problems) CHECK(describe(p, epure::Texts::builtin(language)).find("${") == std::string::npos);
  SUBCASE("an empty roster") {
    const Roster e = read_roster_text("", "e.csv");
    CHECK(has(e, 0, "empty"));
  }
}
