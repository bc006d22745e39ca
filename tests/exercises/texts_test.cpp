// The texts: both languages complete, with the same placeholders for every key; substitution
// refuses a missing value; French typography.
#include <doctest/doctest.h>

#include <regex>
#include <set>

#include "exercises/texts.h"

namespace {
std::set<std::string> placeholders(const std::string& text) {
  std::set<std::string> names;
  static const std::regex re(R"(\$\{([A-Za-z0-9_]+)\})");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1]);
  return names;
}
}  // namespace

TEST_CASE("English and French have the same keys with the same placeholders") {
  const auto& en = epure::Texts::builtin("en");
  const auto& fr = epure::Texts::builtin("fr");
  CHECK(en.language() == "en");
  CHECK(fr.language() == "fr");
  for (const auto& [key, text] : en.all()) {
    CAPTURE(key);
    REQUIRE(fr.has(key));
    CHECK(placeholders(text) == placeholders(fr.get(key)));
  }
  for (const auto& [key, text] : fr.all()) {
    CAPTURE(key);
    CHECK(en.has(key));
  }
}

TEST_CASE("French sentences set a no-break space before : ; ? !") {
  const auto& fr = epure::Texts::builtin("fr");
  for (const auto& [key, text] : fr.all()) {
    CAPTURE(key);
    for (const char* mark : {" :", " ;", " ?", " !"}) CHECK(text.find(mark) == std::string::npos);
  }
}

TEST_CASE("substitution fills every placeholder or refuses") {
  CHECK(epure::substitute("A${A} and t_{ab}", {{"A", "(1, 2)"}}) == "A(1, 2) and t_{ab}");
  CHECK_THROWS_AS(epure::substitute("${missing}", {}), std::invalid_argument);
  CHECK_THROWS_AS(epure::Texts::builtin("de"), std::invalid_argument);
}
