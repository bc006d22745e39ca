#pragma once
// A small French worksheet for the page backends' tests (svg_page_test, pdf_document_test): a
// header with accents and characters to escape, and `sections` exercises, each with a statement
// (a vector, a subscript, a square), a figure and two answer fields.
#include <fmt/format.h>

#include <cstddef>
#include <string_view>
#include <utility>

#include "render/document.h"

namespace epure::render::testing {

inline std::size_t count(std::string_view haystack, std::string_view needle) {
  std::size_t n = 0;
  for (auto at = haystack.find(needle); at != std::string_view::npos; at = haystack.find(needle, at + 1)) ++n;
  return n;
}

inline Document sample_document(int sections) {
  Document doc;
  doc.title = "Rays & <circles> — \"worksheet\"";
  doc.course = "Informatique graphique, M1";
  doc.sheet_id = "K7QF-3M2X";
  doc.language = "fr";
  doc.student_fields = true;
  doc.words = {"Nom :", "Numéro d’étudiant :", "page", "oui", "non"};
  for (int n = 1; n <= sections; ++n) {
    Section s;
    s.add(Heading{fmt::format("Exercice {} — rayon et cercle", n), 1});
    s.add(Paragraph{"Le rayon part de A dans la direction \\vec{u} ; calculer t_{ab} puis d^{2}. "
                    "Arrondir à deux décimales, avec une virgule décimale.",
                    false});
    Scene scene;
    scene.title = "Rayon et cercle";
    Panel panel;
    panel.view = {-1, -1, 7, 5};
    panel.add(Grid{1, true});
    panel.add(Circle{{4, 2}, 1.5, Role::data});
    panel.add(Ray{{0, 1}, {4, 1}, Role::data});
    scene.panels.push_back(std::move(panel));
    s.add(Figure{std::move(scene), 0.7});
    s.add(AnswerField{fmt::format("{}.hit", n), "Touché ?", AnswerField::Kind::boolean, {}});
    s.add(AnswerField{fmt::format("{}.I", n), "I =", AnswerField::Kind::point, {}});
    doc.sections.push_back(std::move(s));
  }
  return doc;
}

}  // namespace epure::render::testing
