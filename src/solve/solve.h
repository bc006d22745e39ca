#pragma once
// The `epure solve` contract: one figure as a JSON object in, one JSON object out. Kinds, field
// names and reasons are the contract that other tools and our answer keys rely on (README,
// "epure solve").
#include <fmt/format.h>
#include <nlohmann/json_fwd.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace epure::solve {

// Bad input: the message names the field at fault ("field 'r': must be > 0").
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How the numbers of a line are read.
enum class Semantics {
  // As the doubles they are, every decision exact (README, "epure solve"; issue 15): what the
  // calculator owes its user.
  exact,
  // As the decimals a worksheet typed: a figure within the data's rounding of a boundary is on
  // it (segments parallel as decimals are parallel, a t within rounding of an end is that end).
  // The semantics the worksheets are drawn and their keys solved with (the generator's
  // instances "parallel as decimals" are parallel in their keys).
  worksheet,
};

// Solves one figure and appends its result object to `out`. Throws InputError (never anything
// else for bad data) when the figure is not a valid solve input.
void solve_figure(const nlohmann::json& figure, fmt::memory_buffer& out,
                  Semantics semantics = Semantics::worksheet);

// Limits on a line (README, "Limits"): a figure is a few hundred bytes and two levels deep.
inline constexpr std::size_t kMaxLineBytes = std::size_t(1) << 20;  // 1 MiB
inline constexpr int kMaxDepth = 32;

// One line of JSON Lines: parses, solves and appends the result object, or {"error": "..."}.
// Never throws. Returns the error message, empty when the line was solved. `epure solve` asks
// for Semantics::exact; without it, a line is solved as a worksheet's (the answer keys' call).
std::string solve_line(std::string_view line, fmt::memory_buffer& out);
std::string solve_line(std::string_view line, fmt::memory_buffer& out, Semantics semantics);

// The kinds the contract knows, in the contract's order.
inline constexpr std::string_view kKinds[] = {"vectors",     "projection",    "segments",
                                              "ray_circle",  "ray_square",    "ray_ellipse",
                                              "ray_rectangle", "ray_sphere",  "ray_cube"};

}  // namespace epure::solve
