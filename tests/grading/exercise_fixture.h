#pragma once
// An exercise key made from a literal instance, as key.json would carry it: the solution from
// the solve contract, the expected values read from it, every number marked isclose with an
// absolute tolerance of 0.02 (a student's two decimals), 1 point per question. Then marking a
// row of cells against it.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "exercises/kind_support.h"
#include "grading/answer_key.h"
#include "grading/marking.h"

namespace epure::test {

inline nlohmann::json solution_value(const nlohmann::json& solution, const std::string& field) {
  const auto dot = field.find('.');
  if (dot == std::string::npos) return solution.at(field);
  return solution.at(field.substr(0, dot)).at(field[dot + 1] - 'x');
}

// `fields` in the order asked; a field absent from the solution is given by `extra`.
inline grading::ExerciseKey exercise(const std::string& instance, std::vector<std::string> fields,
                                     const std::vector<std::pair<std::string, nlohmann::json>>& extra = {},
                                     std::string rule = "isclose") {
  const nlohmann::json inst = nlohmann::json::parse(instance);
  const nlohmann::json sol = nlohmann::json::parse(kinds::solve_instance(instance));
  nlohmann::json questions = nlohmann::json::array();
  for (const auto& f : fields) {
    nlohmann::json expected;
    bool found = false;
    for (const auto& [name, value] : extra)
      if (name == f) expected = value, found = true;
    if (!found) expected = solution_value(sol, f);
    nlohmann::json q = {{"id", "1." + f}, {"expected", expected}, {"points", 1}};
    if (expected.is_number()) q["tolerance"] = {{"rule", rule}, {"rel", 0.001}, {"abs", 0.02}, {"why", "test"}};
    else q["tolerance"] = {{"rule", "exact"}, {"why", "test"}};
    // a point in the plane is marked as a point (a point in space: three numbers, as its keys)
    if (f.size() > 2 && (f.substr(f.size() - 2) == ".x" || f.substr(f.size() - 2) == ".y") &&
        !(sol.contains(f.substr(0, f.size() - 2)) && sol.at(f.substr(0, f.size() - 2)).size() == 3))
      q["point"] = "1." + f.substr(0, f.size() - 2);
    questions.push_back(q);
  }
  const nlohmann::json sheet = {
      {"id", "1000-0001-000X"},
      {"index", 0},
      {"exercises", {{{"n", 1}, {"kind", inst.at("kind")}, {"branch", ""}, {"instance", inst}, {"solution", sol}, {"questions", questions}}}}};
  return grading::read_sheet_json(sheet, "test").exercises.at(0);
}

// A kind in space whose kind is not the contract's ("vectors_3d" is the contract's vectors with
// three components): its points asked as three numbers, as its keys ask them.
inline grading::ExerciseKey exercise_in_space(const std::string& kind, const std::string& instance,
                                              const std::vector<std::string>& fields) {
  nlohmann::json sheet = nlohmann::json::parse(instance);
  const nlohmann::json sol = nlohmann::json::parse(kinds::solve_instance(instance));
  nlohmann::json questions = nlohmann::json::array();
  for (const auto& f : fields) {
    const nlohmann::json expected = solution_value(sol, f);
    nlohmann::json q = {{"id", "1." + f}, {"expected", expected}, {"points", 1}};
    if (expected.is_number()) q["tolerance"] = {{"rule", "isclose"}, {"rel", 0.001}, {"abs", 0.02}, {"why", "test"}};
    else q["tolerance"] = {{"rule", "exact"}, {"why", "test"}};
    questions.push_back(q);
  }
  const nlohmann::json key = {
      {"id", "1000-0001-000X"},
      {"index", 0},
      {"exercises", {{{"n", 1}, {"kind", kind}, {"branch", ""}, {"instance", sheet}, {"solution", sol}, {"questions", questions}}}}};
  return grading::read_sheet_json(key, "test").exercises.at(0);
}

struct Marked {
  const grading::ExerciseKey* key;
  grading::ExerciseMarks marks;
  // the cells' text: marks keep views of it (what was given), so it lives as long as they do,
  // on the heap, where moving a Marked never moves a string
  std::shared_ptr<const std::vector<std::string>> cells;

  const grading::QuestionMark& operator[](const std::string& field) const {
    const int i = key->find(field);
    REQUIRE_MESSAGE(i >= 0, field);
    return marks[static_cast<std::size_t>(i)];
  }
  double total() const {
    double t = 0;
    for (const auto& m : marks) t += m.points;
    return t;
  }
};

// Cells by field; the others blank.
inline Marked mark(const grading::ExerciseKey& key, std::initializer_list<std::pair<std::string, std::string>> answers,
                   bool follow_through = true) {
  auto storage = std::make_shared<std::vector<std::string>>(key.questions.size());
  for (const auto& [field, text] : answers) {
    const int i = key.find(field);
    REQUIRE_MESSAGE(i >= 0, field);
    (*storage)[static_cast<std::size_t>(i)] = text;
  }
  std::vector<std::string_view> cells(storage->begin(), storage->end());
  grading::MarkingOptions options;
  options.follow_through = follow_through;
  Marked m{&key, {}, storage};
  grading::mark_exercise(key, cells, options, m.marks);
  return m;
}

}  // namespace epure::test
