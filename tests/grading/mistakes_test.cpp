// Every named mistake every grader knows: a literal wrong answer that triggers it, and the
// sentence a student reads for it, in English and in French. The table must cover exactly the
// codes the graders declare (a new code without a case here fails the last check).
#include <doctest/doctest.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "exercises/texts.h"
#include "grading/exercise_fixture.h"
#include "grading/feedback_text.h"
#include "grading/kind_grader.h"

using epure::grading::FeedbackText;
using epure::test::exercise;
using epure::test::exercise_in_space;
using epure::test::mark;

namespace {

struct Case {
  std::string code;
  epure::grading::ExerciseKey key;
  std::vector<std::pair<std::string, std::string>> answers;
  std::string question;  // the field that carries the mistake
};

// The template's text up to its first placeholder: what every rendering of it starts with.
// The template's text before its first placeholder, plain as a sentence (JSON) writes it.
std::string fixed_part(const std::string& language, const std::string& code) {
  const auto& text = epure::Texts::builtin(language).get("grading.mistake." + code);
  return epure::grading::plain_text(text.substr(0, text.find("${")));
}

std::vector<Case> cases() {
  const char* projection = R"({"kind":"projection","A":[1,1],"B":[5,4],"C":[2,6]})";
  const char* circle = R"({"kind":"ray_circle","A":[0,0],"u":[2,0],"C":[5,1],"r":2})";
  const char* square = R"({"kind":"ray_square","A":[3,0.5],"u":[-4,-1]})";
  const char* segments = R"({"kind":"segments","A":[0,0],"B":[4,0],"C":[1,-1],"D":[1,1]})";
  const std::vector<std::string> circle_fields = {"t_proj", "d2", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"};
  const std::vector<std::string> square_fields = {"faces", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"};
  const std::vector<std::string> vector_fields = {"dot", "cross", "norm_u", "norm_v", "cos", "sin", "angle_deg"};
  // An ellipse C(1,1), radii (2,1), turned 90°, A(−4,1), u = (0,3) (û = (0,1)):
  //   A − C = (−5,0); R(−90°)(x,y) = (y,−x): (0,5); S⁻¹: A_c = (0,5)
  //   R(+90°) instead: (0,−5)                        rotation_sign
  //   A not translated: S⁻¹R(−90°)(−4,1) = (0.5,4)   translation_forgotten
  //   R(−90°)·S⁻¹·(A − C) = R(−90°)(−2.5,0) = (0,2.5)   transform_order
  //   u_c = S⁻¹R(−90°)û = (0.5,0); renormalised (1,0); from u itself (1.5,0);
  //   û translated like a point: S⁻¹R(−90°)(û − C) = S⁻¹R(−90°)(−1,0) = (0,1)
  const auto turned = exercise(R"({"kind":"ray_ellipse","A":[-4,1],"u":[0,3],"C":[1,1],"radii":[2,1],"angle":90})",
                               {"Ac.x", "Ac.y", "uc.x", "uc.y"}, {{"Ac.x", 0}, {"Ac.y", 5}, {"uc.x", 0.5}, {"uc.y", 0}});
  // An ellipse C(0,0), radii (2,1), A(1.2,3), u = (0,−1): I = (1.2,0.8), I_c = (0.6,0.8) = N_c;
  //   N = unit(S⁻¹N_c) = unit(0.3,0.8) ≈ (0.351,0.936); not unit: (0.3,0.8);
  //   carried by S instead of S⁻ᵀ: unit(1.2,0.8) ≈ (0.832,0.555); left canonical: (0.6,0.8)
  const auto slanted =
      exercise(R"({"kind":"ray_ellipse","A":[1.2,3],"u":[0,-1],"C":[0,0],"radii":[2,1],"angle":0})", {"N.x", "N.y"});
  // The axis-aligned ellipse of ray_transformed_test.cpp: A_c = (−2.5,0), t = 3, far root 7,
  // I = (−1,1), I_c = (−1,0), N = (−1,0).
  const auto flat = exercise(R"({"kind":"ray_ellipse","A":[-4,1],"u":[1,0],"C":[1,1],"radii":[2,1],"angle":0})",
                             {"Ac.x", "Ac.y", "uc.x", "uc.y", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"},
                             {{"Ac.x", -2.5}, {"Ac.y", 0}, {"uc.x", 0.5}, {"uc.y", 0}});
  // A inside the circle C(0,0), r = 2 from A(1,0), u = (1,0): t = 1; the root behind A is −3
  const auto inside = exercise(R"({"kind":"ray_circle","A":[1,0],"u":[1,0],"C":[0,0],"r":2})", circle_fields);
  return {
      {"t_unsquared_norm", exercise(projection, {"t"}), {{"t", "3.8"}}, "t"},
      {"t_not_divided", exercise(projection, {"t"}), {{"t", "19"}}, "t"},
      {"t_swapped", exercise(segments, {"t_ab", "t_cd"}), {{"t_ab", "0.5"}, {"t_cd", "0.25"}}, "t_ab"},
      {"cross_sign", exercise(segments, {"t_ab", "t_cd"}), {{"t_ab", "-0.25"}}, "t_ab"},
      {"faces_inner_half_planes", exercise(R"({"kind":"ray_square","A":[3,0.5],"u":[-1,0]})", {"faces"}), {{"faces", "-x +y -y"}}, "faces"},
      {"cross_sign", exercise(R"({"kind":"vectors","u":[3,4],"v":[1,2]})", vector_fields), {{"cross", "-2"}}, "cross"},
      {"norm_not_rooted", exercise(R"({"kind":"vectors","u":[3,4],"v":[1,2]})", vector_fields), {{"norm_v", "5"}}, "norm_v"},
      // u∧v = (2, −7, 4) for u = (1, 2, 3), v = (−2, 0, 1); x_u·z_v − z_u·x_v = 7
      {"cross_middle_sign",
       exercise_in_space("vectors_3d", R"({"kind":"vectors","u":[1,2,3],"v":[-2,0,1]})",
                         {"dot", "cross.x", "cross.y", "cross.z", "norm_u", "norm_v", "cos", "sin", "angle_deg"}),
       {{"cross.x", "2"}, {"cross.y", "7"}, {"cross.z", "4"}},
       "cross.y"},
      {"angle_unsigned", exercise(R"({"kind":"vectors","u":[1,2],"v":[3,4]})", vector_fields), {{"angle_deg", "10.30"}}, "angle_deg"},
      {"angle_radians", exercise(R"({"kind":"vectors","u":[1,2],"v":[3,4]})", vector_fields), {{"angle_deg", "-0.18"}}, "angle_deg"},
      {"direction_not_unit", exercise(circle, circle_fields), {{"t_proj", "10"}}, "t_proj"},
      {"far_intersection", exercise(circle, circle_fields), {{"t", "6.73"}}, "t"},
      {"near_root_inside", inside, {{"t", "-3"}}, "t"},
      {"normal_not_unit", exercise(circle, circle_fields), {{"N.x", "-1.73"}, {"N.y", "-1"}}, "N.x"},
      {"normal_inward", exercise(circle, circle_fields), {{"N.x", "0.87"}, {"N.y", "0.5"}}, "N.x"},
      {"faces_wrong_half_planes", exercise(square, square_fields), {{"faces", "-x"}}, "faces"},
      {"faces_from_direction", exercise(square, square_fields), {{"faces", "+x +y"}}, "faces"},
      {"normal_inward", exercise(square, square_fields), {{"N.x", "-1"}, {"N.y", "0"}}, "N.x"},
      {"direction_not_unit", exercise(square, square_fields), {{"t", "0.5"}}, "t"},
      {"rotation_sign", turned, {{"Ac.x", "0"}, {"Ac.y", "-5"}}, "Ac.y"},
      {"translation_forgotten", turned, {{"Ac.x", "0.5"}, {"Ac.y", "4"}}, "Ac.x"},
      {"transform_order", turned, {{"Ac.x", "0"}, {"Ac.y", "2.5"}}, "Ac.y"},
      {"uc_renormalised", turned, {{"uc.x", "1"}, {"uc.y", "0"}}, "uc.x"},
      {"direction_not_unit", turned, {{"uc.x", "1.5"}, {"uc.y", "0"}}, "uc.x"},
      {"direction_translated", turned, {{"uc.x", "0"}, {"uc.y", "1"}}, "uc.y"},
      {"far_intersection", flat, {{"t", "7"}}, "t"},
      {"not_back_to_world", flat, {{"I.x", "-1"}, {"I.y", "0"}}, "I.y"},
      {"normal_inward", flat, {{"N.x", "1"}, {"N.y", "0"}}, "N.x"},
      {"normal_not_unit", slanted, {{"N.x", "0.3"}, {"N.y", "0.8"}}, "N.x"},
      {"normal_wrong_transform", slanted, {{"N.x", "0.832"}, {"N.y", "0.555"}}, "N.x"},
      {"not_back_to_world", slanted, {{"N.x", "0.6"}, {"N.y", "0.8"}}, "N.x"},
  };
}

epure::test::Marked mark_case(const Case& c) {
  // the fixture takes an initializer list; rebuild the cells by hand
  auto storage = std::make_shared<std::vector<std::string>>(c.key.questions.size());
  for (const auto& [field, text] : c.answers) {
    const int i = c.key.find(field);
    REQUIRE_MESSAGE(i >= 0, field);
    (*storage)[static_cast<std::size_t>(i)] = text;
  }
  std::vector<std::string_view> cells(storage->begin(), storage->end());
  epure::test::Marked m{&c.key, {}, storage};
  epure::grading::mark_exercise(c.key, cells, epure::grading::MarkingOptions{}, m.marks);
  return m;
}

}  // namespace

TEST_CASE("every named mistake: triggered by a literal answer, explained in English and French") {
  const FeedbackText en("en", 2), fr("fr", 2);
  std::set<std::string> seen;
  for (const auto& c : cases()) {
    CAPTURE(c.code);
    CAPTURE(c.question);
    const auto m = mark_case(c);
    const auto& got = m[c.question];
    CHECK(got.mistake == c.code);
    CHECK(got.verdict != epure::grading::Verdict::right);
    const auto& q = c.key.questions[static_cast<std::size_t>(c.key.find(c.question))];
    for (const auto* text : {&en, &fr}) {
      const std::string language = text == &en ? "en" : "fr";
      CAPTURE(language);
      const std::string sentence = text->sentence(q, got);
      CAPTURE(sentence);
      const std::string fixed = fixed_part(language, c.code);
      REQUIRE_FALSE(fixed.empty());
      CHECK(sentence.find(fixed) != std::string::npos);
      CHECK(sentence.find("${") == std::string::npos);  // every placeholder filled
    }
    seen.insert(c.code);
  }
  std::set<std::string> declared;
  for (const auto* grader : epure::grading::all_graders())
    for (auto code : grader->mistakes()) declared.insert(std::string(code));
  for (const auto& code : declared) {
    CAPTURE(code);
    CHECK(seen.count(code) == 1);
  }
}
