// The preamble's grader. u = (3, 4), v = (1, 2): u·v = 11, u∧v = 2, ‖u‖ = 5, ‖v‖ = √5,
// cos = 11/(5√5) ≈ 0.9839, sin = 2/(5√5) ≈ 0.1789, angle ≈ 10.30°.
#include <doctest/doctest.h>

#include "grading/exercise_fixture.h"

using epure::grading::Verdict;
using epure::test::exercise;
using epure::test::mark;

namespace {
const std::vector<std::string> kFields = {"dot", "cross", "norm_u", "norm_v", "cos", "sin", "angle_deg"};
}

TEST_CASE("vectors: a sign error in the cross product, and what follows from it") {
  const auto key = exercise(R"({"kind":"vectors","u":[3,4],"v":[1,2]})", kFields);
  const auto m = mark(key, {{"dot", "11"}, {"cross", "-2"}, {"norm_u", "5"}, {"norm_v", "2.24"}, {"cos", "0.98"},
                            {"sin", "-0.18"}, {"angle_deg", "-10.41"}});
  CHECK(m["cross"].mistake == "cross_sign");
  CHECK(m["sin"].verdict == Verdict::follow_through);
  CHECK(m["angle_deg"].verdict == Verdict::follow_through);
  CHECK(m.total() == doctest::Approx(6).epsilon(1e-12));
}

TEST_CASE("vectors: a norm without its root; cos from it follows") {
  const auto key = exercise(R"({"kind":"vectors","u":[3,4],"v":[1,2]})", kFields);
  // ‖v‖ given as v·v = 5: cos = 11/(5·5) = 0.44
  const auto m = mark(key, {{"dot", "11"}, {"cross", "2"}, {"norm_u", "5"}, {"norm_v", "5"}, {"cos", "0.44"}});
  CHECK(m["norm_v"].mistake == "norm_not_rooted");
  CHECK(m["cos"].verdict == Verdict::follow_through);
  CHECK(m["cos"].from == "dot norm_u norm_v");
}

TEST_CASE("vectors: the angle without its sign, or in radians") {
  // u = (1, 2), v = (3, 4): u∧v = −2, the angle ≈ −10.30°
  const auto key = exercise(R"({"kind":"vectors","u":[1,2],"v":[3,4]})", kFields);
  SUBCASE("unsigned") { CHECK(mark(key, {{"angle_deg", "10.30"}})["angle_deg"].mistake == "angle_unsigned"); }
  SUBCASE("radians") { CHECK(mark(key, {{"angle_deg", "-0.18"}})["angle_deg"].mistake == "angle_radians"); }
}
