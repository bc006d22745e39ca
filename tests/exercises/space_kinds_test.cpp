// The kinds in space at the level of the plane's: ray_sphere and ray_cube over many seeds per
// difficulty and branch (the instance drawn in the asked branch, the questions the solve
// contract answers, exact forms equal to the values, positive tolerances, complete texts in both
// languages, the key's worked steps), the same seed drawing the same sheet, the sphere's key
// diagram per branch, the cube's key walking its candidate faces in order, the spec's
// constraints held or refused, and the figure families written once over the dimension:
// a sphere whose figure lies in the plane z = 0 is the circle, a cube met in that plane is the
// square, under every named mistake too.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "exercises/exercise.h"
#include "exercises/kind_support.h"
#include "grading/expression.h"
#include "support/method_answers.h"

namespace {

using namespace epure;
using nlohmann::json;

constexpr Difficulty kLevels[] = {Difficulty::easy, Difficulty::standard, Difficulty::hard};

ExerciseInstance make(const std::string& kind, Difficulty level, const std::string& branch, std::uint64_t seed,
                      const char* language = "en") {
  ExerciseSpec spec;
  spec.kind = kind;
  spec.difficulty = level;
  const ExerciseContext ctx{3, spec, Texts::builtin(language), NumberStyle::for_language(language), 2, branch};
  Rng rng(seed, 11);
  return find_kind(kind)->make(rng, ctx);
}

// The solution's value of a question field: "t", "I.x" (I's first coordinate), "faces".
json solution_value(const json& solution, const std::string& field) {
  const auto dot = field.find('.');
  if (dot == std::string::npos) return solution.at(field);
  return solution.at(field.substr(0, dot)).at(field[dot + 1] - 'x');
}

// The same number, a NaN as a NaN (a mistake's road can leave the real numbers: √ of a negative).
bool same(double a, double b) { return std::isnan(a) ? std::isnan(b) : a == doctest::Approx(b).epsilon(1e-12); }

std::vector<std::string> texts_of(const render::Section& s) {
  std::vector<std::string> out;
  for (const auto& block : s.blocks) {
    if (auto* h = std::get_if<render::Heading>(&block)) out.push_back(h->text);
    if (auto* p = std::get_if<render::Paragraph>(&block)) out.push_back(p->text);
    if (auto* f = std::get_if<render::AnswerField>(&block)) out.push_back(f->prompt);
    if (auto* l = std::get_if<render::AnswerLine>(&block)) out.insert(out.end(), {l->prompt, l->answer});
    if (auto* f = std::get_if<render::Figure>(&block)) {
      out.insert(out.end(), {f->scene.title, f->scene.description});
      for (const auto& panel : f->scene.panels) out.push_back(panel.caption);
    }
  }
  return out;
}

// An instance drawn under a spec of the test's own (its constraints).
ExerciseInstance make_with(const ExerciseSpec& spec, const std::string& branch, std::uint64_t seed) {
  const ExerciseContext ctx{2, spec, Texts::builtin("en"), NumberStyle::for_language("en"), 2, branch};
  Rng rng(seed, 5);
  return find_kind(spec.kind)->make(rng, ctx);
}

const Question& question(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return q;
  FAIL("no question " << field);
  throw std::logic_error("unreachable");
}

const render::Scene& key_scene(const ExerciseInstance& inst) {
  const render::Figure* figure = nullptr;
  for (const auto& block : inst.key.blocks)
    if (auto* f = std::get_if<render::Figure>(&block)) figure = f;
  REQUIRE(figure != nullptr);
  return figure->scene;
}

int paragraphs(const render::Section& s) {
  int n = 0;
  for (const auto& block : s.blocks) n += std::holds_alternative<render::Paragraph>(block);
  return n;
}

void check_instance(const ExerciseInstance& inst, const std::string& kind, const std::string& branch) {
  CHECK(inst.kind == kind);
  CHECK(inst.branch == branch);
  const json solution = json::parse(inst.solution);
  CHECK(json::parse(kinds::solve_instance(inst.instance)) == solution);
  REQUIRE_FALSE(inst.questions.empty());
  for (const auto& q : inst.questions) {
    CAPTURE(q.field);
    const json expected = solution_value(solution, q.field);
    if (const double* x = std::get_if<double>(&q.expected)) {
      CHECK(*x == doctest::Approx(expected.get<double>()).epsilon(1e-12));
      CHECK(q.tolerance.abs > 0);
      if (q.exact) {
        const auto parsed = grading::parse_number(*q.exact);
        REQUIRE(parsed.ok);
        CHECK(parsed.value == doctest::Approx(*x).epsilon(1e-9));
      }
    } else if (const bool* b = std::get_if<bool>(&q.expected)) {
      CHECK(*b == expected.get<bool>());
    } else if (const auto* w = std::get_if<std::string>(&q.expected)) {
      CHECK(*w == expected.get<std::string>());
    } else {
      CHECK(std::get<std::vector<std::string>>(q.expected) == expected.get<std::vector<std::string>>());
    }
  }
  for (const auto& section : {inst.sheet, inst.key})
    for (const auto& t : texts_of(section)) {
      CAPTURE(t);
      CHECK(t.find("${") == std::string::npos);
      CHECK(t.find(".step.") == std::string::npos);
    }
}

}  // namespace

TEST_CASE("ray_sphere and ray_cube: every difficulty and branch, over many seeds") {
  for (const char* kind : {"ray_sphere", "ray_cube"})
    for (Difficulty level : kLevels)
      for (const auto& [branch, weight] : find_kind(kind)->default_branches())
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
          CAPTURE(kind);
          CAPTURE(static_cast<int>(level));
          CAPTURE(branch);
          CAPTURE(seed);
          const auto inst = make(kind, level, branch, seed);
          check_instance(inst, kind, branch);
          // the key tells the course's steps as the method reached them, then its figure
          CHECK(paragraphs(inst.key) >= 6);
        }
}

TEST_CASE("ray_sphere and ray_cube: French texts are complete, with a decimal comma") {
  for (const char* kind : {"ray_sphere", "ray_cube"})
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      CAPTURE(kind);
      CAPTURE(seed);
      const auto en = make(kind, Difficulty::standard, "hit", seed, "en");
      const auto fr = make(kind, Difficulty::standard, "hit", seed, "fr");
      CHECK(fr.instance == en.instance);  // the language never changes the draw
      check_instance(fr, kind, "hit");
      bool comma = false;
      // the French points "(1 ; 2 ; 3)", the decimal comma "0,5"
      for (const auto& t : texts_of(fr.key)) comma = comma || t.find("\u00a0;") != std::string::npos;
      CHECK(comma);
    }
}

TEST_CASE("ray_sphere and ray_cube: the same seed draws the same instance and the same texts") {
  for (const char* kind : {"ray_sphere", "ray_cube"}) {
    for (const auto& [branch, weight] : find_kind(kind)->default_branches())
      for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        CAPTURE(kind);
        CAPTURE(branch);
        CAPTURE(seed);
        const auto a = make(kind, Difficulty::standard, branch, seed), b = make(kind, Difficulty::standard, branch, seed);
        CHECK(a.instance == b.instance);
        CHECK(texts_of(a.key) == texts_of(b.key));
        CHECK(texts_of(a.sheet) == texts_of(b.sheet));
        CHECK(a.fingerprint == b.fingerprint);
      }
    CHECK(make(kind, Difficulty::standard, "hit", 1).instance != make(kind, Difficulty::standard, "hit", 2).instance);
  }
}

TEST_CASE("ray_sphere: the key's diagram shows the 3D view and the construction in the plane of the ray and C") {
  for (const char* branch : {"hit", "behind", "miss", "inside"}) {
    const std::string b = branch;
    CAPTURE(b);
    const auto inst = make("ray_sphere", Difficulty::standard, branch, 11);
    const render::Scene& scene = key_scene(inst);
    REQUIRE(scene.panels.size() == 2);  // the 3D view, then the plane in true size
    CHECK(scene.links.size() == 1);
    const bool hit = b == "hit" || b == "inside";
    int normals_3d = 0, outlines = 0;
    for (const auto& item : scene.panels[0].items) {
      if (auto* a = std::get_if<render::Arrow>(&item); a && a->role == render::Role::normal) ++normals_3d;
      if (std::holds_alternative<render::Circle>(item)) ++outlines;
    }
    CHECK(outlines == 1);  // the sphere's outline
    CHECK(normals_3d == (hit ? 1 : 0));
    int dimensions = 0, right_angles = 0, normals = 0, filled = 0, circles = 0;
    for (const auto& item : scene.panels[1].items) {
      if (std::holds_alternative<render::Dimension>(item)) ++dimensions;
      if (std::holds_alternative<render::RightAngle>(item)) ++right_angles;
      if (auto* a = std::get_if<render::Arrow>(&item); a && a->role == render::Role::normal) ++normals;
      if (auto* p = std::get_if<render::Polygon>(&item); p && p->filled) ++filled;
      if (std::holds_alternative<render::Circle>(item)) ++circles;
    }
    CHECK(circles == 1);
    CHECK(right_angles == 1);
    CHECK(dimensions == (hit ? 3 : b == "miss" ? 2 : 0));  // d, √(r² − d²), r; or d > r
    CHECK(normals == (hit ? 1 : 0));
    CHECK(filled == (hit ? 1 : 0));
  }
}

TEST_CASE("ray_sphere: a spec can tighten the constraints, and an impossible one is refused") {
  ExerciseSpec spec;
  spec.kind = "ray_sphere";
  spec.constraints["min_radius"] = 3;
  spec.constraints["max_radius"] = 3;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    CAPTURE(seed);
    CHECK(json::parse(make_with(spec, "hit", seed).instance)["r"].get<double>() == doctest::Approx(3).epsilon(1e-12));
  }
  spec.constraints["max_radius"] = 1;  // below the smallest radius
  CHECK_THROWS_AS(make_with(spec, "hit", 1), std::runtime_error);
}

TEST_CASE("ray_cube: the key walks the candidate faces in the course's order") {
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    CAPTURE(seed);
    const auto inst = make("ray_cube", Difficulty::standard, "hit", seed);
    const auto faces = std::get<std::vector<std::string>>(question(inst, "faces").expected);
    // from outside, the candidates are the faces whose outer half-space holds A: one to three
    CHECK(!faces.empty());
    CHECK(faces.size() <= 3);
    std::vector<std::string> walked;
    for (const auto& block : inst.key.blocks)
      if (auto* p = std::get_if<render::Paragraph>(&block))
        for (const auto& f : faces)
          if (p->text.rfind("Face " + kinds::face_label(f) + ":", 0) == 0) walked.push_back(f);
    CHECK(walked == faces);  // one step per candidate, in the contract's order of the faces
  }
}

TEST_CASE("ray_cube: from inside, the exit face is the smallest t among the faces the ray heads to") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    CAPTURE(seed);
    const auto inst = make("ray_cube", Difficulty::standard, "inside", seed);
    CHECK(std::get<bool>(question(inst, "inside").expected));
    CHECK(std::get<std::vector<std::string>>(question(inst, "faces").expected).empty());
    const json A = json::parse(inst.instance)["A"];
    for (int k = 0; k < 3; ++k) CHECK(std::abs(A[k].get<double>()) < 1);
    int exits = 0;
    for (const auto& block : inst.key.blocks)
      if (auto* p = std::get_if<render::Paragraph>(&block))
        exits += p->text.find("> 0, and t = (1 − A·") != std::string::npos;
    CHECK(exits >= 1);  // at least one face heads out of the cube
  }
}

TEST_CASE("ray_cube: a spec can tighten the constraints, and an impossible one is refused") {
  ExerciseSpec spec;
  spec.kind = "ray_cube";
  spec.constraints["t_min"] = 2;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    CAPTURE(seed);
    const auto inst = make_with(spec, "hit", seed);
    CHECK(std::get<double>(question(inst, "t").expected) >= 2 - 1e-9);
  }
  spec.constraints["t_min"] = 1000;  // no ray from the drawing's area travels that far to the cube
  CHECK_THROWS_AS(make_with(spec, "hit", 1), std::runtime_error);
}

TEST_CASE("ray_cube: faces are printed with the minus sign, as the square's sides") {
  const auto inst = make("ray_cube", Difficulty::standard, "hit", 2);
  bool candidates = false;
  for (const auto& t : texts_of(inst.key))
    if (t.rfind("Candidate faces:", 0) == 0) {
      candidates = true;
      CHECK(t.find("-x") == std::string::npos);
      CHECK(t.find("-y") == std::string::npos);
      CHECK(t.find("-z") == std::string::npos);
    }
  CHECK(candidates);
}

TEST_CASE("the ball's method in space: a sphere whose figure lies in z = 0 is the circle") {
  const ExerciseKind* circle = find_kind("ray_circle");
  for (const char* branch : {"hit", "behind", "miss", "inside"})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      CAPTURE(branch);
      CAPTURE(seed);
      ExerciseSpec spec;
      spec.kind = "ray_circle";
      const ExerciseContext ctx{1, spec, Texts::builtin("en"), NumberStyle::for_language("en"), 2, branch};
      Rng rng(seed, 3);
      const json flat = json::parse(circle->make(rng, ctx).instance);
      const json in_space = {{"kind", "ray_sphere"},
                             {"A", {flat["A"][0], flat["A"][1], 0}},
                             {"u", {flat["u"][0], flat["u"][1], 0}},
                             {"C", {flat["C"][0], flat["C"][1], 0}},
                             {"r", flat["r"]}};
      // every mistake on every road, and each road alone
      std::vector<method::Switches> runs;
      std::vector<std::string_view> roads{""};
      for (auto r : circle->roads()) roads.push_back(r);
      for (auto road : roads) {
        runs.push_back({"", road});
        for (auto m : circle->mistakes()) runs.push_back({m, road});
      }
      for (const method::Switches& run : runs) {
        CAPTURE(run.mistake);
        CAPTURE(run.road);
        const auto a = test::method_answers(flat.dump(), run);
        const auto b = test::method_answers(in_space.dump(), run);
        for (const auto& [field, values] : a) {
          CAPTURE(field);
          if (values.size() == 1) {
            REQUIRE(b.count(field));
            CHECK(same(b.at(field)[0], values[0]));
          } else {
            CHECK(same(b.at(field + ".x")[0], values[0]));
            CHECK(same(b.at(field + ".y")[0], values[1]));
            CHECK((std::isnan(values[0]) || b.at(field + ".z")[0] == 0));
          }
        }
      }
    }
}

TEST_CASE("the box's method in space: a cube met in the plane z = 0 is the square") {
  const ExerciseKind* square = find_kind("ray_square");
  for (const char* branch : {"hit", "miss", "inside"})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      CAPTURE(branch);
      CAPTURE(seed);
      ExerciseSpec spec;
      spec.kind = "ray_square";
      const ExerciseContext ctx{1, spec, Texts::builtin("en"), NumberStyle::for_language("en"), 2, branch};
      Rng rng(seed, 3);
      const json flat = json::parse(square->make(rng, ctx).instance);
      const json in_space = {{"kind", "ray_cube"},
                             {"A", {flat["A"][0], flat["A"][1], 0}},
                             {"u", {flat["u"][0], flat["u"][1], 0}}};
      // the cube declares the square's mistakes: the twins cannot drift
      const auto cube_mistakes = find_kind("ray_cube")->mistakes();
      REQUIRE(std::vector<std::string_view>(cube_mistakes.begin(), cube_mistakes.end()) ==
              std::vector<std::string_view>(square->mistakes().begin(), square->mistakes().end()));
      std::vector<std::string_view> mistakes{""};
      for (auto m : square->mistakes()) mistakes.push_back(m);
      for (std::string_view mistake : mistakes) {
        CAPTURE(mistake);
        const auto a = test::method_answers(flat.dump(), mistake);
        const auto b = test::method_answers(in_space.dump(), mistake);
        for (const auto& [field, values] : a) {
          CAPTURE(field);
          if (values.size() == 1) {
            CHECK(same(b.at(field)[0], values[0]));
          } else {
            CHECK(same(b.at(field + ".x")[0], values[0]));
            CHECK(same(b.at(field + ".y")[0], values[1]));
            CHECK((std::isnan(values[0]) || b.at(field + ".z")[0] == 0));
          }
        }
      }
      // and the same decisions, but for the faces ±z the cube adds
      const auto right_flat = square->evaluate(square->read_instance(flat), nullptr, "", 2);
      const ExerciseKind* cube = find_kind("ray_cube");
      const auto right_space = cube->evaluate(cube->read_instance(in_space), nullptr, "", 2);
      for (const auto& a : right_flat)
        for (const auto& b : right_space)
          if (a.id == b.id && a.type != method::AnswerType::number && a.type != method::AnswerType::point) {
            CAPTURE(a.id);
            CHECK(a.boolean == b.boolean);
            CHECK(a.faces == b.faces);  // +x +y −x −y are bits 0, 1, 3, 4 in both
          }
    }
}
