// epure_layout_demo OUT_DIR: writes a sample French worksheet and its key, each as one SVG with
// its pages stacked, to look at (rsvg-convert to PNG) and to check (xmllint) in
// tests/cli/layout_svg.sh. Every kind of block and answer field appears at least once.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "render/document.h"
#include "render/svg_page.h"

using namespace epure::render;

namespace {

Label label(const char* text, P2 at, Side side, Role role = Role::data) { return Label{text, at, side, role}; }

Scene projection_scene() {
  Scene s;
  s.title = "Projection orthogonale de C sur (AB)";
  s.description = "Les points A, B et C sur une grille ; la droite (AB).";
  Panel p;
  p.view = {-1, -1, 9, 6};
  p.add(Grid{1, true});
  p.add(Line{{1, 1}, {7, 3}, Role::construction});
  p.add(Segment{{1, 1}, {7, 3}, Role::data, false});
  p.add(PointMark{{1, 1}, Role::data, label("A", {1, 1}, Side::below)});
  p.add(PointMark{{7, 3}, Role::data, label("B", {7, 3}, Side::below)});
  p.add(PointMark{{3, 5}, Role::data, label("C", {3, 5}, Side::above)});
  s.panels.push_back(std::move(p));
  return s;
}

Scene circle_scene() {
  Scene s;
  s.title = "Rayon et cercle";
  s.description = "Un rayon issu de A de direction u et le cercle de centre C et de rayon r.";
  Panel p;
  p.view = {-1, -1, 9, 6};
  p.add(Grid{1, true});
  p.add(Circle{{5, 3}, 2, Role::data});
  p.add(Ray{{0, 1}, {4, 3}, Role::data});
  p.add(PointMark{{0, 1}, Role::data, label("A", {0, 1}, Side::below_right)});
  p.add(PointMark{{5, 3}, Role::data, label("C", {5, 3}, Side::right)});
  p.add(Arrow{{0, 1}, {0.8, 1.6}, Role::data});
  p.add(Label{"\\vec{u}", {0.4, 1.3}, Side::above_left, Role::data});
  s.panels.push_back(std::move(p));
  return s;
}

Document sheet() {
  Document d;
  d.title = "Utilitaires d’un lancer de rayons — feuille d’exercices";
  d.course = "Informatique graphique, M1";
  d.sheet_id = "K7QF-3M2X";
  d.language = "fr";
  d.student_fields = true;
  d.words = {"Nom :", "Numéro d’étudiant :", "page", "oui", "non"};
  d.header_note = "Durée : 1 h 30. Documents autorisés : une feuille A4 manuscrite.";

  Section intro;
  intro.add(Paragraph{"Arrondir chaque résultat intermédiaire à deux décimales et écrire les "
                      "nombres avec une virgule décimale (2,17 et non 2.17).",
                      true});
  d.sections.push_back(std::move(intro));

  Section one;
  one.add(Heading{"Exercice 1 — projection orthogonale", 1});
  one.add(Paragraph{"On donne les points A(1 ; 1), B(7 ; 3) et C(3 ; 5). Calculer le paramètre "
                    "t = \\vec{AB}·\\vec{AC} / ‖\\vec{AB}‖^{2} de la projection orthogonale P de C "
                    "sur la droite (AB), puis les coordonnées de P. Dire si P est avant A, entre A "
                    "et B, ou après B.",
                    false});
  one.add(Figure{projection_scene(), 0.62});
  one.add(AnswerField{"1.t", "t =", AnswerField::Kind::number, {}});
  one.add(AnswerField{"1.P", "P =", AnswerField::Kind::point, {}});
  one.add(AnswerField{"1.position", "P est", AnswerField::Kind::choice, {"avant A", "entre A et B", "après B"}});
  d.sections.push_back(std::move(one));

  Section two;
  two.add(Heading{"Exercice 2 — intersection de deux segments", 1});
  two.add(Paragraph{"Les segments [AB] et [CD] joignent A(0 ; 0), B(4 ; 2), C(1 ; 3) et D(3 ; −1). "
                    "Écrire I = A + t_{ab} \\vec{AB} = C + t_{cd} \\vec{CD} et résoudre le système. "
                    "Les segments se coupent-ils ?",
                    false});
  two.add(AnswerField{"2.intersects", "Les segments se coupent :", AnswerField::Kind::boolean, {}});
  two.add(AnswerField{"2.t_ab", "t_{ab} =", AnswerField::Kind::number, {}});
  two.add(AnswerField{"2.t_cd", "t_{cd} =", AnswerField::Kind::number, {}});
  two.add(AnswerField{"2.I", "I =", AnswerField::Kind::point, {}});
  d.sections.push_back(std::move(two));

  Section three;
  three.add(Heading{"Exercice 3 — rayon et cercle", 1});
  three.add(Paragraph{"Le rayon part de A(0 ; 1) dans la direction \\vec{u} = (4 ; 3) ; le cercle a "
                      "pour centre C(5 ; 3) et pour rayon r = 2. Projeter C sur le rayon pour obtenir "
                      "P, calculer d^{2} = CP^{2}, puis, s’il y a un point d’impact, utiliser "
                      "Pythagore dans le triangle CPI : PI = √(r^{2} − d^{2}).",
                      false});
  three.add(Figure{circle_scene(), 0.62});
  three.add(AnswerField{"3.d2", "d^{2} =", AnswerField::Kind::number, {}});
  three.add(AnswerField{"3.hit", "Le rayon touche le cercle :", AnswerField::Kind::boolean, {}});
  three.add(AnswerField{"3.I", "I =", AnswerField::Kind::point, {}});
  three.add(AnswerField{"3.N", "normale \\vec{N} =", AnswerField::Kind::point, {}});
  d.sections.push_back(std::move(three));

  Section four;
  four.add(Heading{"Exercice 4 — rayon et cube", 1});
  four.add(Paragraph{"Le rayon part de O(3 ; 0,5 ; −2) dans la direction \\vec{v} = (−2 ; 0 ; 1). "
                     "Quelles faces du cube [−1 ; 1]^{3} traverse-t-il, et en quel point entre-t-il ?",
                     false});
  four.add(AnswerField{"4.faces", "Faces touchées :", AnswerField::Kind::faces,
                       {"x = −1", "x = 1", "y = −1", "y = 1", "z = −1", "z = 1"}});
  four.add(AnswerField{"4.I", "point d’entrée I =", AnswerField::Kind::point3, {}});
  d.sections.push_back(std::move(four));
  return d;
}

Document key() {
  Document d = sheet();
  d.title = "Utilitaires d’un lancer de rayons — corrigé";
  d.student_fields = false;
  d.header_note.clear();
  d.sections.clear();

  Section one;
  one.add(Heading{"Exercice 1 — projection orthogonale", 1});
  one.add(Heading{"Solution détaillée", 2});
  one.add(Paragraph{"\\vec{AB} = (6 ; 2), \\vec{AC} = (2 ; 4), \\vec{AB}·\\vec{AC} = 20, "
                    "‖\\vec{AB}‖^{2} = 40, donc t = 20/40 = 0,5 ⇒ P = A + 0,5 \\vec{AB} = (4 ; 2).",
                    false});
  one.add(Figure{projection_scene(), 0.5});
  one.add(AnswerLine{"1.t", "t", "0,5 (exact : 1/2)"});
  one.add(AnswerLine{"1.P", "P", "(4 ; 2)"});
  one.add(AnswerLine{"1.position", "P est", "entre A et B"});
  d.sections.push_back(std::move(one));

  Section two;
  two.add(Heading{"Exercice 2 — intersection de deux segments", 1});
  two.add(AnswerLine{"2.intersects", "Les segments se coupent", "oui"});
  two.add(AnswerLine{"2.t_ab", "t_{ab}", "≈ 0,43 (exact : 3/7)"});
  two.add(AnswerLine{"2.t_cd", "t_{cd}", "≈ 0,29 (exact : 2/7) ; tolérance ±0,01, ou 1 % de la "
                                          "valeur, la plus grande des deux"});
  two.add(AnswerLine{"2.I", "I", "≈ (1,71 ; 0,86)"});
  d.sections.push_back(std::move(two));
  return d;
}

bool write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: epure_layout_demo OUT_DIR\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const bool ok = write(dir / "sheet.svg", document_to_svg(sheet())) &&
                  write(dir / "key.svg", document_to_svg(key()));
  return ok ? 0 : 1;
}
