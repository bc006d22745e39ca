#pragma once
// A kind's method evaluated in doubles on a solve input, for tests: field → its value ([x] for a
// number, [x, y] for a point), optionally with a named mistake or another road switched on.
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "exercises/exercise.h"

namespace epure::test {

inline std::map<std::string, std::vector<double>> method_answers(std::string_view instance,
                                                                 method::Switches switches = {}) {
  const auto j = nlohmann::json::parse(instance);
  const ExerciseKind* kind = find_kind(j.at("kind").get<std::string>());
  std::map<std::string, std::vector<double>> out;
  for (const auto& a : kind->evaluate(kind->read_instance(j), nullptr, switches, 2)) {
    if (a.type == method::AnswerType::number) out[std::string(a.id)] = {a.x.v};
    if (a.type == method::AnswerType::point) out[std::string(a.id)] = {a.x.v, a.y.v};
  }
  return out;
}

}  // namespace epure::test
