// A cell read for its question's type: yes/no in English and French, positions and reasons
// as the sheets print them (or close), faces in any order and separator, blanks.
#include <doctest/doctest.h>

#include <array>
#include <string>
#include <string_view>

#include "exercises/texts.h"
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
    const auto g = read_answer(cell, AnswerType::choice);
    REQUIRE(g.readable());
    CHECK(g.word == word);
  }
  SUBCASE("a yes is not a position") { CHECK(read_answer("oui", AnswerType::choice).why == "word"); }
  SUBCASE("nor is nonsense") { CHECK(read_answer("dunno", AnswerType::choice).why == "word"); }
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

namespace {

// A word as a student may also type it: accents left out (é → e, à → a, ’ → ').
std::string without_accents(std::string_view s) {
  static const std::pair<std::string_view, std::string_view> kPlain[] = {
      {"\u00e9", "e"}, {"\u00e8", "e"}, {"\u00ea", "e"}, {"\u00e0", "a"}, {"\u00e2", "a"}, {"\u00f4", "o"},
      {"\u00ee", "i"}, {"\u00e7", "c"}, {"\u00f9", "u"}, {"\u00fb", "u"}, {"\u2019", "'"}};
  std::string out(s);
  for (const auto& [from, to] : kPlain)
    for (std::size_t at = out.find(from); at != std::string::npos; at = out.find(from, at + to.size()))
      out.replace(at, from.size(), to);
  return out;
}

std::string upper_ascii(std::string s) {
  for (char& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return s;
}

}  // namespace

TEST_CASE("every wording a sheet prints for a choice reads back to its word, in every language") {
  int seen = 0;
  for (const auto& language : epure::builtin_languages()) {
    const auto& texts = epure::Texts::builtin(language);
    for (const auto& [key, text] : texts.all()) {
      if (key.rfind("choice.", 0) != 0) continue;
      const std::string word = key.substr(7);
      for (const std::string& typed : {text, upper_ascii(text), without_accents(text), upper_ascii(without_accents(text))}) {
        CAPTURE(language);
        CAPTURE(typed);
        const auto g = read_answer(typed, AnswerType::choice);
        REQUIRE(g.readable());
        CHECK(g.word == word);
      }
      ++seen;
    }
  }
  CHECK(seen >= 18);  // nine choices in each of two languages
}

TEST_CASE("every spelling the templates list reads back to its word, in every language") {
  for (const auto& language : epure::builtin_languages()) {
    const auto& texts = epure::Texts::builtin(language);
    for (const auto& [key, list] : texts.all()) {
      if (key.rfind("grading.read.", 0) != 0) continue;
      // what surrounds an answer (lead, tail) is no answer
      if (key == "grading.read.lead" || key == "grading.read.tail") continue;
      const std::string token = key.substr(13);
      std::string_view rest = list;
      while (!rest.empty()) {
        const auto comma = rest.find(',');
        const std::string spelling = epure::grading::fold_word(rest.substr(0, comma));
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
        if (spelling.empty()) continue;
        CAPTURE(language);
        CAPTURE(spelling);
        // one spelling, one meaning: a word two lists share would be read as either
        const auto w = epure::grading::read_word(spelling);
        REQUIRE(w.has_value());
        CHECK(*w == token);
      }
    }
  }
}

TEST_CASE("the sheets' own wordings of a miss, and short forms") {
  for (const char* miss : {"passe à côté", "Passe a cote", "la droite passe à côté", "manqué", "MANQUE", "passes beside"}) {
    CAPTURE(miss);
    const auto g = read_answer(miss, AnswerType::choice);
    REQUIRE(g.readable());
    CHECK(g.word == "miss");
  }
  for (const char* outside : {"à l'extérieur", "A L\u2019EXTERIEUR", "dehors", "outside"}) {
    CAPTURE(outside);
    CHECK(read_answer(outside, AnswerType::choice).word == "outside");
  }
}

TEST_CASE("an empty set of sides, as students write it") {
  for (const char* none : {"aucun", "Aucune", "none", "\u2205", "-", "\u2014", "rien", "aucun côté", "{}"}) {
    CAPTURE(none);
    const auto g = read_answer(none, AnswerType::faces);
    REQUIRE(g.readable());
    CHECK(g.faces == 0);
  }
}

TEST_CASE("a unit typed after a number is the number (issue 31: 4,75 cm, 1,04 u)") {
  const std::pair<const char*, double> cases[] = {
      {"4,75 cm", 4.75}, {"1,04 u", 1.04},   {"4,75cm", 4.75},     {"1,8 u²", 1.8},   {"1,8 cm2", 1.8},
      {"3 unités", 3},   {"2.5 units", 2.5}, {"−0,25 u.a.", -0.25}, {"50,91°", 50.91}, {"−71,57 °", -71.57},
      {"t = 4,75", 4.75}, {"d² = 1,8", 1.8}, {"t_proj=4,02", 4.02}, {"I.x = 2,14 cm", 2.14}, {"4,75.", 4.75},
      {"√11 u", 3.3166247903554}};
  for (const auto& [cell, value] : cases) {
    CAPTURE(cell);
    const auto g = read_answer(cell, AnswerType::number);
    REQUIRE(g.readable());
    CHECK(g.number == doctest::Approx(value).epsilon(1e-12));
  }
  SUBCASE("what is not a unit of the figure stays unreadable, to be checked") {
    for (const char* cell : {"0.89 rad", "4 km/h", "cm", "5 cm cm", "5°°", "2 = 2", "abc = 3 = 4", "4,75 um"}) {
      CAPTURE(cell);
      CHECK(read_answer(cell, AnswerType::number).state == Given::State::unreadable);
    }
  }
}

TEST_CASE("a whole point typed in one cell is split into its coordinates, or is to check when ambiguous") {
  using epure::grading::PointCell;
  using epure::grading::read_point_cell;
  std::array<std::string_view, 3> parts{};
  SUBCASE("the course's (x ; y), in any language") {
    for (bool comma : {true, false}) {
      CHECK(read_point_cell("(3 ; 5)", 2, comma, parts) == PointCell::point);
      CHECK(parts[0] == "3");
      CHECK(parts[1] == "5");
      CHECK(read_point_cell("P = (1,5 ; −2)", 2, comma, parts) == PointCell::point);
      CHECK(parts[0] == "1,5");
      CHECK(parts[1] == "−2");
      CHECK(read_point_cell("[2;1;0]", 3, comma, parts) == PointCell::point);
      CHECK(parts[2] == "0");
      CHECK(read_point_cell("(3, 5)", 2, comma, parts) == PointCell::point);  // a comma and a space
    }
  }
  SUBCASE("(3,5): a point with decimal points, but 3,5 itself with decimal commas: not guessed") {
    CHECK(read_point_cell("(3,5)", 2, false, parts) == PointCell::point);
    CHECK(read_point_cell("(3,5)", 2, true, parts) == PointCell::ambiguous);
    // without brackets, the number 3,5 in every language (decimal commas are read anywhere)
    CHECK(read_point_cell("3,5", 2, true, parts) == PointCell::not_a_point);
    CHECK(read_point_cell("3,5", 2, false, parts) == PointCell::not_a_point);
  }
  SUBCASE("the wrong number of coordinates, or parts that are no numbers") {
    CHECK(read_point_cell("(3 ; 5)", 3, true, parts) == PointCell::not_a_point);
    CHECK(read_point_cell("(3 ; 5 ; 1)", 2, true, parts) == PointCell::not_a_point);
    CHECK(read_point_cell("(a ; 5)", 2, true, parts) == PointCell::not_a_point);
    CHECK(read_point_cell("(3 ; )", 2, true, parts) == PointCell::not_a_point);
    CHECK(read_point_cell("3", 2, true, parts) == PointCell::not_a_point);
  }
}

TEST_CASE("the wordings students use for every choice answer, in both languages (issue 31: hors segment)") {
  const std::pair<const char*, const char*> cases[] = {
      // segments: the reason
      {"hors segment", "outside"}, {"hors des segments", "outside"}, {"Hors de [AB]", "outside"},
      {"les droites se coupent hors des segments", "outside"}, {"outside the segments", "outside"},
      {"off the segments", "outside"}, {"droites parallèles", "parallel"}, {"les droites sont parallèles", "parallel"},
      {"droites confondues", "collinear"}, {"sur la même droite", "collinear"}, {"on the same line", "collinear"},
      // projection: the position
      {"P est avant A", "before"}, {"t < 0", "before"}, {"sur le segment", "between"}, {"sur [AB]", "between"},
      {"0 ≤ t ≤ 1", "between"}, {"au-delà de B", "after"}, {"beyond B", "after"}, {"P is after B", "after"},
      // rays: the reason (the course: "le rayon ne se dirige pas vers le cercle", "passe à côté du cercle")
      {"le rayon passe à côté du cercle", "miss"}, {"la droite passe à côté de la sphère", "miss"},
      {"d² > r²", "miss"}, {"the ray misses the circle", "miss"}, {"ne touche pas le carré", "miss"},
      {"mauvaise direction", "behind"}, {"le rayon part à l’opposé du cercle", "behind"}, {"t_proj < 0", "behind"},
      {"the ray heads away", "behind"}, {"wrong direction", "behind"}};
  for (const auto& [cell, word] : cases) {
    CAPTURE(cell);
    const auto g = read_answer(cell, AnswerType::choice);
    REQUIRE(g.readable());
    CHECK(g.word == word);
  }
  SUBCASE("what says no case stays to check: 'pas d'intersection' is a miss, a ray behind, parallel lines…") {
    for (const char* cell : {"pas d'intersection", "no intersection", "les segments ne se coupent pas", "hors"}) {
      CAPTURE(cell);
      CHECK(read_answer(cell, AnswerType::choice).state == Given::State::unreadable);
    }
  }
}
