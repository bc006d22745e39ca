// The `vectors` kind (the course's preamble): over many seeds for every difficulty and branch,
// the drawn instance is the branch asked, meets its constraints, asks the core's answers with
// exact forms that agree, tolerances that accept an honest student's rounding, solves, and
// formats in both languages; the same seed draws the same instance.
#include <doctest/doctest.h>

#include "support/method_answers.h"
#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>

#include "exercises/kind_support.h"
#include "geometry/vectors.h"

namespace {

using namespace epure;
using geo::Vec2;

// The value of a machine exact form ("1/4", "(5-2*sqrt(2))/3", "-sqrt(3)/2"), read back
// independently of exact.cpp.
class MachineForm {
 public:
  explicit MachineForm(std::string s) : s_(std::move(s)) {}
  double value() {
    const double v = sum();
    REQUIRE(i_ == s_.size());
    return v;
  }

 private:
  double sum() {
    double v = product();
    while (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) v += s_[i_++] == '+' ? product() : -product();
    return v;
  }
  double product() {
    double v = factor();
    while (i_ < s_.size() && (s_[i_] == '*' || s_[i_] == '/')) v = s_[i_++] == '*' ? v * factor() : v / factor();
    return v;
  }
  double factor() {
    REQUIRE(i_ < s_.size());
    if (s_[i_] == '-') return ++i_, -factor();
    if (s_.compare(i_, 5, "sqrt(") == 0) {
      i_ += 5;
      const double v = sum();
      REQUIRE(s_[i_++] == ')');
      return std::sqrt(v);
    }
    if (s_[i_] == '(') {
      ++i_;
      const double v = sum();
      REQUIRE(s_[i_++] == ')');
      return v;
    }
    const std::size_t start = i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    REQUIRE(i_ > start);
    return std::stod(s_.substr(start, i_ - start));
  }
  std::string s_;
  std::size_t i_ = 0;
};

double round_to(double x, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(x * scale) / scale;
}

// x carried to 4 significant digits as the sheet says, by printf's own rounding (independent of
// method.h's)
double carry4(double x) { return std::stod(fmt::format("{:.3e}", x)); }

bool accepts(const Question& q, double given) {
  const double expected = std::get<double>(q.expected);
  return std::abs(given - expected) <= std::max(q.tolerance.rel * std::abs(expected), q.tolerance.abs);
}

bool on_grid(double x, double step) {
  return std::abs(x / step - std::nearbyint(x / step)) < 1e-9;
}

void check_text(const std::string& text, const std::string& language) {
  CAPTURE(text);
  CHECK_FALSE(text.empty());
  CHECK(text.find("${") == std::string::npos);
  // the language's decimal mark: never "2.5" in French nor "2,5" in English
  static const std::regex point(R"(\d\.\d)"), comma(R"(\d,\d)");
  CHECK_FALSE(std::regex_search(text, language == "fr" ? point : comma));
}

void check_section_texts(const render::Section& section, const std::string& language) {
  for (const auto& block : section.blocks) {
    if (const auto* h = std::get_if<render::Heading>(&block)) check_text(h->text, language);
    if (const auto* p = std::get_if<render::Paragraph>(&block)) check_text(p->text, language);
    if (const auto* f = std::get_if<render::AnswerField>(&block)) check_text(f->prompt, language);
    if (const auto* l = std::get_if<render::AnswerLine>(&block)) {
      check_text(l->prompt, language);
      check_text(l->answer, language);
    }
    if (const auto* fig = std::get_if<render::Figure>(&block)) {
      check_text(fig->scene.title, language);
      check_text(fig->scene.description, language);
      for (const auto& panel : fig->scene.panels)
        for (const auto& item : panel.items) {
          if (const auto* label = std::get_if<render::Label>(&item)) check_text(label->text, language);
          if (const auto* mark = std::get_if<render::PointMark>(&item); mark && mark->label)
            check_text(mark->label->text, language);
          if (const auto* tick = std::get_if<render::Tick>(&item); tick && tick->text)
            check_text(*tick->text, language);
        }
    }
  }
}

struct Made {
  ExerciseInstance inst;
  Vec2 u, v;
};

Made make(Difficulty level, const std::string& branch, const std::string& language, std::uint64_t seed) {
  ExerciseSpec spec;
  spec.kind = "vectors";
  spec.difficulty = level;
  const ExerciseContext ctx{1, spec, Texts::builtin(language), NumberStyle::for_language(language), 2, branch};
  Rng rng(seed, 7);
  Made m{epure::find_kind("vectors")->make(rng, ctx), {}, {}};
  const auto j = nlohmann::json::parse(m.inst.instance);
  m.u = {j["u"][0].get<double>(), j["u"][1].get<double>()};
  m.v = {j["v"][0].get<double>(), j["v"][1].get<double>()};
  return m;
}

const Question& question(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return q;
  FAIL("no question " << field);
  throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("vectors: every difficulty and branch draws a well-posed instance the core agrees with") {
  const auto& kind = (*epure::find_kind("vectors"));
  REQUIRE(find_kind("vectors") == &kind);
  const auto constraints = kind.default_constraints();
  for (Difficulty level : {Difficulty::easy, Difficulty::standard, Difficulty::hard}) {
    const bool hard = level == Difficulty::hard;
    for (const auto& [branch, weight] : kind.default_branches()) {
      for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const std::string language = seed % 2 ? "fr" : "en";
        CAPTURE(to_string(level));
        CAPTURE(branch);
        CAPTURE(seed);
        const Made m = make(level, branch, language, seed);
        const auto& inst = m.inst;
        CAPTURE(inst.instance);
        CHECK(inst.kind == "vectors");
        CHECK(inst.branch == branch);
        const auto r = geo::compare_vectors(m.u, m.v);

        // the branch, from the core
        const double a = std::abs(r.angle_deg);
        const double right_margin = constraints.at("right_margin_deg") / (hard ? 2 : 1);
        if (branch == "acute") CHECK(a <= 90 - right_margin);
        if (branch == "obtuse") CHECK(a >= 90 + right_margin);
        if (branch == "right") CHECK(std::abs(r.cos) <= 1e-12);

        // the constraints
        const double min_angle = constraints.at("min_angle_deg") / (hard ? 2 : 1);
        CHECK(a >= min_angle);
        CHECK(a <= 180 - min_angle);
        CHECK(r.norm_u >= constraints.at("min_norm"));
        CHECK(r.norm_v >= constraints.at("min_norm"));
        CHECK(geo::norm(m.u - m.v) >= constraints.at("min_tip_gap"));
        for (double c : {m.u.x, m.u.y, m.v.x, m.v.y}) {
          CHECK(std::abs(c) <= constraints.at("max_component"));
          CHECK(on_grid(c, hard ? 0.1 : 1));
        }
        if (level == Difficulty::easy) {
          CHECK(on_grid(r.norm_u, 1));
          CHECK(on_grid(r.norm_v, 1));
        }
        if (level == Difficulty::standard) CHECK_FALSE((on_grid(r.norm_u, 1) && on_grid(r.norm_v, 1)));

        // the questions: the core's answers, with exact forms that agree
        const char* fields[] = {"dot", "cross", "norm_u", "norm_v", "cos", "sin", "angle_deg"};
        const double core[] = {r.dot, r.cross, r.norm_u, r.norm_v, r.cos, r.sin, r.angle_deg};
        REQUIRE(inst.questions.size() == 7);
        for (int i = 0; i < 7; ++i) {
          const Question& q = inst.questions[i];
          CAPTURE(q.field);
          CHECK(q.field == fields[i]);
          CHECK(std::get<double>(q.expected) == doctest::Approx(core[i]).epsilon(1e-12));
          CHECK(q.tolerance.kind == ToleranceRule::Kind::isclose);
          CHECK(q.tolerance.abs > 0);
          CHECK(std::isfinite(q.tolerance.abs));
          if (q.exact) {
            const double value = MachineForm(*q.exact).value();
            CHECK(std::abs(value - core[i]) <= 1e-9 * std::max(1.0, std::abs(core[i])));
          } else {
            // only the angle may lack an exact form, and data on a grid always have one
            CHECK(q.field == "angle_deg");
          }
        }
        if (level == Difficulty::easy)
          for (const char* f : {"norm_u", "norm_v", "cos", "sin"})
            CHECK(question(inst, f).exact->find("sqrt") == std::string::npos);
        if (branch == "right") CHECK(question(inst, "angle_deg").exact);
        // the tolerances are fair but not lax
        CHECK(question(inst, "cos").tolerance.abs < 0.05);
        CHECK(question(inst, "angle_deg").tolerance.abs < 3);

        // the hand method is the core's when nothing is rounded
        const auto by_hand = test::method_answers(inst.instance);
        for (int i = 0; i < 7; ++i)
          CHECK(std::abs(by_hand.at(fields[i])[0] - core[i]) <= 1e-9 * std::max(1.0, std::abs(core[i])));

        // a student who works as the sheet says (each value carried to 4 significant digits,
        // each answer written to 2 decimals) is accepted
        const double nu = carry4(r.norm_u), nv = carry4(r.norm_v);
        const double cos = carry4(r.dot / (nu * nv)), sin = carry4(r.cross / (nu * nv));
        const double angle = std::atan2(sin, cos) * 180 / std::numbers::pi;
        CHECK(accepts(question(inst, "norm_u"), round_to(nu, 2)));
        CHECK(accepts(question(inst, "norm_v"), round_to(nv, 2)));
        CHECK(accepts(question(inst, "cos"), round_to(cos, 2)));
        CHECK(accepts(question(inst, "sin"), round_to(sin, 2)));
        CHECK(accepts(question(inst, "angle_deg"), round_to(angle, 2)));
        // and one who carries only 2 decimals is not always: cos would be 4 % off at 0,12

        // the instance solves to the solution recorded, which says the same
        CHECK(inst.solution == kinds::solve_instance(inst.instance));
        const auto sol = nlohmann::json::parse(inst.solution);
        for (int i = 0; i < 7; ++i) CHECK(sol[fields[i]].get<double>() == doctest::Approx(core[i]).epsilon(1e-12));
        CHECK(inst.fingerprint == kinds::fingerprint(inst.instance));

        // every text is complete, in the language's typography
        check_section_texts(inst.sheet, language);
        check_section_texts(inst.key, language);

        // the same seed draws the same instance
        if (seed % 10 == 0) CHECK(make(level, branch, language, seed).inst.instance == inst.instance);
      }
    }
  }
}

TEST_CASE("vectors: both languages format every instance") {
  for (const auto& [branch, weight] : epure::find_kind("vectors")->default_branches())
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      CAPTURE(branch);
      CAPTURE(seed);
      // the same draw in either language: only the words differ
      const Made en = make(Difficulty::hard, branch, "en", seed);
      const Made fr = make(Difficulty::hard, branch, "fr", seed);
      CHECK(en.inst.instance == fr.inst.instance);
      CHECK(en.inst.key.blocks.size() == fr.inst.key.blocks.size());
    }
}

TEST_CASE("vectors: the hand method on a worked pair") {
  // u = (3, 4), v = (−4, 3): a quarter turn counter-clockwise
  const char* pair = R"({"kind":"vectors","u":[3,4],"v":[-4,3]})";
  auto r = test::method_answers(pair);
  CHECK(r["dot"][0] == doctest::Approx(0).epsilon(1e-15));
  CHECK(r["cross"][0] == doctest::Approx(25).epsilon(1e-15));
  CHECK(r["norm_u"][0] == doctest::Approx(5).epsilon(1e-15));
  CHECK(r["norm_v"][0] == doctest::Approx(5).epsilon(1e-15));
  CHECK(r["cos"][0] == doctest::Approx(0).epsilon(1e-15));
  CHECK(r["sin"][0] == doctest::Approx(1).epsilon(1e-15));
  CHECK(r["angle_deg"][0] == doctest::Approx(90).epsilon(1e-15));
  // the named mistakes take their own road, and only theirs
  r = test::method_answers(pair, "cross_sign");
  CHECK(r["cross"][0] == doctest::Approx(-25).epsilon(1e-15));
  CHECK(r["angle_deg"][0] == doctest::Approx(-90).epsilon(1e-15));
  r = test::method_answers(pair, "norm_not_rooted");
  CHECK(r["norm_u"][0] == doctest::Approx(25).epsilon(1e-15));
  CHECK(r["dot"][0] == doctest::Approx(0).epsilon(1e-15));
  r = test::method_answers(pair, "angle_radians");
  CHECK(r["angle_deg"][0] == doctest::Approx(std::numbers::pi / 2).epsilon(1e-15));
}

TEST_CASE("vectors: an unknown branch is refused") {
  ExerciseSpec spec;
  spec.kind = "vectors";
  const ExerciseContext ctx{1, spec, Texts::builtin("en"), NumberStyle::for_language("en"), 2, "sideways"};
  Rng rng(1);
  CHECK_THROWS_AS(epure::find_kind("vectors")->make(rng, ctx), std::invalid_argument);
}
