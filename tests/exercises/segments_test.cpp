// The `segments` kind (exercise 2): over many seeds for every difficulty and branch, the drawn
// instance is the branch asked, meets its constraints, asks the core's answers (and only the
// fields its branch has) with exact forms that agree, tolerances that accept an honest student's
// rounding, solves, and formats in both languages; the same seed draws the same instance.
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
#include "geometry/segments.h"

namespace {

using namespace epure;
using geo::Point2;
using geo::SegmentRelation;

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
  Point2 A, B, C, D;
};

Made make(Difficulty level, const std::string& branch, const std::string& language, std::uint64_t seed) {
  ExerciseSpec spec;
  spec.kind = "segments";
  spec.difficulty = level;
  const ExerciseContext ctx{2, spec, Texts::builtin(language), NumberStyle::for_language(language), 2, branch};
  Rng rng(seed, 11);
  Made m{epure::find_kind("segments")->make(rng, ctx), {}, {}, {}, {}};
  const auto j = nlohmann::json::parse(m.inst.instance);
  const auto point = [&](const char* name) { return Point2{j[name][0].get<double>(), j[name][1].get<double>()}; };
  m.A = point("A");
  m.B = point("B");
  m.C = point("C");
  m.D = point("D");
  return m;
}

const Question& question(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return q;
  FAIL("no question " << field);
  throw std::logic_error("unreachable");
}

bool in_area(Point2 p, double slack) {
  return p.x >= -slack && p.x <= 10 + slack && p.y >= -slack && p.y <= 8 + slack;
}

}  // namespace

TEST_CASE("segments: every difficulty and branch draws a well-posed instance the core agrees with") {
  const auto& kind = (*epure::find_kind("segments"));
  REQUIRE(find_kind("segments") == &kind);
  const auto constraints = kind.default_constraints();
  for (Difficulty level : {Difficulty::easy, Difficulty::standard, Difficulty::hard}) {
    const bool hard = level == Difficulty::hard;
    const double t_margin = constraints.at("t_margin") / (hard ? 3 : 1);
    const double outside_margin = constraints.at("outside_margin") / (hard ? 2 : 1);
    const double max_t = constraints.at("max_t");
    const double min_sin = std::sin(constraints.at("min_angle_deg") / (hard ? 2 : 1) * std::numbers::pi / 180);
    const double parallel_gap = constraints.at("parallel_gap") / (hard ? 2 : 1);
    // every branch, collinear too (its default weight is 0, but a spec may ask for it)
    for (const auto& [branch, weight] : kind.default_branches()) {
      for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const std::string language = seed % 2 ? "fr" : "en";
        CAPTURE(to_string(level));
        CAPTURE(branch);
        CAPTURE(seed);
        const Made m = make(level, branch, language, seed);
        const auto& inst = m.inst;
        CAPTURE(inst.instance);
        CHECK(inst.kind == "segments");
        CHECK(inst.branch == branch);
        const auto s = geo::intersect_segments(m.A, m.B, m.C, m.D);

        // the branch, from the core
        CHECK(geo::to_string(s.relation) == branch);

        // the constraints
        const Point2 points[4] = {m.A, m.B, m.C, m.D};
        for (int i = 0; i < 4; ++i) {
          CHECK(in_area(points[i], 0));
          CHECK(std::abs(points[i].x * (hard ? 10 : 1) - std::nearbyint(points[i].x * (hard ? 10 : 1))) < 1e-9);
          CHECK(std::abs(points[i].y * (hard ? 10 : 1) - std::nearbyint(points[i].y * (hard ? 10 : 1))) < 1e-9);
          for (int j = 0; j < i; ++j) CHECK(geo::norm(points[i] - points[j]) >= constraints.at("min_separation"));
        }
        CHECK(geo::norm(s.AB) >= constraints.at("min_length"));
        CHECK(geo::norm(s.CD) >= constraints.at("min_length"));
        const bool crossing = branch == "intersects" || branch == "outside";
        if (crossing) {
          REQUIRE(s.t_ab);
          CHECK(std::abs(s.ab_cross_cd) >= min_sin * geo::norm(s.AB) * geo::norm(s.CD));
          for (double t : {*s.t_ab, *s.t_cd}) {
            CAPTURE(t);
            CHECK(t >= 1 - max_t);
            CHECK(t <= max_t);
            const bool inside = t >= t_margin && t <= 1 - t_margin;
            const bool clearly_out = t <= -outside_margin || t >= 1 + outside_margin;
            CHECK((inside || clearly_out));
            if (branch == "intersects") CHECK(inside);
          }
          const Point2 P = m.A + *s.t_ab * s.AB;
          CHECK(in_area(P, 1));
          if (branch == "outside")
            for (const Point2& p : points) CHECK(geo::norm(P - p) >= constraints.at("outside_clearance"));
        }
        if (branch == "parallel") CHECK(std::abs(s.ac_cross_ab) >= parallel_gap * geo::norm(s.AB));

        // the questions: exactly the branch's fields, with the core's answers
        std::vector<std::string> fields;
        for (const auto& q : inst.questions) fields.push_back(q.field);
        if (branch == "intersects") CHECK(fields == std::vector<std::string>{"intersects", "t_ab", "t_cd", "I.x", "I.y"});
        if (branch == "outside") CHECK(fields == std::vector<std::string>{"intersects", "t_ab", "t_cd", "reason"});
        if (!crossing) CHECK(fields == std::vector<std::string>{"intersects", "reason"});
        CHECK(std::get<bool>(question(inst, "intersects").expected) == s.intersects());
        if (!s.intersects()) CHECK(std::get<std::string>(question(inst, "reason").expected) == branch);
        for (const auto& q : inst.questions) CHECK(q.points > 0);

        const auto sol = nlohmann::json::parse(inst.solution);
        CHECK(sol["intersects"].get<bool>() == s.intersects());
        if (crossing) {
          std::vector<std::pair<std::string, double>> core = {{"t_ab", *s.t_ab}, {"t_cd", *s.t_cd}};
          if (s.I) {
            core.emplace_back("I.x", s.I->x);
            core.emplace_back("I.y", s.I->y);
            CHECK(sol["I"][0].get<double>() == doctest::Approx(s.I->x).epsilon(1e-12));
            CHECK(sol["I"][1].get<double>() == doctest::Approx(s.I->y).epsilon(1e-12));
          }
          CHECK(sol["t_ab"].get<double>() == doctest::Approx(*s.t_ab).epsilon(1e-12));
          CHECK(sol["t_cd"].get<double>() == doctest::Approx(*s.t_cd).epsilon(1e-12));
          for (const auto& [field, value] : core) {
            CAPTURE(field);
            const Question& q = question(inst, field);
            CHECK(std::get<double>(q.expected) == doctest::Approx(value).epsilon(1e-12));
            CHECK(q.tolerance.kind == ToleranceRule::Kind::isclose);
            CHECK(q.tolerance.abs > 0);
            CHECK(std::isfinite(q.tolerance.abs));
            // data on a grid: every answer is an exact rational
            REQUIRE(q.exact);
            CHECK(q.exact->find("sqrt") == std::string::npos);
            CHECK(std::abs(MachineForm(*q.exact).value() - value) <= 1e-9 * std::max(1.0, std::abs(value)));
          }
          if (level == Difficulty::easy)
            // t = p/n with n | 100: a terminating decimal a student writes exactly
            for (double t : {*s.t_ab, *s.t_cd}) CHECK(std::abs(t * 100 - std::nearbyint(t * 100)) < 1e-9);
          CHECK(question(inst, "t_ab").tolerance.abs < 0.05);

          // the hand method is the core's when nothing is rounded
          const auto by_hand = test::method_answers(inst.instance);
          CHECK(by_hand.at("t_ab")[0] == doctest::Approx(*s.t_ab).epsilon(1e-9));
          CHECK(by_hand.at("t_cd")[0] == doctest::Approx(*s.t_cd).epsilon(1e-9));
          if (s.I) {
            CHECK(by_hand.at("I")[0] == doctest::Approx(s.I->x).epsilon(1e-9));
            CHECK(by_hand.at("I")[1] == doctest::Approx(s.I->y).epsilon(1e-9));
          }

          // a student who carries t_ab and t_cd to 4 significant digits, computes I from them
          // and writes each answer to 2 decimals, as the sheet says, is accepted
          const double t_ab = carry4(s.ac_cross_cd / s.ab_cross_cd), t_cd = carry4(s.ac_cross_ab / s.ab_cross_cd);
          CHECK(accepts(question(inst, "t_ab"), round_to(t_ab, 2)));
          CHECK(accepts(question(inst, "t_cd"), round_to(t_cd, 2)));
          if (s.I) {
            CHECK(accepts(question(inst, "I.x"), round_to(m.A.x + t_ab * s.AB.x, 2)));
            CHECK(accepts(question(inst, "I.y"), round_to(m.A.y + t_ab * s.AB.y, 2)));
          }
        } else {
          CHECK(sol["reason"].get<std::string>() == branch);
          CHECK_FALSE(sol.contains("t_ab"));
        }

        // the instance solves to the solution recorded
        CHECK(inst.solution == kinds::solve_instance(inst.instance));
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

TEST_CASE("segments: both languages format every instance alike") {
  for (const auto& [branch, weight] : epure::find_kind("segments")->default_branches())
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      CAPTURE(branch);
      CAPTURE(seed);
      const Made en = make(Difficulty::hard, branch, "en", seed);
      const Made fr = make(Difficulty::hard, branch, "fr", seed);
      CHECK(en.inst.instance == fr.inst.instance);
      CHECK(en.inst.key.blocks.size() == fr.inst.key.blocks.size());
    }
}

TEST_CASE("segments: the hand method on worked cases") {
  // 1. the diagonals of the square (0,0)–(4,4) cross at its centre: t_ab = t_cd = 1/2
  const char* diagonals = R"({"kind":"segments","A":[0,0],"B":[4,4],"C":[0,4],"D":[4,0]})";
  auto r = test::method_answers(diagonals);
  CHECK(r["t_ab"][0] == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(r["t_cd"][0] == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(r["I"][0] == doctest::Approx(2).epsilon(1e-15));
  CHECK(r["I"][1] == doctest::Approx(2).epsilon(1e-15));
  // 2. crossing beyond B: A(0,0) B(2,0), C(4,−1) D(4,1): t_ab = 2, t_cd = 1/2, no I
  r = test::method_answers(R"({"kind":"segments","A":[0,0],"B":[2,0],"C":[4,-1],"D":[4,1]})");
  CHECK(r["t_ab"][0] == doctest::Approx(2).epsilon(1e-15));
  CHECK(r["t_cd"][0] == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(r.count("I") == 0);
  // 3. t_ab and t_cd swapped, and the cross products taken the other way round
  r = test::method_answers(R"({"kind":"segments","A":[0,0],"B":[2,0],"C":[4,-1],"D":[4,1]})", "t_swapped");
  CHECK(r["t_ab"][0] == doctest::Approx(0.5).epsilon(1e-15));
  CHECK(r["t_cd"][0] == doctest::Approx(2).epsilon(1e-15));
  r = test::method_answers(R"({"kind":"segments","A":[0,0],"B":[2,0],"C":[4,-1],"D":[4,1]})", "cross_sign");
  CHECK(r["t_ab"][0] == doctest::Approx(-2).epsilon(1e-15));
  // 4. parallel lines: no parameter
  r = test::method_answers(R"({"kind":"segments","A":[0,0],"B":[2,0],"C":[0,1],"D":[3,1]})");
  CHECK(r.count("t_ab") == 0);
}

TEST_CASE("segments: an unknown branch is refused") {
  ExerciseSpec spec;
  spec.kind = "segments";
  const ExerciseContext ctx{1, spec, Texts::builtin("en"), NumberStyle::for_language("en"), 2, "touching"};
  Rng rng(1);
  CHECK_THROWS_AS(epure::find_kind("segments")->make(rng, ctx), std::invalid_argument);
}
