// Answers typed where or as the sheet did not ask, read as meant (issue 31, "to check, not
// zero"): a point in one cell, two neighbouring cells swapped, a cell that cannot be read held
// to check rather than scored 0.
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"
#include "grading/typed_cells.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
// A(−5, 1), u = (1, 0), C = 0, r = 3: t_proj = 5, d² = 1, a hit at t = 5 − √8 ≈ 2.17,
// I ≈ (−2.83, 1), N ≈ (−0.94, 0.33).
const char* kHit = R"({"kind":"ray_circle","A":[-5,1],"u":[1,0],"C":[0,0],"r":3})";
const std::vector<std::string> kFields = {"t_proj", "d2", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"};

// Marked with the cells given by field, in French (decimal commas) or English.
epure::test::Marked mark_in(const epure::grading::ExerciseKey& key,
                            std::initializer_list<std::pair<std::string, std::string>> answers, bool french) {
  auto storage = std::make_shared<std::vector<std::string>>(key.questions.size());
  for (const auto& [field, text] : answers) (*storage)[static_cast<std::size_t>(key.find(field))] = text;
  std::vector<std::string_view> cells(storage->begin(), storage->end());
  epure::grading::MarkingOptions options;
  options.numbers.decimal_comma = french;
  epure::test::Marked m{&key, {}, storage};
  epure::grading::mark_exercise(key, cells, options, m.marks);
  return m;
}
}  // namespace

TEST_CASE("two neighbouring cells swapped are each read in their own place (sheet 1000-0005-001Q's shape)") {
  const auto key = exercise(kHit, kFields);
  SUBCASE("1. t_proj and d² swapped: both right, noted, all the points") {
    const auto m = mark(key, {{"t_proj", "1"}, {"d2", "5,00"}, {"inside", "non"}, {"hit", "oui"}, {"t", "2,17"},
                              {"I.x", "-2,83"}, {"I.y", "1"}, {"N.x", "-0,94"}, {"N.y", "0,33"}});
    CHECK(m["t_proj"].verdict == Verdict::right);
    CHECK(m["d2"].verdict == Verdict::right);
    CHECK(m["t_proj"].note == "swapped_cells");
    CHECK(m["t_proj"].note_field == "1.d2");
    CHECK(m["d2"].note_field == "1.t_proj");
    CHECK(m["t_proj"].given.number == doctest::Approx(5).epsilon(1e-12));  // read from d²'s cell
    CHECK(m.total() == doctest::Approx(9).epsilon(1e-12));
  }
  SUBCASE("2. a number and a word swapped: t in the hit cell, oui in t's") {
    const auto m = mark(key, {{"t_proj", "5"}, {"d2", "1"}, {"inside", "non"}, {"hit", "2,17"}, {"t", "oui"},
                              {"I.x", "-2,83"}, {"I.y", "1"}, {"N.x", "-0,94"}, {"N.y", "0,33"}});
    CHECK(m["hit"].verdict == Verdict::right);
    CHECK(m["t"].verdict == Verdict::right);
    CHECK(m.total() == doctest::Approx(9).epsilon(1e-12));
  }
  SUBCASE("3. two yes/no swapped are also two wrong answers: not credited") {
    const auto m = mark(key, {{"t_proj", "5"}, {"d2", "1"}, {"inside", "oui"}, {"hit", "non"}});
    CHECK(m["inside"].verdict == Verdict::wrong);
    CHECK(m["hit"].verdict == Verdict::wrong);
  }
  SUBCASE("4. x and y of one point swapped stay the named mistake (a point is written (x ; y))") {
    const auto m = mark(key, {{"t_proj", "5"}, {"d2", "1"}, {"I.x", "1"}, {"I.y", "-2,83"}});
    CHECK(m["I.x"].verdict == Verdict::wrong);
    CHECK(m["I.x"].mistake == "swapped_coordinates");
  }
  SUBCASE("5. neighbours that are not each other's answers stay wrong") {
    const auto m = mark(key, {{"t_proj", "1"}, {"d2", "4"}});
    CHECK(m["t_proj"].verdict == Verdict::wrong);
    CHECK(m["d2"].verdict == Verdict::wrong);
    CHECK(m["t_proj"].note.empty());
  }
}

TEST_CASE("a point typed whole in one cell is read coordinate by coordinate (issue 31: (3 ; 5))") {
  const auto key = exercise(kHit, kFields);
  SUBCASE("1. (x ; y) in I.x, I.y empty") {
    const auto m = mark_in(key, {{"t_proj", "5"}, {"d2", "1"}, {"I.x", "(−2,83 ; 1)"}}, true);
    CHECK(m["I.x"].verdict == Verdict::right);
    CHECK(m["I.y"].verdict == Verdict::right);
    CHECK(m["I.x"].note == "point_in_one_cell");
  }
  SUBCASE("2. the point typed in the y cell") {
    const auto m = mark_in(key, {{"I.y", "(-2.83, 1)"}}, false);
    CHECK(m["I.x"].verdict == Verdict::right);
    CHECK(m["I.y"].verdict == Verdict::right);
  }
  SUBCASE("3. a wrong point is wrong coordinate by coordinate, and follow-through still applies") {
    const auto m = mark_in(key, {{"I.x", "(5 ; 5)"}}, true);
    CHECK(m["I.x"].verdict == Verdict::wrong);
    CHECK(m["I.y"].verdict == Verdict::wrong);
  }
  SUBCASE("4. (3,5) on a French sheet: a point or 3,5? to check, its points held") {
    const auto m = mark_in(key, {{"N.x", "(3,5)"}}, true);
    CHECK(m["N.x"].verdict == Verdict::to_check);
    CHECK(m["N.y"].verdict == Verdict::to_check);
    CHECK(m["N.x"].given.why == "ambiguous_point");
    CHECK(m.total() == doctest::Approx(0).epsilon(1e-12));
  }
  SUBCASE("5. with both cells filled, each cell is its own coordinate") {
    const auto m = mark_in(key, {{"I.x", "(−2,83 ; 1)"}, {"I.y", "1"}}, true);
    CHECK(m["I.x"].verdict == Verdict::to_check);
    CHECK(m["I.y"].verdict == Verdict::right);
  }
}

TEST_CASE("what cannot be read is to check: points held, not scored 0, never diagnosed") {
  const auto key = exercise(kHit, kFields);
  const auto m = mark(key, {{"t_proj", "5,0?"}, {"d2", "1"}, {"t", "0.89 rad"}});
  CHECK(m["t_proj"].verdict == Verdict::to_check);
  CHECK(m["t_proj"].points == 0);
  CHECK(m["t_proj"].mistake.empty());
  CHECK(m["t"].verdict == Verdict::to_check);
  CHECK(m["d2"].verdict == Verdict::right);
}
