// Worksheet specs: the built-in course worksheet parses; every mistake is reported with file,
// line and key.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include "exercises/spec.h"

using epure::parse_spec;
using epure::SpecError;

namespace {
std::string error_of(const std::string& toml) {
  try {
    parse_spec(toml, "my.toml");
  } catch (const SpecError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a minimal spec takes the defaults") {
  auto spec = parse_spec("[[exercise]]\nkind = \"projection\"\n", "min.toml");
  CHECK(spec.language == "en");
  CHECK(spec.decimals == 2);
  REQUIRE(spec.exercises.size() == 1);
  CHECK(spec.exercises[0].difficulty == epure::Difficulty::standard);
  CHECK(spec.exercises[0].branches.empty());
}

TEST_CASE("spec settings are read") {
  auto spec = parse_spec(R"(
title = "T"
language = "fr"
decimals = 3
difficulty = "easy"
[[exercise]]
kind = "projection"
difficulty = "hard"
branches = { after = 1, before = 2 }
questions = { t = { points = 3, abs = 0.02 }, P = { whole_point = true } }
constraints = { t_margin = 0.2 }
)", "s.toml");
  CHECK(spec.language == "fr");
  CHECK(spec.decimals == 3);
  const auto& e = spec.exercises.at(0);
  CHECK(e.difficulty == epure::Difficulty::hard);
  // the kind's order, not the file's
  REQUIRE(e.branches.size() == 2);
  CHECK(e.branches[0].first == "before");
  CHECK(e.questions.at("t").points == 3);
  CHECK(e.questions.at("P").whole_point);
  CHECK(e.constraints.at("t_margin") == doctest::Approx(0.2).epsilon(1e-15));
}

TEST_CASE("title, course, author and subject may be given per language") {
  const auto spec = parse_spec(R"(
language = "en"
title = { en = "Utilities", fr = "Utilitaires" }
course = "Graphics"
subject = { fr = "Produits" }
[[exercise]]
kind = "projection"
)", "w.toml");
  CHECK(spec.title == "Utilities");
  CHECK(spec.course == "Graphics");
  CHECK(spec.subject == "");  // no English subject given
  const auto fr = spec.words_in("fr");
  CHECK(fr.title == "Utilitaires");
  CHECK(fr.course == "Graphics");  // not translated: the spec language's words
  CHECK(fr.subject == "Produits");
  const auto en = spec.words_in("en");
  CHECK(en.title == "Utilities");
  CHECK(en.subject == "");

  SUBCASE("the built-in course speaks both languages") {
    const auto course = epure::builtin_spec();
    CHECK(course.words_in("fr").title != course.words_in("en").title);
    CHECK(course.words_in("fr").course != course.words_in("en").course);
  }
  SUBCASE("an unknown language or a non-string is an error naming the key") {
    const auto e = error_of("title = { de = \"Titel\" }\n[[exercise]]\nkind = \"projection\"\n");
    CHECK(e.find("my.toml:1:") == 0);
    CHECK(e.find("'title.de'") != std::string::npos);
    CHECK(error_of("title = { en = 3 }\n[[exercise]]\nkind = \"projection\"\n").find("'title.en'") != std::string::npos);
    CHECK(error_of("title = 3\n[[exercise]]\nkind = \"projection\"\n").find("'title'") != std::string::npos);
  }
}

TEST_CASE("an exercise may have a heading of its own; the others are numbered in order") {
  const auto spec = parse_spec(R"(
language = "fr"
[[exercise]]
kind = "vectors"
heading = { en = "Preamble", fr = "Préambule" }
[[exercise]]
kind = "projection"
[[exercise]]
kind = "segments"
heading = "Bonus"
[[exercise]]
kind = "ray_circle"
)", "h.toml");
  CHECK(spec.exercises[0].heading == "Préambule");
  CHECK(spec.exercises[0].heading_in("en") == "Preamble");
  CHECK(spec.exercises[2].heading_in("en") == "Bonus");  // one string: every language
  CHECK(spec.exercises[1].heading.empty());
  CHECK(epure::exercise_number(spec, 1) == 1);
  CHECK(epure::exercise_number(spec, 3) == 2);
  SUBCASE("the built-in course numbers as the course does: preamble, exercises 1 to 4, open questions") {
    const auto course = epure::builtin_spec();
    REQUIRE(course.exercises.size() == 7);
    CHECK(course.exercises[0].heading_in("fr") == "Préambule");
    CHECK(epure::exercise_number(course, 1) == 1);
    CHECK(epure::exercise_number(course, 4) == 4);
    CHECK(course.exercises[5].heading_in("fr") == "Exercice 3, question 3");
    // one numbering: the ids' number says what the heading says
    CHECK(epure::exercise_id(course, 0) == "P");
    CHECK(epure::exercise_id(course, 1) == "1");
    CHECK(epure::exercise_id(course, 4) == "4");
    CHECK(epure::exercise_id(course, 5) == "3.3");
    CHECK(epure::exercise_id(course, 6) == "4.3");
  }
  SUBCASE("exercise numbers: given, derived, and never twice") {
    // without `number`: n for "Exercise n", the place for a heading unless that place is taken
    CHECK(epure::exercise_id(spec, 0) == "s1");  // "Préambule" at place 1, "Exercise 1" is 1
    CHECK(epure::exercise_id(spec, 1) == "1");
    CHECK(epure::exercise_id(spec, 2) == "3");   // "Bonus" at place 3: no exercise is 3
    CHECK(epure::exercise_id(spec, 3) == "2");
    CHECK(spec.exercises[0].number == "s1");     // parse_spec fills them in
    const auto given = epure::parse_spec(
        "[[exercise]]\nkind = \"projection\"\nnumber = \"A.1\"\n[[exercise]]\nkind = \"segments\"\nnumber = 7\n", "n.toml");
    CHECK(given.exercises[0].number == "A.1");
    CHECK(given.exercises[1].number == "7");
    const auto clash = error_of("[[exercise]]\nkind = \"projection\"\n[[exercise]]\nkind = \"segments\"\nnumber = \"1\"\n");
    CHECK(clash.find("exercise[2]") != std::string::npos);
    CHECK(clash.find("number 1 is exercise[1]'s too") != std::string::npos);
    for (const char* bad : {"\"\"", "\"3..3\"", "\".3\"", "\"3.\"", "\"3 3\"", "\"é\"", "\"1234567890123\"", "1.5"}) {
      CAPTURE(bad);
      const auto e = error_of(std::string("[[exercise]]\nkind = \"projection\"\nnumber = ") + bad + "\n");
      CHECK(e.find("'exercise[1].number'") != std::string::npos);
    }
  }
  SUBCASE("a heading of another language or type is an error naming the key") {
    const auto e = error_of("[[exercise]]\nkind = \"projection\"\nheading = { de = \"x\" }\n");
    CHECK(e.find("my.toml:3:") == 0);
    CHECK(e.find("'exercise[1].heading.de'") != std::string::npos);
    CHECK(error_of("[[exercise]]\nkind = \"projection\"\nheading = 3\n").find("'exercise[1].heading'") != std::string::npos);
  }
}

TEST_CASE("every mistake names the file, the line and the key") {
  SUBCASE("1. not TOML") { CHECK(error_of("title = \n").find("my.toml:1:") == 0); }
  SUBCASE("2. unknown top-level key") {
    const auto e = error_of("titel = \"x\"\n[[exercise]]\nkind = \"projection\"\n");
    CHECK(e.find("my.toml:1:") == 0);
    CHECK(e.find("'titel'") != std::string::npos);
  }
  SUBCASE("3. unknown kind") {
    const auto e = error_of("[[exercise]]\nkind = \"ray_torus\"\n");
    CHECK(e.find("my.toml:2:") == 0);
    CHECK(e.find("exercise[1].kind") != std::string::npos);
  }
  SUBCASE("4. unknown branch") {
    const auto e = error_of("[[exercise]]\nkind = \"projection\"\nbranches = { inside = 1 }\n");
    CHECK(e.find("my.toml:3:") == 0);
    CHECK(e.find("exercise[1].branches.inside") != std::string::npos);
  }
  SUBCASE("5. unknown question field") {
    const auto e = error_of("[[exercise]]\nkind = \"projection\"\nquestions = { I = { points = 1 } }\n");
    CHECK(e.find("exercise[1].questions.I") != std::string::npos);
  }
  SUBCASE("6. bad difficulty") {
    CHECK(error_of("difficulty = \"medium\"\n[[exercise]]\nkind = \"projection\"\n").find("'difficulty'") != std::string::npos);
  }
  SUBCASE("7. bad language, page, decimals") {
    CHECK(error_of("language = \"de\"\n[[exercise]]\nkind = \"projection\"\n").find("'language'") != std::string::npos);
    CHECK(error_of("page = \"A5\"\n[[exercise]]\nkind = \"projection\"\n").find("'page'") != std::string::npos);
    CHECK(error_of("decimals = 9\n[[exercise]]\nkind = \"projection\"\n").find("'decimals'") != std::string::npos);
  }
  SUBCASE("7b. the student number's comb: 4 to 12 cells") {
    for (const char* bad : {"3", "13", "\"8\"", "8.0"})
      CHECK(error_of(fmt::format("student_number_digits = {}\n[[exercise]]\nkind = \"projection\"\n", bad))
                .find("'student_number_digits': expected an integer from 4 to 12") != std::string::npos);
  }
  SUBCASE("8. no exercise") { CHECK(error_of("title = \"x\"\n").find("no [[exercise]]") != std::string::npos); }
  SUBCASE("9. negative weight, zero total") {
    CHECK(error_of("[[exercise]]\nkind = \"projection\"\nbranches = { before = -1 }\n").find("≥ 0") != std::string::npos);
    CHECK(error_of("[[exercise]]\nkind = \"projection\"\nbranches = { before = 0 }\n").find("positive") != std::string::npos);
  }
  SUBCASE("10. unknown constraint") {
    CHECK(error_of("[[exercise]]\nkind = \"projection\"\nconstraints = { speed = 1 }\n").find("constraints.speed") != std::string::npos);
  }
}

TEST_CASE("an exercise's points and the scale are read and checked") {
  const auto spec = parse_spec(R"(
scale = 20
[[exercise]]
kind = "projection"
points = 6.5
questions = { t = { points = 2 } }
[[exercise]]
kind = "segments"
)", "p.toml");
  REQUIRE(spec.scale.has_value());
  CHECK(*spec.scale == doctest::Approx(20).epsilon(1e-15));
  REQUIRE(spec.exercises.at(0).points.has_value());
  CHECK(*spec.exercises[0].points == doctest::Approx(6.5).epsilon(1e-15));
  CHECK(spec.exercises[0].questions.at("t").points == 2);  // a weight
  CHECK_FALSE(spec.exercises[1].points.has_value());       // the kind's default
  CHECK_FALSE(parse_spec("[[exercise]]\nkind = \"projection\"\n", "m.toml").scale.has_value());

  SUBCASE("1. points that are not whole quarters") {
    const auto e = error_of("[[exercise]]\nkind = \"projection\"\npoints = 2.3\n");
    CHECK(e.find("my.toml:3:") == 0);
    CHECK(e.find("exercise[1].points") != std::string::npos);
    CHECK(e.find("0.25") != std::string::npos);
  }
  SUBCASE("2. negative points") {
    CHECK(error_of("[[exercise]]\nkind = \"projection\"\npoints = -1\n").find("≥ 0") != std::string::npos);
  }
  SUBCASE("3. a scale that is not a positive number") {
    CHECK(error_of("scale = 0\n[[exercise]]\nkind = \"projection\"\n").find("my.toml:1:") == 0);
    CHECK(error_of("scale = \"20\"\n[[exercise]]\nkind = \"projection\"\n").find("'scale'") != std::string::npos);
  }
}
