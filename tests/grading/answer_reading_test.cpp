// A cell read for its question's type: yes/no in English and French, positions and reasons
// as the sheets print them (or close), faces in any order and separator, blanks.
#include <doctest/doctest.h>

#include "grading/answer_reading.h"
#include "grading/words.h"

using epure::grading::AnswerType;
using epure::grading::face_bit;
using epure::grading::FaceBits;
using epure::grading::Given;
using epure::grading::read_answer;

TEST_CASE("an empty cell is not answered") {
  for (const char* cell : {"", "   ", "\u00a0"}) {
    CAPTURE(cell);
    CHECK(read_answer(cell, AnswerType::number).state == Given::State::blank);
  }
}

TEST_CASE("yes and no, in every spelling the templates list") {
  for (const char* yes : {"yes", "YES", "y", "true", "1", "oui", "Oui", "o", "vrai", "x"}) {
    CAPTURE(yes);
    const auto g = read_answer(yes, AnswerType::boolean);
    REQUIRE(g.readable());
    CHECK(g.boolean);
  }
  for (const char* no : {"no", "n", "false", "0", "non", "NON", "faux"}) {
    CAPTURE(no);
    const auto g = read_answer(no, AnswerType::boolean);
    REQUIRE(g.readable());
    CHECK_FALSE(g.boolean);
  }
  SUBCASE("anything else is unreadable") {
    const auto g = read_answer("peut-être", AnswerType::boolean);
    CHECK(g.state == Given::State::unreadable);
    CHECK(g.why == "boolean");
  }
}

TEST_CASE("positions and reasons in English and French") {
  const std::pair<const char*, const char*> cases[] = {
      {"before", "before"},   {"before A", "before"},     {"avant A", "before"},   {"AVANT", "before"},
      {"entre A et B", "between"}, {"between", "between"}, {"après B", "after"},   {"apres", "after"},
      {"à l’extérieur", "outside"}, {"a l'exterieur", "outside"}, {"parallèles", "parallel"},
      {"derrière", "behind"}, {"manqué", "miss"},         {"miss.", "miss"},       {"Colinéaires", "collinear"}};
  for (const auto& [cell, word] : cases) {
    CAPTURE(cell);
    const auto g = read_answer(cell, AnswerType::word);
    REQUIRE(g.readable());
    CHECK(g.word == word);
  }
  SUBCASE("a yes is not a position") { CHECK(read_answer("oui", AnswerType::word).why == "word"); }
  SUBCASE("nor is nonsense") { CHECK(read_answer("dunno", AnswerType::word).why == "word"); }
}

TEST_CASE("faces in any order and separator") {
  const FaceBits px_my = face_bit("+x") | face_bit("-y");
  for (const char* cell : {"+x -y", "-y;+x", "-y, +x", "+x,-y", "+X −Y", "x=1 y=-1", "[\"+x\", \"-y\"]", "+x et -y", "-y +x +x"}) {
    CAPTURE(cell);
    const auto g = read_answer(cell, AnswerType::faces);
    REQUIRE(g.readable());
    CHECK(g.faces == px_my);
  }
  for (const char* none : {"none", "aucun", "aucune", "∅", "{}"}) {
    CAPTURE(none);
    const auto g = read_answer(none, AnswerType::faces);
    REQUIRE(g.readable());
    CHECK(g.faces == 0);
  }
  SUBCASE("a face without its sign") { CHECK(read_answer("x y", AnswerType::faces).why == "faces"); }
  SUBCASE("not a face") { CHECK(read_answer("+w", AnswerType::faces).why == "faces"); }
}

TEST_CASE("folding words: case, accents, apostrophes, spaces, a final full stop") {
  CHECK(epure::grading::fold_word("  À l’Extérieur. ") == "a l exterieur");
  CHECK(epure::grading::fold_word("Œuvre") == "oeuvre");
  CHECK(epure::grading::read_word("Étudiant") == std::optional<std::string_view>("student"));
  CHECK(epure::grading::read_word("Feuille") == std::optional<std::string_view>("sheet"));
}
