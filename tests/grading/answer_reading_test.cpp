// A cell read for its question's type: yes/no in English and French, positions and reasons
// as the sheets print them (or close), faces in any order and separator, blanks.
#include <doctest/doctest.h>

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
        const auto g = read_answer(typed, AnswerType::word);
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
    const auto g = read_answer(miss, AnswerType::word);
    REQUIRE(g.readable());
    CHECK(g.word == "miss");
  }
  for (const char* outside : {"à l'extérieur", "A L\u2019EXTERIEUR", "dehors", "outside"}) {
    CAPTURE(outside);
    CHECK(read_answer(outside, AnswerType::word).word == "outside");
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
