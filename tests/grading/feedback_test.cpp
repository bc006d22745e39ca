// The sentences students read (every mistake code of every grader has them in English and
// French), the expected answers as the key prints them, and the wrong points drawn on a
// diagram.
#include <doctest/doctest.h>

#include "exercises/texts.h"
#include "grading/exercise_fixture.h"
#include "grading/feedback_sheet.h"
#include "grading/feedback_text.h"
#include "grading/histogram.h"
#include "grading/kind_grader.h"

using namespace epure::grading;

TEST_CASE("every mistake code has its sentence in every language") {
  for (const auto& language : epure::builtin_languages()) {
    const auto& texts = epure::Texts::builtin(language);
    for (const auto* grader : all_graders())
      for (auto code : grader->mistakes()) {
        CAPTURE(language);
        CAPTURE(code);
        CHECK(texts.has("grading.mistake." + std::string(code)));
      }
  }
}

TEST_CASE("the generic mistakes have their sentence in every language") {
  for (const auto& language : epure::builtin_languages()) {
    CAPTURE(language);
    CHECK(epure::Texts::builtin(language).has("grading.mistake.swapped_coordinates"));
  }
}

TEST_CASE("a choice, a yes/no and a set of sides are shown in the sheet's words") {
  const auto key = epure::test::exercise(R"({"kind":"segments","A":[0,0],"B":[2,0],"C":[3,1],"D":[3,3]})",
                                         {"intersects", "reason"});
  const auto m = epure::test::mark(key, {{"intersects", "no"}, {"reason", "parallel"}});
  const FeedbackText fr("fr", 2), en("en", 2);
  const int reason = key.find("reason"), intersects = key.find("intersects");
  REQUIRE(reason >= 0);
  REQUIRE(intersects >= 0);
  CHECK(fr.given_shown(key.questions[reason], m.marks[reason]) == "parallèles");
  CHECK(en.given_shown(key.questions[reason], m.marks[reason]) == "parallel");
  CHECK(fr.given_shown(key.questions[intersects], m.marks[intersects]) == "non");
  // in the sentence too: "Attendu à l’extérieur, vous avez donné parallèles."
  const std::string said = fr.sentence(key.questions[reason], m.marks[reason]);
  CHECK(said.find("parallèles") != std::string::npos);
  CHECK(said.find("parallel.") == std::string::npos);
}

TEST_CASE("sentences: named mistake, follow-through, unanswered, to check") {
  const auto key = epure::test::exercise(R"({"kind":"projection","A":[1,1],"B":[5,4],"C":[2,6]})",
                                         {"t", "P.x", "P.y", "position"}, {}, "isclose");
  const auto m = epure::test::mark(key, {{"t", "3.8"}, {"P.x", "16.2"}, {"P.y", "12.4"}});
  const FeedbackText en("en", 2), fr("fr", 2);
  CHECK(en.sentence(key.questions[0], m["t"]).find("Expected 0.76, you gave 3.8.") == 0);
  CHECK(en.sentence(key.questions[0], m["t"]).find("‖AB‖²") != std::string::npos);
  CHECK(en.sentence(key.questions[1], m["P.x"]).find("Right from your own t = 3.8") == 0);
  CHECK(fr.sentence(key.questions[1], m["P.x"]).find("report d’erreur") != std::string::npos);
  CHECK(en.sentence(key.questions[3], m["position"]) == "Not answered: expected between A and B.");
  CHECK(fr.expected(key.questions[0]) == "0,76");
  auto with_exact = key.questions[0];
  with_exact.exact = "19/25";
  CHECK(fr.expected(with_exact) == "0,76 (= 19/25)");
  with_exact.exact = "25*sqrt(1066)/1066";  // too long to help: left out
  CHECK(en.expected(with_exact) == "0.76");
  CHECK(en.explanation(key.questions[3], m["position"]).empty());
  const auto u = epure::test::mark(key, {{"t", "n/a"}});
  CHECK(en.sentence(key.questions[0], u["t"]).find("To check: “n/a” is not a number; its points are held") == 0);
  CHECK(fr.sentence(key.questions[0], u["t"]).find("À vérifier\u00a0: «\u00a0n/a\u00a0» n’est pas un nombre") == 0);
}

TEST_CASE("the templates' label markup as plain text") {
  CHECK(plain_text("x_{u}") == "x_u");                  // one character: no parentheses
  CHECK(plain_text("t_{proj} and t_{ab}") == "t_proj and t_ab");  // a name, as the ids spell it
  CHECK(plain_text("A_{1 2}") == "A_(1 2)");            // anything else: in parentheses
  CHECK(plain_text("r^{2} \u2212 d^{2}") == "r\u00b2 \u2212 d\u00b2");
  CHECK(plain_text("S^{\u22121}, (M^{\u22121})^{T}, T^{-1}") == "S\u207b\u00b9, (M\u207b\u00b9)\u1d40, T\u207b\u00b9");
  CHECK(plain_text("r^{ab}, r^{x}") == "r^(ab), r^x");  // no superscript letter for every character
  CHECK(plain_text("\\vec{AB}, \\vec{u}_{c}") == "vec(AB), vec(u)_c");
  CHECK(plain_text("\\{x\\} a\\\\b") == "{x} a\\b");      // escapes
  CHECK(plain_text("x_{1, a_b, r^2, \\vec AB") == "x_{1, a_b, r^2, \\vec AB");  // not markup: as written
  CHECK(plain_text("") == "");
}

TEST_CASE("feedback sentences (JSON) are plain text, explanations (SVG sheets) keep the markup") {
  QuestionKey q;
  q.id = "4.t";
  q.field = "t";
  q.number = 2.5;
  QuestionMark m;
  m.given.state = Given::State::value;
  m.given.raw = "x_{1}";  // the student's own text is kept as typed, markup or not
  m.given.number = 2.9;
  m.verdict = Verdict::wrong;
  m.mistake = "far_intersection";
  const FeedbackText en("en", 2), fr("fr", 2);
  CHECK(en.sentence(q, m) ==
        "Expected 2.50, you gave x_{1}. That is the far intersection J, at t_proj + \u221a(r\u00b2 \u2212 d\u00b2): "
        "the ray meets I first, at t_proj \u2212 \u221a(r\u00b2 \u2212 d\u00b2).");
  CHECK(en.explanation(q, m).find("t_{proj} + \u221a(r^{2} \u2212 d^{2})") != std::string::npos);
  m.mistake = "translation_forgotten";
  CHECK(fr.sentence(q, m).find("A_c = S\u207b\u00b9\u00b7R(\u2212\u03b8)\u00b7(A \u2212 C)") != std::string::npos);
  m.mistake = "normal_wrong_transform";
  CHECK(en.sentence(q, m).find("(M\u207b\u00b9)\u1d40") != std::string::npos);
  CHECK(en.explanation(q, m).find("(M^{\u22121})^{T}") != std::string::npos);
}

TEST_CASE("exact forms for people") {
  CHECK(pretty_exact("(5-2*sqrt(2))/3") == "(5 \u2212 2\u221a2)/3");
  CHECK(pretty_exact("-sqrt(3)/2") == "\u2212\u221a3/2");
  CHECK(pretty_exact("16/61") == "16/61");
}

TEST_CASE("a wrong point is drawn on the key's diagram, a right one is not") {
  const auto key = epure::test::exercise(R"({"kind":"projection","A":[1,1],"B":[5,4],"C":[2,6]})",
                                         {"t", "P.x", "P.y", "position"});
  const FeedbackText en("en", 2);
  auto scene_with = [&](const char* px) {
    epure::render::Scene scene;
    scene.panels.emplace_back();
    scene.panels[0].view = {0, 0, 6, 6};
    const auto m = epure::test::mark(key, {{"t", "0.76"}, {"P.x", px}, {"P.y", "3.28"}});
    overlay_answers(scene, key, m.marks, en);
    return scene;
  };
  const auto wrong = scene_with("4.5");
  REQUIRE(wrong.panels[0].items.size() == 1);
  const auto* mark = std::get_if<epure::render::PointMark>(&wrong.panels[0].items[0]);
  REQUIRE(mark);
  // in the student's own colour, never orange (a candidate side's); its label says whose it is
  CHECK(mark->role == epure::render::Role::given);
  CHECK(mark->at.x == doctest::Approx(4.5).epsilon(1e-12));
  CHECK(mark->label->text == "P (yours)");
  CHECK(scene_with("4.04").panels[0].items.empty());
}

TEST_CASE("the histogram has a bar for every non-empty bin") {
  ClassStatistics stats({});
  const FeedbackText en("en", 2);
  const auto scene = histogram_scene(stats, en);
  REQUIRE(scene.panels.size() == 1);
  CHECK(scene.title == "Scores of the class");
}
