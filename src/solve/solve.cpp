// Dispatching a figure to the kind that solves it. Compiled with the exercise kinds
// (src/CMakeLists.txt): the contract's kinds are the registry's, read by their schemas.
#include "solve/solve.h"

#include <nlohmann/json.hpp>

#include <span>
#include <utility>

#include "exercises/exercise.h"
#include "geometry/degenerate.h"
#include "solve/json_out.h"
#include "solve/result.h"

namespace epure::solve {

namespace {

// The kinds of a contract kind, in the registry's order.
struct ContractKind {
  std::string_view name;
  std::vector<const ExerciseKind*> kinds;
};

const std::vector<ContractKind>& contract_table() {
  static const std::vector<ContractKind> table = [] {
    std::vector<ContractKind> t;
    for (const ExerciseKind* kind : all_kinds()) {
      const std::string_view name = kind->contract_kind();
      auto it = std::find_if(t.begin(), t.end(), [&](const ContractKind& c) { return c.name == name; });
      if (it == t.end()) t.push_back({name, {kind}});
      else it->kinds.push_back(kind);
    }
    return t;
  }();
  return table;
}

// The kind that solves the figure: of those sharing its contract kind, the first that says so,
// else the first (whose reading then words the error).
const ExerciseKind* solver_for(std::string_view name, const Fields& figure) {
  for (const ContractKind& c : contract_table()) {
    if (c.name != name) continue;
    for (const ExerciseKind* kind : c.kinds)
      if (kind->solves(figure)) return kind;
    return c.kinds.front();
  }
  return nullptr;
}

void solve(std::span<const Field> figure, fmt::memory_buffer& out) {
  Fields fields(figure);
  const Value& kind = fields.get("kind");
  if (kind.type != Type::string) fail("kind", fmt::format("expected a string, got {}", type_name(kind.type)));
  const std::string_view name = kind.string;
  const ExerciseKind* solver = solver_for(name, fields);
  if (!solver) fail("kind", fmt::format("unknown kind '{}'", name));

  const std::size_t start = out.size();
  try {
    Result result(out, name);
    solver->solve_figure(fields, result);
    result.end();
  } catch (const geo::DegenerateFigure& e) {
    out.resize(start);
    fail(e.field(), e.what());
  } catch (...) {
    out.resize(start);
    throw;
  }
}

}  // namespace

void solve_figure(const nlohmann::json& figure, fmt::memory_buffer& out) {
  if (!figure.is_object()) throw InputError("line: expected a JSON object");
  // Views into `figure`, which outlives them.
  solve(fields_of(figure), out);
}

std::string solve_line(std::string_view line, fmt::memory_buffer& out) {
  std::string message;
  const std::size_t start = out.size();
  try {
    const LineReader figure(line);
    solve(figure.fields(), out);
    return {};
  } catch (const InputError& e) {
    message = e.what();
  } catch (const std::exception& e) {
    message = fmt::format("line: {}", e.what());
  }
  out.resize(start);
  JsonWriter(out).begin_object().field("error", std::string_view(message)).end_object();
  return message;
}

std::vector<std::string_view> contract_kinds() {
  std::vector<std::string_view> names;
  for (const ContractKind& c : contract_table()) names.push_back(c.name);
  return names;
}

}  // namespace epure::solve
