// `epure kinds`: the exercise kinds the program knows, read from the kinds themselves (their
// solve contract's kind and data fields with their roles, branches and default weights,
// questions, named mistakes, constraints), so that scripts and tests take them from one place
// instead of a hand-kept table.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <memory>

#include "cli/commands.h"
#include "exercises/exercise.h"

namespace epure::cli {

namespace {

std::string_view type_name(method::AnswerType t) {
  switch (t) {
    case method::AnswerType::number: return "number";
    case method::AnswerType::point: return "point";
    case method::AnswerType::boolean: return "boolean";
    case method::AnswerType::choice: return "choice";
    case method::AnswerType::faces: return "faces";
  }
  return "number";
}

std::string_view role_name(FieldRole r) {
  switch (r) {
    case FieldRole::point: return "point";
    case FieldRole::direction: return "direction";
    case FieldRole::radius: return "radius";
    case FieldRole::axes: return "axes";
    case FieldRole::number: return "number";
  }
  return "number";
}

nlohmann::ordered_json describe(const ExerciseKind& kind) {
  nlohmann::ordered_json k;
  k["name"] = kind.name();
  // the solve input's kind and fields, in the schema's order: a point or vector's components
  // (2 or 3), 1 for a number; what the datum is (data_field.h), and what it hangs on
  k["solve_kind"] = kind.contract_kind();
  auto& data = k["data"] = nlohmann::ordered_json::array();
  for (const DataField& f : kind.data_fields()) {
    nlohmann::ordered_json j = {{"field", f.name}, {"dim", f.dim}, {"role", role_name(f.role.role)}};
    if (!f.role.from.empty()) j["from"] = f.role.from;
    if (!f.role.angle.empty()) j["angle"] = f.role.angle;
    data.push_back(j);
  }
  auto& branches = k["branches"] = nlohmann::ordered_json::object();
  for (const auto& [name, weight] : kind.default_branches()) branches[name] = weight;
  auto& questions = k["questions"] = nlohmann::ordered_json::array();
  if (!kind.questions().empty()) {
    for (const auto& q : kind.questions()) {
      nlohmann::ordered_json j = {{"field", q.field}, {"type", type_name(q.type)}, {"weight", q.weight}};
      if (!q.choices.empty()) j["choices"] = std::vector<std::string>(q.choices.begin(), q.choices.end());
      questions.push_back(j);
    }
  } else {
    for (const auto& f : kind.fields()) questions.push_back({{"field", f}});
  }
  k["mistakes"] = std::vector<std::string>(kind.mistakes().begin(), kind.mistakes().end());
  auto& constraints = k["constraints"] = nlohmann::ordered_json::object();
  for (const auto& [name, value] : kind.default_constraints()) constraints[name] = value;
  return k;
}

}  // namespace

void add_kinds_command(CLI::App& app, int& status) {
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("kinds", "List the exercise kinds: branches, questions, named mistakes");
  cmd->add_flag("--json", *json, "As one JSON array (for scripts)");
  cmd->callback([json, &status] {
    status = run_reporting("epure kinds", [&] {
      if (*json) {
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto* kind : all_kinds()) all.push_back(describe(*kind));
        fmt::print("{}\n", all.dump(2));
        return 0;
      }
      for (const auto* kind : all_kinds()) {
        std::vector<std::string> branches, questions;
        for (const auto& [name, weight] : kind->default_branches()) branches.push_back(fmt::format("{} ({})", name, weight));
        for (const auto& f : kind->fields()) questions.push_back(f);
        fmt::print("{}\n  branches: {}\n  questions: {}\n", kind->name(), fmt::join(branches, ", "),
                   fmt::join(questions, ", "));
        if (!kind->mistakes().empty()) fmt::print("  mistakes: {}\n", fmt::join(kind->mistakes(), ", "));
      }
      return 0;
    });
  });
}

}  // namespace epure::cli
