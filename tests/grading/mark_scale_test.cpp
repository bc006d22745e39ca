// Marks out of N, rounded to a stated step, halves up; French sets out of 20 by default.
#include <doctest/doctest.h>

#include <stdexcept>

#include "grading/answer_key.h"
#include "grading/mark_scale.h"

using namespace epure::grading;

TEST_CASE("which scale: --out-of, else the spec's scale, else 20 for French, else points") {
  KeyInfo info;
  CHECK(MarkScale::choose(info, "fr", 0, 0).out_of == 20.0);
  CHECK_FALSE(MarkScale::choose(info, "en", 0, 0).out_of);
  CHECK(MarkScale::choose(info, "en", 10, 0).out_of == 10.0);
  info.scale = 100;
  CHECK(MarkScale::choose(info, "fr", 0, 0).out_of == 100.0);
  CHECK(MarkScale::choose(info, "fr", 20, 0).out_of == 20.0);
  CHECK(MarkScale::choose(info, "fr", 0, 0).step == 0.01);
  CHECK(MarkScale::choose(info, "fr", 0, 0.25).step == 0.25);
  CHECK_THROWS_AS(MarkScale::choose(info, "fr", 0, 0.3), std::invalid_argument);
  CHECK_THROWS_AS(MarkScale::choose(info, "fr", 0, 2), std::invalid_argument);
  CHECK_THROWS_AS(MarkScale::choose(info, "fr", -20, 0), std::invalid_argument);
}

TEST_CASE("a mark: score / max × N, to the nearest step, halves up") {
  MarkScale s;
  s.out_of = 20;
  CHECK(s.mark(43, 43) == 20);
  CHECK(s.mark(0, 43) == 0);
  CHECK(s.mark(10.25, 40) == doctest::Approx(5.13).epsilon(1e-12));   // 5.125: the half goes up
  CHECK(s.mark(29, 43) == doctest::Approx(13.49).epsilon(1e-12));     // 13.4883…
  CHECK(s.mark(31.5, 43) == doctest::Approx(14.65).epsilon(1e-12));   // 14.6511…
  s.step = 0.5;
  CHECK(s.mark(29, 43) == doctest::Approx(13.5).epsilon(1e-12));
  CHECK(s.mark(10.25, 40) == doctest::Approx(5).epsilon(1e-12));       // 5.125 → 5
  s.step = 0.25;
  CHECK(s.mark(10.75, 43) == doctest::Approx(5).epsilon(1e-12));       // 5.0 exactly
  CHECK(s.mark(21.5, 43) == doctest::Approx(10).epsilon(1e-12));
  MarkScale points;
  CHECK(points.mark(31.5, 43) == 31.5);  // no scale: the points themselves
}
