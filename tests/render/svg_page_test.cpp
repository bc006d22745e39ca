#include "render/svg_page.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include "render/svg_writer.h"

using namespace epure::render;

namespace {

std::size_t count(std::string_view haystack, std::string_view needle) {
  std::size_t n = 0;
  for (auto at = haystack.find(needle); at != std::string_view::npos; at = haystack.find(needle, at + 1)) ++n;
  return n;
}

Document document(int sections) {
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

}  // namespace

TEST_CASE("svg page: every page of a document stacked in one SVG") {
  const Document doc = document(4);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  const std::string svg = pages_to_svg(pages, doc);

  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(count(svg, "class=\"page\"") == pages.size());
  CHECK(count(svg, "class=\"band\"") == pages.size() - 1);
  CHECK(count(svg, "class=\"figure\"") == 4);
  CHECK(svg.find("xml:lang=\"fr\"") != std::string::npos);
  CHECK(svg.find("font-family=\"DejaVu Sans, sans-serif\"") != std::string::npos);
  // The page height, times the pages, plus the bands between them.
  const double h = doc.page.height_pt * static_cast<double>(pages.size()) +
                   kPageGap * static_cast<double>(pages.size() - 1);
  CHECK(svg.find(fmt::format("viewBox=\"0 0 {} {}\"", format_number(doc.page.width_pt), format_number(h))) !=
        std::string::npos);
  // Every string escaped, in <title> as in the header's text.
  CHECK(svg.find("<title>Rays &amp; &lt;circles&gt; — \"worksheet\"</title>") != std::string::npos);
  CHECK(svg.find("<circles>") == std::string::npos);
  // Text as text: the header's "page i/n" and a statement's accents are searchable.
  for (const auto& p : pages) CHECK(svg.find(fmt::format("page {}/{}", p.number, pages.size())) != std::string::npos);
  CHECK(svg.find("décimales") != std::string::npos);
  CHECK(svg.find("Numéro d’étudiant :") != std::string::npos);
}

TEST_CASE("svg page: one page alone, and the same bytes every time") {
  const Document doc = document(2);
  const auto pages = layout_document(doc);
  const std::string one = page_to_svg(pages[0], doc);
  CHECK(count(one, "class=\"page\"") == 1);
  CHECK(count(one, "class=\"band\"") == 0);
  CHECK(one.find(fmt::format("viewBox=\"0 0 {} {}\"", format_number(doc.page.width_pt),
                             format_number(doc.page.height_pt))) != std::string::npos);
  CHECK(document_to_svg(doc) == document_to_svg(doc));
  CHECK(document_to_svg(doc) == pages_to_svg(pages, doc));
}

TEST_CASE("svg page: an empty document is one page with its header") {
  Document doc;
  doc.title = "Empty";
  doc.sheet_id = "AAAA-AAAA";
  const std::string svg = document_to_svg(doc);
  CHECK(count(svg, "class=\"page\"") == 1);
  CHECK(svg.find("page 1/1") != std::string::npos);
  CHECK(svg.find("xml:lang") == std::string::npos);  // no language, no empty tag
}
