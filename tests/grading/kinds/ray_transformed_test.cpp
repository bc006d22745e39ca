// The ellipse's and rectangle's graders. The figure is centred at C(1,1) with sizes (2, 1), not
// rotated; A(−4, 1), u = (1, 0). Canonical frame: A_c = ((−4 − 1)/2, 0) = (−2.5, 0),
// u_c = (0.5, 0). The ray meets x_c = −1 at t = 3: I = (−1, 1), N = (−1, 0); the ellipse's far
// root is t = 7, at (3, 1).
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const std::vector<std::string> kFields = {"Ac.x", "Ac.y", "uc.x", "uc.y", "inside", "hit", "t", "I.x", "I.y", "N.x", "N.y"};
const std::vector<std::pair<std::string, nlohmann::json>> kCanonical = {
    {"Ac.x", -2.5}, {"Ac.y", 0}, {"uc.x", 0.5}, {"uc.y", 0}};

epure::grading::ExerciseKey ellipse(double angle = 0) {
  return exercise(fmt::format(R"({{"kind":"ray_ellipse","A":[-4,1],"u":[1,0],"C":[1,1],"radii":[2,1],"angle":{}}})", angle),
                  kFields, kCanonical);
}
epure::grading::ExerciseKey rectangle() {
  return exercise(R"({"kind":"ray_rectangle","A":[-4,1],"u":[1,0],"C":[1,1],"half":[2,1],"angle":0})", kFields, kCanonical);
}
}  // namespace

TEST_CASE("ray_ellipse: right answers, then the frame change's mistakes") {
  const auto key = ellipse();
  CHECK(mark(key, {{"Ac.x", "-2.5"}, {"Ac.y", "0"}, {"uc.x", "0.5"}, {"uc.y", "0"}, {"inside", "no"}, {"hit", "yes"},
                   {"t", "3"}, {"I.x", "-1"}, {"I.y", "1"}, {"N.x", "-1"}, {"N.y", "0"}})
            .total() == doctest::Approx(11).epsilon(1e-12));
  SUBCASE("the translation forgotten: S⁻¹·A") {
    CHECK(mark(key, {{"Ac.x", "-2"}, {"Ac.y", "1"}})["Ac.x"].mistake == "translation_forgotten");
  }
  SUBCASE("u_c renormalised") { CHECK(mark(key, {{"uc.x", "1"}, {"uc.y", "0"}})["uc.x"].mistake == "uc_renormalised"); }
  SUBCASE("t from the student's own canonical ray") {
    // A_c = (−3, 0) (wrong): |−3 + 0.5 t| = 1 at t = 4
    const auto m = mark(key, {{"Ac.x", "-3"}, {"Ac.y", "0"}, {"uc.x", "0.5"}, {"uc.y", "0"}, {"t", "4"}});
    CHECK(m["t"].verdict == Verdict::follow_through);
    CHECK(m["t"].from == "Ac uc");
  }
  SUBCASE("u_c renormalised is never named against the student's own right u_c (sheet 0097)") {
    // u_c renormalised (1, 0): |−2.5 + t| = 1 at t = 1.5
    CHECK(mark(key, {{"t", "1.5"}})["t"].mistake == "uc_renormalised");
    const auto m = mark(key, {{"Ac.x", "-2.5"}, {"Ac.y", "0"}, {"uc.x", "0.5"}, {"uc.y", "0"}, {"t", "1.5"}});
    CHECK(m["uc.x"].verdict == Verdict::right);
    CHECK(m["t"].verdict == Verdict::wrong);
    CHECK(m["t"].mistake.empty());
  }
  SUBCASE("the far root") { CHECK(mark(key, {{"t", "7"}})["t"].mistake == "far_intersection"); }
  SUBCASE("the normal not normalised") {
    CHECK(mark(key, {{"N.x", "-0.5"}, {"N.y", "0"}})["N.x"].mistake == "normal_not_unit");
  }
  SUBCASE("the normal inward") { CHECK(mark(key, {{"N.x", "1"}, {"N.y", "0"}})["N.x"].mistake == "normal_inward"); }
  SUBCASE("I left in the canonical frame") {
    CHECK(mark(key, {{"I.x", "-1"}, {"I.y", "0"}})["I.y"].mistake == "not_back_to_world");
  }
}

TEST_CASE("ray_ellipse: the rotation the wrong way") {
  // rotated by 90°: A − C = (−5, 0); R(−90°)·(−5, 0) = (0, 5) → A_c = (0, 5); R(+90°) gives
  // (0, −5) → (0, −5)
  const auto key = exercise(R"({"kind":"ray_ellipse","A":[-4,1],"u":[0,1],"C":[1,1],"radii":[2,1],"angle":90})",
                            {"Ac.x", "Ac.y"}, {{"Ac.x", 0}, {"Ac.y", 5}});
  CHECK(mark(key, {{"Ac.x", "0"}, {"Ac.y", "-5"}})["Ac.y"].mistake == "rotation_sign");
}

TEST_CASE("ray_rectangle: the normal not normalised, I from a wrong t") {
  const auto key = rectangle();
  CHECK(mark(key, {{"N.x", "-0.5"}, {"N.y", "0"}})["N.x"].mistake == "normal_not_unit");
  const auto m = mark(key, {{"t", "3.5"}, {"I.x", "-0.5"}, {"I.y", "1"}});
  CHECK(m["I.x"].verdict == Verdict::follow_through);
}
