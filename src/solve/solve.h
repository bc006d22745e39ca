#pragma once
// The `epure solve` contract: one figure as a JSON object in, one JSON object out. Kinds, field
// names and reasons are the contract that other tools and our answer keys rely on (README,
// "epure solve"). A line is read by solve/line_reader.h; the kinds of the registry
// (exercises/kinds/registry.cpp) read their fields by their schema and solve them
// (ExerciseKind::solve_figure): this file only dispatches.
#include <fmt/format.h>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "solve/fields.h"
#include "solve/line_reader.h"

namespace epure::solve {

// Solves one figure and appends its result object to `out`. Throws InputError (never anything
// else for bad data) when the figure is not a valid solve input. A number is the shortest
// decimal of its double here (a parsed document has lost its text); solve_line reads the text.
void solve_figure(const nlohmann::json& figure, fmt::memory_buffer& out);

// One line of JSON Lines: parses, solves and appends the result object, or {"error": "..."}.
// Never throws. Returns the error message, empty when the line was solved. One semantics for
// every caller (`epure solve`, the explorer, the keys): every decision exact for the decimals
// the line writes (README, "What a number means").
std::string solve_line(std::string_view line, fmt::memory_buffer& out);

// The kinds the contract knows, in the registry's order (a contract kind two exercise kinds
// share, `vectors` in the plane and in space, once).
std::vector<std::string_view> contract_kinds();

}  // namespace epure::solve
