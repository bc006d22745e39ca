#pragma once
// What the ray_ellipse and ray_rectangle tests check alike: over many seeds per difficulty and
// branch, an instance is drawn, its branch and data are those asked, every question's expected
// value is the core's, exact forms agree with it, tolerances are sound, the student's method
// agrees with the core, the instance solves, both languages fill every text, and a seed always
// draws the same instance. Each test file adds its figure's clearance checks.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <regex>
#include <string>
#include <variant>

#include "exercises/exercise.h"
#include "exercises/kind_support.h"
#include "exercises/kinds/transformed_common.h"
#include "support/method_answers.h"

namespace epure::test {

using kinds::transformed::Data;
using kinds::transformed::Shape;

// The data of a ray_ellipse / ray_rectangle solve input.
inline Data data_of(const std::string& instance) {
  const auto j = nlohmann::json::parse(instance);
  const auto& sizes = j.contains("radii") ? j["radii"] : j["half"];
  Data d;
  d.A = {j["A"][0].get<double>(), j["A"][1].get<double>()};
  d.u = {j["u"][0].get<double>(), j["u"][1].get<double>()};
  d.C = {j["C"][0].get<double>(), j["C"][1].get<double>()};
  d.sx = sizes[0].get<double>();
  d.sy = sizes[1].get<double>();
  d.angle_deg = j["angle"].get<double>();
  return d;
}

// A solve input of `kind` with the data (the sizes as "radii" or "half").
inline std::string instance_of(std::string_view kind, const Data& d) {
  const nlohmann::json j = {{"kind", kind},
                            {"A", {d.A.x, d.A.y}},
                            {"u", {d.u.x, d.u.y}},
                            {"C", {d.C.x, d.C.y}},
                            {kind == "ray_ellipse" ? "radii" : "half", {d.sx, d.sy}},
                            {"angle", d.angle_deg}};
  return j.dump();
}

// The kind's method on an instance, unrounded, in the order {Ac.x, Ac.y, uc.x, uc.y} and, with
// a hit, {t, I.x, I.y, N.x, N.y}.
inline std::vector<double> hand_answers(const std::string& instance, std::string_view mistake = {}) {
  const auto answers = method_answers(instance, mistake);
  std::vector<double> out;
  for (const char* f : {"Ac", "uc", "t", "I", "N"})
    if (auto it = answers.find(f); it != answers.end()) out.insert(out.end(), it->second.begin(), it->second.end());
  return out;
}

// The value of an exact form as Surd::machine() writes it: "3", "-1/4", "-sqrt(3)/2",
// "(5-2*sqrt(2))/3".
inline double machine_value(std::string s) {
  double den = 1;
  const auto slash = s.rfind('/');
  if (slash != std::string::npos && s.find(')', slash) == std::string::npos) {
    den = std::stod(s.substr(slash + 1));
    s = s.substr(0, slash);
  }
  if (s.size() > 1 && s.front() == '(' && s.back() == ')') s = s.substr(1, s.size() - 2);
  double sum = 0;
  std::size_t start = 0;
  for (std::size_t i = 1; i <= s.size(); ++i) {
    if (i < s.size() && s[i] != '+' && s[i] != '-') continue;
    const std::string term = s.substr(start, i - start);
    const auto root = term.find("sqrt(");
    if (root == std::string::npos) {
      sum += std::stod(term);
    } else {
      const double c = std::stod(term.substr(root + 5));
      std::string coefficient = term.substr(0, root);
      if (!coefficient.empty() && coefficient.back() == '*') coefficient.pop_back();
      const double k = coefficient.empty() || coefficient == "+" ? 1 : coefficient == "-" ? -1 : std::stod(coefficient);
      sum += k * std::sqrt(c);
    }
    start = i;
  }
  return sum / den;
}

inline bool on_grid(double x, double step) {
  const double k = x / step;
  return std::abs(k - std::nearbyint(k)) < 1e-9;
}

// A spec of one exercise of `kind` at `level`, with every other setting at its default.
inline ExerciseSpec spec_for(std::string_view kind, Difficulty level) {
  ExerciseSpec spec;
  spec.kind = std::string(kind);
  spec.difficulty = level;
  return spec;
}

inline ExerciseContext context_for(const ExerciseSpec& spec, const std::string& language,
                                   const std::string& branch) {
  return ExerciseContext{1, spec, Texts::builtin(language), NumberStyle::for_language(language), 2, branch};
}

inline double expected_number(const Question& q) { return std::get<double>(q.expected); }
inline bool expected_bool(const Question& q) { return std::get<bool>(q.expected); }

// Every text of a section, for the placeholder and typography checks.
inline std::vector<std::string> texts_of(const render::Section& s) {
  std::vector<std::string> out;
  for (const auto& block : s.blocks) {
    if (const auto* h = std::get_if<render::Heading>(&block)) out.push_back(h->text);
    if (const auto* p = std::get_if<render::Paragraph>(&block)) out.push_back(p->text);
    if (const auto* f = std::get_if<render::AnswerField>(&block)) out.push_back(f->prompt);
    if (const auto* l = std::get_if<render::AnswerLine>(&block)) {
      out.push_back(l->prompt);
      out.push_back(l->answer);
    }
    if (const auto* fig = std::get_if<render::Figure>(&block)) {
      out.push_back(fig->scene.title);
      out.push_back(fig->scene.description);
      for (const auto& link : fig->scene.links) out.push_back(link);
      for (const auto& panel : fig->scene.panels) out.push_back(panel.caption);
    }
  }
  return out;
}

inline std::vector<render::Scene> scenes_of(const render::Section& s) {
  std::vector<render::Scene> out;
  for (const auto& block : s.blocks)
    if (const auto* fig = std::get_if<render::Figure>(&block)) out.push_back(fig->scene);
  return out;
}

struct KindCheck {
  const ExerciseKind& kind;
  Shape shape;
  // The figure's clearances for the branch, with the (difficulty-adjusted) limits.
  std::function<void(const Data&, const std::string& branch, const kinds::transformed::Limits&)> clear;
};

template <class Result>
void check_against_core(const ExerciseInstance& inst, const Result& r, double max_tolerance) {
  std::map<std::string, double> core{{"Ac.x", r.canonical_ray.origin.x},
                                     {"Ac.y", r.canonical_ray.origin.y},
                                     {"uc.x", r.canonical_ray.direction.x},
                                     {"uc.y", r.canonical_ray.direction.y}};
  if (r.hit) {
    core["t"] = r.hit->t;
    core["I.x"] = r.hit->I.x;
    core["I.y"] = r.hit->I.y;
    core["N.x"] = r.hit->N.x;
    core["N.y"] = r.hit->N.y;
  }
  std::vector<std::string> asked;
  for (const auto& q : inst.questions) {
    CAPTURE(q.field);
    asked.push_back(q.field);
    if (q.field == "inside") {
      CHECK(expected_bool(q) == r.inside);
      continue;
    }
    if (q.field == "hit") {
      CHECK(expected_bool(q) == r.hit.has_value());
      continue;
    }
    REQUIRE(core.count(q.field) == 1);
    const double value = expected_number(q);
    CHECK(value == doctest::Approx(core[q.field]).epsilon(1e-12));
    if (q.exact) {
      CAPTURE(*q.exact);
      CHECK(machine_value(*q.exact) == doctest::Approx(value).epsilon(1e-9).scale(1));
      CHECK(q.exact_pretty.has_value());
    }
    CHECK(q.tolerance.kind == ToleranceRule::Kind::isclose);
    CHECK(std::isfinite(q.tolerance.abs));
    CHECK(q.tolerance.abs > 0);
    CHECK(q.tolerance.abs <= max_tolerance);  // a well-conditioned instance
  }
  std::vector<std::string> want{"Ac.x", "Ac.y", "uc.x", "uc.y", "inside", "hit"};
  if (r.hit)
    for (const char* f : {"t", "I.x", "I.y", "N.x", "N.y"}) want.push_back(f);
  CHECK(asked == want);
}

inline const Question* find_question(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return &q;
  return nullptr;
}

template <class Figure>
void check_kind(const KindCheck& check, int seeds, Figure figure_of) {
  for (Difficulty level : {Difficulty::easy, Difficulty::standard, Difficulty::hard}) {
    const ExerciseSpec spec = spec_for(check.kind.name(), level);
    for (const auto& [branch, weight] : check.kind.default_branches()) {
      for (int seed = 0; seed < seeds; ++seed) {
        const std::string level_name(to_string(level));
        CAPTURE(level_name);
        CAPTURE(branch);
        CAPTURE(seed);
        const ExerciseContext ctx = context_for(spec, "en", branch);
        Rng rng(static_cast<std::uint64_t>(seed), 7);
        const ExerciseInstance inst = check.kind.make(rng, ctx);
        CAPTURE(inst.instance);
        CHECK(inst.branch == branch);
        CHECK(inst.kind == check.kind.name());
        CHECK(inst.solution == kinds::solve_instance(inst.instance));
        CHECK(inst.fingerprint == kinds::fingerprint(inst.instance));

        const Data d = data_of(inst.instance);
        const auto r = geo::intersect(kinds::transformed::world_ray(d), figure_of(d));
        // the branch, from the core
        CHECK(r.inside == (branch == "inside"));
        CHECK(r.hit.has_value() == (branch != "miss"));

        // the data of the level
        const double step = level == Difficulty::hard ? 0.1 : 1;
        for (double x : {d.A.x, d.A.y, d.u.x, d.u.y, d.C.x, d.C.y, d.sx, d.sy}) CHECK(on_grid(x, step));
        CHECK(on_grid(d.angle_deg, 1));
        if (level == Difficulty::easy) {
          CHECK((on_grid(d.angle_deg, 90) && d.angle_deg >= 0 && d.angle_deg <= 90));
          CHECK(std::max(d.sx, d.sy) <= 4);
          // û is rational: ‖u‖ is an integer
          CHECK(on_grid(geo::norm(d.u), 1));
        }
        if (level == Difficulty::standard) CHECK((on_grid(d.angle_deg, 30) || on_grid(d.angle_deg, 45)));

        // the constraints shared by both figures
        const auto lim = kinds::transformed::limits(ctx, check.kind);
        const double aspect = std::max(d.sx, d.sy) / std::min(d.sx, d.sy);
        CHECK(aspect <= lim.max_aspect + 1e-12);
        CHECK(aspect >= lim.min_aspect - 1e-12);
        for (double x : {-1.0, 1.0})
          for (double y : {-1.0, 1.0}) {
            // the figure lies within the image of the canonical square: keep that in the area
            // for the rectangle; for the ellipse its bounding box, checked below, is tighter
            if (check.shape == Shape::rectangle) {
              const geo::Point2 corner = r.to_world.apply(geo::Point2{x, y});
              CHECK(corner.x >= 0.5 - 1e-9);
              CHECK(corner.x <= lim.width - 0.5 + 1e-9);
              CHECK(corner.y >= 0.5 - 1e-9);
              CHECK(corner.y <= lim.height - 0.5 + 1e-9);
            }
          }
        if (check.shape == Shape::ellipse) {
          const double radians = d.angle_deg * std::numbers::pi / 180;
          const double c = std::cos(radians), s = std::sin(radians);
          const double ex = std::hypot(d.sx * c, d.sy * s), ey = std::hypot(d.sx * s, d.sy * c);
          CHECK(d.C.x - ex >= 0.5 - 1e-9);
          CHECK(d.C.x + ex <= lim.width - 0.5 + 1e-9);
          CHECK(d.C.y - ey >= 0.5 - 1e-9);
          CHECK(d.C.y + ey <= lim.height - 0.5 + 1e-9);
        }
        CHECK(d.A.x >= 0);
        CHECK(d.A.x <= lim.width);
        CHECK(d.A.y >= 0);
        CHECK(d.A.y <= lim.height);
        const geo::Point2 Ac = r.canonical_ray.origin;
        CHECK(std::max(std::abs(Ac.x), std::abs(Ac.y)) <= lim.max_canonical);
        if (r.hit) CHECK(r.hit->t >= lim.min_gap);
        check.clear(d, branch, lim);

        // questions: the core's values, exact forms, tolerances
        check_against_core(inst, r, lim.max_tolerance);
        if (level == Difficulty::easy) {
          // rational data, a quarter-turn angle, û rational: A_c and u_c rational; t and I too
          for (const char* f : {"Ac.x", "Ac.y", "uc.x", "uc.y", "t", "I.x", "I.y"})
            if (const Question* q = find_question(inst, f)) {
              CAPTURE(f);
              REQUIRE(q->exact.has_value());
              CHECK(q->exact->find("sqrt") == std::string::npos);
            }
        }
        if (level == Difficulty::standard)
          for (const char* f : {"Ac.x", "Ac.y"}) CHECK(find_question(inst, f)->exact.has_value());

        // the kind's method, unrounded, is the core's
        const auto hand = hand_answers(inst.instance);
        REQUIRE(hand.size() == (r.hit ? 9u : 4u));
        CHECK(hand[0] == doctest::Approx(Ac.x).epsilon(1e-9).scale(1));
        CHECK(hand[1] == doctest::Approx(Ac.y).epsilon(1e-9).scale(1));
        CHECK(hand[2] == doctest::Approx(r.canonical_ray.direction.x).epsilon(1e-9).scale(1));
        CHECK(hand[3] == doctest::Approx(r.canonical_ray.direction.y).epsilon(1e-9).scale(1));
        if (r.hit) {
          CHECK(hand[4] == doctest::Approx(r.hit->t).epsilon(1e-9).scale(1));
          CHECK(hand[5] == doctest::Approx(r.hit->I.x).epsilon(1e-9).scale(1));
          CHECK(hand[6] == doctest::Approx(r.hit->I.y).epsilon(1e-9).scale(1));
          CHECK(hand[7] == doctest::Approx(r.hit->N.x).epsilon(1e-9).scale(1));
          CHECK(hand[8] == doctest::Approx(r.hit->N.y).epsilon(1e-9).scale(1));
        }

        // the diagrams: the data in the world frame; the key's two frames and T⁻¹ between them
        // (its −1 with the minus sign, U+2212)
        const auto sheet_scenes = scenes_of(inst.sheet);
        REQUIRE(sheet_scenes.size() == 1);
        CHECK(sheet_scenes[0].panels.size() == 1);
        const auto key_scenes = scenes_of(inst.key);
        REQUIRE(key_scenes.size() == 1);
        CHECK(key_scenes[0].panels.size() == 2);
        REQUIRE(key_scenes[0].links.size() == 1);
        CHECK(key_scenes[0].links[0].find("T^{−1}") == 0);

        // determinism, and the other language: same data, every text filled, French numbers
        Rng again(static_cast<std::uint64_t>(seed), 7);
        const ExerciseInstance same = check.kind.make(again, ctx);
        CHECK(same.instance == inst.instance);
        CHECK(texts_of(same.key) == texts_of(inst.key));
        for (const std::string& text : texts_of(inst.key)) CHECK(text.find("${") == std::string::npos);
        if (seed % 5 == 0) {
          Rng french(static_cast<std::uint64_t>(seed), 7);
          const ExerciseInstance fr = check.kind.make(french, context_for(spec, "fr", branch));
          CHECK(fr.instance == inst.instance);
          static const std::regex decimal_point(R"(\d\.\d)");
          for (const auto* section : {&fr.sheet, &fr.key})
            for (const std::string& text : texts_of(*section)) {
              CAPTURE(text);
              CHECK(text.find("${") == std::string::npos);
              CHECK_FALSE(std::regex_search(text, decimal_point));
            }
        }
      }
    }
  }
}

}  // namespace epure::test
