// Who a submission is from (check/sheet_tag.h).
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>

#include "check/sheet_tag.h"

using namespace epure;
using namespace epure::check;

TEST_CASE("sheet and student from the starter's comment, in English and French") {
  const std::string id = SheetId{kDrawVersion, 5, 2}.str();
  const SubmissionTags en = read_tags("/* title\n * sheet: " + id + "     <- the id\n * student: Zoé Lefèvre\n */\nint x;");
  REQUIRE(en.sheet);
  CHECK(en.sheet->str() == id);
  CHECK(en.sheet_line == 2);
  CHECK(en.student == "Zoé Lefèvre");
  const SubmissionTags fr = read_tags("// Feuille : " + id + "\n// Étudiant : Léo Martin\n");
  REQUIRE(fr.sheet);
  CHECK(fr.student == "Léo Martin");
  // typed as a person types it: lower case, no dashes
  std::string loose = id;
  loose.erase(std::remove(loose.begin(), loose.end(), '-'), loose.end());
  for (char& c : loose) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  CHECK(read_tags("/* sheet id: " + loose + " */").sheet);
}

TEST_CASE("placeholders say nothing; a bad id is refused with its reason; the first line counts") {
  const SubmissionTags placeholder = read_tags("/* sheet: XXXX-XXXX-XXXX\n * student: First Last */");
  CHECK_FALSE(placeholder.sheet);
  CHECK_FALSE(placeholder.sheet_problem);
  CHECK(placeholder.student.empty());
  std::string id = SheetId{kDrawVersion, 5, 2}.str();
  id.back() = id.back() == 'A' ? 'B' : 'A';  // the check character wrong
  const SubmissionTags bad = read_tags("/* sheet: " + id + " */");
  CHECK_FALSE(bad.sheet);
  REQUIRE(bad.sheet_problem);
  CHECK(bad.sheet_text == id);
  const SubmissionTags two = read_tags("/* student: First */\n/* student: Second */");
  CHECK(two.student == "First");
  CHECK(read_tags("int student = 3; /* no colon here */").student.empty());
  // not in code: only comments count
  CHECK(read_tags("const char* s = \"student: Eve\";").student.empty());
}

TEST_CASE("a name is cut, and never carries control characters or broken UTF-8") {
  const SubmissionTags t = read_tags("/* student: " + std::string(500, 'a') + " */");
  CHECK(t.student.size() == kMaxTagValue);
  const SubmissionTags c = read_tags("/* student: A\x01\xff" "B */");
  CHECK(c.student == "A??B");
}
