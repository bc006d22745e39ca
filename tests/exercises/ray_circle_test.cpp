// The ray_circle exercise (exercise 3): over many seeds per difficulty and branch, the instance
// is drawn in the asked branch, meets its constraints, asks what the solve contract answers, with
// exact forms that agree with the core, positive tolerances and complete texts in both languages.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <variant>

#include "exercises/exercise.h"
#include "exercises/kind_support.h"
#include "geometry/ray_circle.h"

namespace epure::kinds::testing {
std::vector<double> ray_circle_student_answers(geo::Point2 A, geo::Vec2 u, geo::Point2 C, double r);
}

namespace {

using namespace epure;
using nlohmann::json;

constexpr const char* kBranches[] = {"hit", "behind", "miss", "inside"};
constexpr Difficulty kLevels[] = {Difficulty::easy, Difficulty::standard, Difficulty::hard};

ExerciseInstance make(Difficulty level, const std::string& branch, std::uint64_t seed,
                      const char* language = "en") {
  ExerciseSpec spec;
  spec.kind = "ray_circle";
  spec.difficulty = level;
  const ExerciseContext ctx{3, spec, Texts::builtin(language), NumberStyle::for_language(language), 2, branch};
  Rng rng(seed, 7);
  return epure::find_kind("ray_circle")->make(rng, ctx);
}

// The value of an exact form as key.json writes it: integers, + − * /, sqrt( ), parentheses.
class ExactReader {
 public:
  explicit ExactReader(const std::string& s) : s_(s) {}
  double read() {
    const double v = sum();
    REQUIRE(i_ == s_.size());
    return v;
  }

 private:
  double sum() {
    double v = product();
    while (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) {
      const char op = s_[i_++];
      const double w = product();
      v = op == '+' ? v + w : v - w;
    }
    return v;
  }
  double product() {
    double v = factor();
    while (i_ < s_.size() && (s_[i_] == '*' || s_[i_] == '/')) {
      const char op = s_[i_++];
      const double w = factor();
      v = op == '*' ? v * w : v / w;
    }
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
  const std::string& s_;
  std::size_t i_ = 0;
};

geo::Point2 point_of(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }
geo::Vec2 vec_of(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }

std::string branch_of(const geo::RayCircle& rc) {
  if (rc.inside) return "inside";
  if (rc.hit) return "hit";
  return geo::to_string(*rc.reason);
}

bool on_grid(double x, double step) { return std::abs(x / step - std::nearbyint(x / step)) < 1e-9; }

// Every text of a section, so that none keeps a placeholder.
std::vector<std::string> texts_of(const render::Section& s) {
  std::vector<std::string> out;
  for (const auto& block : s.blocks) {
    if (auto* h = std::get_if<render::Heading>(&block)) out.push_back(h->text);
    if (auto* p = std::get_if<render::Paragraph>(&block)) out.push_back(p->text);
    if (auto* f = std::get_if<render::AnswerField>(&block)) out.push_back(f->prompt);
    if (auto* l = std::get_if<render::AnswerLine>(&block)) out.insert(out.end(), {l->prompt, l->answer});
    if (auto* f = std::get_if<render::Figure>(&block)) {
      out.insert(out.end(), {f->scene.title, f->scene.description});
      for (const auto& panel : f->scene.panels)
        for (const auto& item : panel.items) {
          if (auto* l = std::get_if<render::Label>(&item)) out.push_back(l->text);
          if (auto* m = std::get_if<render::PointMark>(&item); m && m->label) out.push_back(m->label->text);
          if (auto* d = std::get_if<render::Dimension>(&item)) out.push_back(d->text);
          if (auto* t = std::get_if<render::Tick>(&item); t && t->text) out.push_back(*t->text);
        }
    }
  }
  return out;
}

const Question& question(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return q;
  FAIL("no question ", field);
  throw std::logic_error("unreachable");
}

bool asks(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return true;
  return false;
}

}  // namespace

TEST_CASE("ray_circle: every difficulty and branch, over many seeds") {
  const auto& kind = (*epure::find_kind("ray_circle"));
  CHECK(kind.name() == "ray_circle");
  REQUIRE(kind.default_branches().size() == 4);
  for (Difficulty level : kLevels)
    for (const char* branch : kBranches)
      for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        CAPTURE(to_string(level));
        const std::string branch_name = branch;
        CAPTURE(branch_name);
        CAPTURE(seed);
        const ExerciseInstance inst = make(level, branch, seed);
        CAPTURE(inst.instance);
        CHECK(inst.kind == "ray_circle");
        CHECK(inst.branch == branch);
        CHECK(inst.fingerprint == kinds::fingerprint(inst.instance));
        CHECK(inst.solution == kinds::solve_instance(inst.instance));

        const json in = json::parse(inst.instance);
        const json out = json::parse(inst.solution);
        const geo::Point2 A = point_of(in["A"]), C = point_of(in["C"]);
        const geo::Vec2 u = vec_of(in["u"]);
        const double r = in["r"].get<double>();
        const auto rc = geo::intersect(geo::Ray2::unit(A, u), geo::Circle{C, r});

        // the asked branch, from the core
        REQUIRE(branch_of(rc) == branch);

        // data on the difficulty's grid, in the drawing area
        const double step = level == Difficulty::hard ? 0.1 : 1;
        for (double x : {A.x, A.y, C.x, C.y, u.x, u.y, r}) CHECK(on_grid(x, step));
        CHECK(A.x >= 0);
        CHECK(A.x <= 10);
        CHECK(A.y >= 0);
        CHECK(A.y <= 8);
        CHECK(C.x - r >= -1 - 1e-9);
        CHECK(C.x + r <= 11 + 1e-9);
        CHECK(C.y - r >= -1 - 1e-9);
        CHECK(C.y + r <= 9 + 1e-9);
        CHECK(rc.P.x >= -1);
        CHECK(rc.P.x <= 11);
        CHECK(rc.P.y >= -1);
        CHECK(rc.P.y <= 9);
        CHECK(r >= 2 - 1e-9);
        CHECK(r <= 4 + 1e-9);

        // the default constraints (hard: near the degenerate cases, on their clear side)
        const bool hard = level == Difficulty::hard;
        const double ac = geo::norm(rc.AC) / r, dr = std::sqrt(rc.d2) / r;
        CHECK(dr >= 0.25);
        if (rc.inside) {
          CHECK(ac <= (hard ? 0.95 : 0.85) + 1e-12);
          if (hard) CHECK(ac >= 0.85 - 1e-12);
          CHECK(rc.hit->t >= (hard ? 1.0 / 3 : 1.0));
        } else {
          CHECK(ac >= (hard ? 1.05 : 1.15) - 1e-12);
          CHECK(std::abs(dr - 1) >= (hard ? 0.0375 : 0.15) - 1e-12);
          if (std::string(branch) == "behind") CHECK(rc.t_proj <= -(hard ? 0.5 / 3 : 0.5));
          else CHECK(rc.t_proj >= (hard ? 0.5 / 3 : 0.5));
          if (rc.hit) CHECK(rc.hit->t >= (hard ? 1.0 / 3 : 1.0));
          if (hard) {
            const bool near_tangent = std::abs(dr - 1) <= 0.15 + 1e-12, near_circle = ac <= 1.15 + 1e-12;
            CHECK((near_tangent || (near_circle && std::string(branch) != "miss")));
          }
        }

        // the questions: the contract's fields, the core's values
        CHECK(std::get<double>(question(inst, "t_proj").expected) == doctest::Approx(rc.t_proj).epsilon(1e-12));
        CHECK(std::get<double>(question(inst, "t_proj").expected) == doctest::Approx(out["t_proj"].get<double>()).epsilon(1e-12));
        // behind, the course stops at t_proj: d² is not asked (the contract still gives it)
        const bool behind = std::string(branch) == "behind";
        CHECK(asks(inst, "d2") == !behind);
        if (!behind) {
          CHECK(std::get<double>(question(inst, "d2").expected) == doctest::Approx(rc.d2).epsilon(1e-12));
          CHECK(std::get<double>(question(inst, "d2").expected) == doctest::Approx(out["d2"].get<double>()).epsilon(1e-12));
        }
        CHECK(std::get<bool>(question(inst, "inside").expected) == rc.inside);
        CHECK(std::get<bool>(question(inst, "hit").expected) == rc.hit.has_value());
        CHECK(out["inside"].get<bool>() == rc.inside);
        CHECK(out["hit"].get<bool>() == rc.hit.has_value());
        if (rc.hit) {
          CHECK_FALSE(asks(inst, "reason"));
          const std::pair<const char*, double> expected[] = {
              {"t", rc.hit->t},     {"I.x", rc.hit->I.x}, {"I.y", rc.hit->I.y},
              {"N.x", rc.hit->N.x}, {"N.y", rc.hit->N.y}};
          for (const auto& [field, value] : expected) {
            CAPTURE(field);
            CHECK(std::get<double>(question(inst, field).expected) == doctest::Approx(value).epsilon(1e-12));
          }
          CHECK(std::get<double>(question(inst, "t").expected) == doctest::Approx(out["t"].get<double>()).epsilon(1e-12));
          CHECK(std::get<double>(question(inst, "I.x").expected) == doctest::Approx(out["I"][0].get<double>()).epsilon(1e-12));
          CHECK(std::get<double>(question(inst, "N.y").expected) == doctest::Approx(out["N"][1].get<double>()).epsilon(1e-12));
          CHECK(question(inst, "I.x").point_group == "I");
        } else {
          CHECK_FALSE(asks(inst, "t"));
          CHECK_FALSE(asks(inst, "I.x"));
          CHECK(std::get<std::string>(question(inst, "reason").expected) == geo::to_string(*rc.reason));
          CHECK(out["reason"].get<std::string>() == geo::to_string(*rc.reason));
        }

        // exact forms agree with the core; tolerances positive and finite
        for (const auto& q : inst.questions) {
          CAPTURE(q.field);
          CHECK(q.points > 0);
          if (!std::holds_alternative<double>(q.expected)) {
            CHECK(q.tolerance.kind == ToleranceRule::Kind::exact);
            continue;
          }
          const double expected = std::get<double>(q.expected);
          CHECK(q.tolerance.kind == ToleranceRule::Kind::isclose);
          CHECK(q.tolerance.abs > 0);
          CHECK(std::isfinite(q.tolerance.abs));
          // carrying 4 significant digits keeps every answer within a few per cent (the
          // property test of tolerances pins the 5 %)
          CHECK(q.tolerance.abs < 0.1 * std::max(1.0, std::abs(expected)));
          // the rounding of the answer itself, at least
          CHECK(q.tolerance.abs >= 0.005);
          // with ‖u‖ among 1, 2, 5, 10 every intermediate has at most 2 decimals: only the
          // answer's own rounding remains (‖u‖ = 13 gives û = (5/13, 12/13), which does not)
          const bool terminating = std::abs(geo::norm(u) - 13) > 1e-9;
          if (level == Difficulty::easy && rc.hit && terminating)
            CHECK(q.tolerance.abs == doctest::Approx(0.005).epsilon(1e-8));
          if (q.exact) {
            CAPTURE(*q.exact);
            CHECK(std::abs(ExactReader(*q.exact).read() - expected) <= 1e-9 * std::max(1.0, std::abs(expected)));
          }
        }
        // d² = (u∧AC)²/u·u is rational for data on a grid
        if (!behind) CHECK(question(inst, "d2").exact.has_value());
        if (level == Difficulty::easy) {
          CHECK(question(inst, "t_proj").exact.has_value());
          CHECK(question(inst, "t_proj").exact->find("sqrt") == std::string::npos);
          if (rc.hit) {
            // Pythagoras gives a rational PI: t and I are rational
            REQUIRE(question(inst, "t").exact.has_value());
            CHECK(question(inst, "t").exact->find("sqrt") == std::string::npos);
            CHECK(question(inst, "I.x").exact->find("sqrt") == std::string::npos);
          }
        }
        if (level == Difficulty::standard && rc.hit) {
          // I = P ± √(h²/u·u)·u holds one radicand: always exact at this size
          CHECK(question(inst, "I.x").exact.has_value());
          CHECK(question(inst, "N.y").exact.has_value());
        }

        // the method, on the key's own values, is the core's answer
        const auto* kind = find_kind("ray_circle");
        const auto mine = kind->evaluate(kind->read_instance(nlohmann::json::parse(inst.instance)), nullptr, {}, 2);
        auto answer = [&](std::string_view f) {
          for (const auto& a : mine)
            if (a.id == f) return a;
          FAIL("no answer ", f);
          return mine.front();
        };
        CHECK(answer("t_proj").x.v == doctest::Approx(rc.t_proj).epsilon(1e-9));
        if (!behind) CHECK(answer("d2").x.v == doctest::Approx(rc.d2).epsilon(1e-9));
        if (rc.hit) {
          CHECK(answer("t").x.v == doctest::Approx(rc.hit->t).epsilon(1e-9));
          CHECK(answer("I").x.v == doctest::Approx(rc.hit->I.x).epsilon(1e-9));
          CHECK(answer("I").y.v == doctest::Approx(rc.hit->I.y).epsilon(1e-9));
          CHECK(answer("N").x.v == doctest::Approx(rc.hit->N.x).epsilon(1e-9));
          CHECK(answer("N").y.v == doctest::Approx(rc.hit->N.y).epsilon(1e-9));
        }

        // the sections: answer fields match the questions; no placeholder left
        for (const auto* section : {&inst.sheet, &inst.key})
          for (const auto& text : texts_of(*section)) CHECK(text.find("${") == std::string::npos);
      }
}

TEST_CASE("ray_circle: French texts are complete, with a decimal comma") {
  for (Difficulty level : kLevels)
    for (const char* branch : kBranches)
      for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        CAPTURE(to_string(level));
        const std::string branch_name = branch;
        CAPTURE(branch_name);
        CAPTURE(seed);
        const ExerciseInstance fr = make(level, branch, seed, "fr");
        const ExerciseInstance en = make(level, branch, seed, "en");
        // the language changes the words, never the drawn instance
        CHECK(fr.instance == en.instance);
        for (const auto* section : {&fr.sheet, &fr.key})
          for (const auto& text : texts_of(*section)) {
            CHECK(text.find("${") == std::string::npos);
            CHECK(text.find(" :") == std::string::npos);
            CHECK(text.find(" ?") == std::string::npos);
          }
        if (level == Difficulty::hard) {
          // one-decimal data print with a comma in the statement
          const auto& statement = std::get<render::Paragraph>(fr.sheet.blocks.at(1)).text;
          CHECK_FALSE(std::regex_search(statement, std::regex("[0-9][.][0-9]")));
        }
      }
}

TEST_CASE("ray_circle: the same seed draws the same instance and the same texts") {
  for (const char* branch : kBranches)
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::string branch_name = branch;
      CAPTURE(branch_name);
      CAPTURE(seed);
      const auto a = make(Difficulty::standard, branch, seed), b = make(Difficulty::standard, branch, seed);
      CHECK(a.instance == b.instance);
      CHECK(texts_of(a.key) == texts_of(b.key));
      CHECK(texts_of(a.sheet) == texts_of(b.sheet));
      CHECK(a.fingerprint == b.fingerprint);
    }
  // different seeds draw different instances
  CHECK(make(Difficulty::standard, "hit", 1).instance != make(Difficulty::standard, "hit", 2).instance);
}

TEST_CASE("ray_circle: the key diagram shows the construction of each branch") {
  for (const char* branch : kBranches) {
    const std::string branch_name = branch;
    CAPTURE(branch_name);
    const auto inst = make(Difficulty::standard, branch, 11);
    const render::Figure* figure = nullptr;
    for (const auto& block : inst.key.blocks)
      if (auto* f = std::get_if<render::Figure>(&block)) figure = f;
    REQUIRE(figure != nullptr);
    REQUIRE(figure->scene.panels.size() == 1);
    int dimensions = 0, right_angles = 0, normals = 0, filled = 0, circles = 0;
    for (const auto& item : figure->scene.panels[0].items) {
      if (std::holds_alternative<render::Dimension>(item)) ++dimensions;
      if (std::holds_alternative<render::RightAngle>(item)) ++right_angles;
      if (auto* a = std::get_if<render::Arrow>(&item); a && a->role == render::Role::normal) ++normals;
      if (auto* p = std::get_if<render::Polygon>(&item); p && p->filled) ++filled;
      if (std::holds_alternative<render::Circle>(item)) ++circles;
    }
    const std::string b = branch;
    const bool hit = b == "hit" || b == "inside";
    CHECK(circles == 1);
    CHECK(right_angles == 1);
    CHECK(dimensions == (hit ? 3 : b == "miss" ? 2 : 0));  // d, √(r² − d²), r; or d > r
    CHECK(normals == (hit ? 1 : 0));
    CHECK(filled == (hit ? 1 : 0));
  }
}

TEST_CASE("ray_circle: a spec can tighten the constraints, and an impossible one is refused") {
  ExerciseSpec spec;
  spec.kind = "ray_circle";
  spec.constraints["min_radius"] = 3;
  spec.constraints["max_radius"] = 3;
  const ExerciseContext ctx{3, spec, Texts::builtin("en"), NumberStyle::for_language("en"), 2, "hit"};
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    const auto inst = epure::find_kind("ray_circle")->make(rng, ctx);
    CHECK(json::parse(inst.instance)["r"].get<double>() == doctest::Approx(3).epsilon(1e-12));
  }
  spec.constraints["max_radius"] = 7;
  Rng rng(1);
  CHECK_THROWS_AS(epure::find_kind("ray_circle")->make(rng, ctx), std::runtime_error);
}
