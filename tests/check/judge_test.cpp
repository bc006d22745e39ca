// The judge against the models: the course's method as mended is right on every case epure
// draws, and each classic bug is wrong on some.
#include <doctest/doctest.h>

#include "check/bug_models.h"
#include "check/classify.h"
#include "check/cases.h"
#include "check/judge.h"

using namespace epure::check;

TEST_CASE("the mended course's method is right on every standard case, and every case has an answer") {
  for (const FunctionInfo& f : all_functions()) {
    CAPTURE(f.name);
    const auto cases = standard_cases(f.fn, 1);
    CHECK(cases.size() >= 140);
    int wrong = 0;
    for (const Case& c : cases) {
      REQUIRE(expected(c).has_value());
      const Judgement j = judge(c, model(c, 0));
      if (!j.right) {
        ++wrong;
        if (wrong <= 3) {
          CAPTURE(category_name(c.category));
          CAPTURE(c.in[0]); CAPTURE(c.in[1]); CAPTURE(c.in[2]); CAPTURE(c.in[3]); CAPTURE(c.in[4]);
          CAPTURE(c.in[5]); CAPTURE(c.in[6]); CAPTURE(c.in[7]); CAPTURE(c.in[8]); CAPTURE(c.in[9]);
          const Outcome m = model(c, 0);
          CAPTURE(m.hit); CAPTURE(m.out[0]); CAPTURE(m.out[1]); CAPTURE(m.out[2]); CAPTURE(m.out[3]);
          CAPTURE(j.expected.hit); CAPTURE(j.expected.out[0]); CAPTURE(j.expected.out[1]);
          CAPTURE(j.expected.out[2]); CAPTURE(j.expected.out[3]);
          FAIL_CHECK("the mended method is judged wrong");
        }
      }
    }
    CHECK(wrong == 0);
  }
}

TEST_CASE("every classic bug of a function is wrong on some of its cases") {
  for (const FunctionInfo& f : all_functions()) {
    const auto cases = standard_cases(f.fn, 1);
    for (Bug b : bugs_of(f.fn)) {
      CAPTURE(f.name);
      CAPTURE(bug_code(b));
      int wrong = 0;
      for (const Case& c : cases)
        if (!judge(c, model(c, bit(b))).right) ++wrong;
      CHECK(wrong > 0);
    }
  }
}

TEST_CASE("each classic bug, run as a model, is named by the classifier") {
  for (const FunctionInfo& f : all_functions()) {
    const auto cases = standard_cases(f.fn, 1);
    for (Bug b : bugs_of(f.fn)) {
      CAPTURE(f.name);
      CAPTURE(bug_code(b));
      std::vector<std::optional<Outcome>> got;
      std::vector<bool> right;
      for (const Case& c : cases) {
        got.push_back(model(c, bit(b)));
        right.push_back(judge(c, *got.back()).right);
      }
      const Classification named = classify(f.fn, cases, got, right);
      REQUIRE(named.bugs.size() == 1);
      CHECK(bug_code(named.bugs[0]) == bug_code(b));
    }
    // the right method: nothing to name
    std::vector<std::optional<Outcome>> got;
    std::vector<bool> right;
    for (const Case& c : cases) {
      got.push_back(model(c, 0));
      right.push_back(true);
    }
    CHECK(classify(f.fn, cases, got, right).bugs.empty());
  }
}

TEST_CASE("decisions: exact where the data are exact, room within their rounding") {
  // the tangent at A on the circle x² + y² = 25 (integers): a hit at t = 0, exactly
  Case tangent{Fn::circle, Category::on_boundary, {}};
  tangent.in = {5, 0, 0, 1, 0, 0, 5};
  CHECK(exact_safe(tangent));
  const auto e = expected(tangent);
  REQUIRE(e);
  CHECK(e->hit);
  CHECK(e->out[0] == 5);
  Outcome miss;
  CHECK_FALSE(judge(tangent, miss).right);  // t <= 0 is wrong here
  // segments collinear as decimals: only "no intersection" is right (the exact crossing of the
  // doubles' lines is rounding noise)
  Case collinear{Fn::segments, Category::near_parallel, {}};
  collinear.in = {0.1, 0.2, 0.4, 0.8, 0.2, 0.4, 0.7, 1.4};
  CHECK_FALSE(exact_safe(collinear));
  CHECK(judge(collinear, Outcome{}).right);
  Outcome noise{true, {0.3, 0.6, 0, 0, 0, 0}};
  CHECK_FALSE(judge(collinear, noise).right);
}
