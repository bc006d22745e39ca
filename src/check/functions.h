#pragma once
// The functions `epure check` knows: the course's five (Projection, InterSegments,
// rayon_inter_cercle, rayon_inter_cercle_canonique, rayon_inter_carre_canonique), then its open
// questions (an ellipse, a rectangle, the sphere and the cube), with the prototypes of
// templates/check/starter/*/raytracer.h. Their order is the harness's function numbers
// (templates/check/harness.c) and the report's.
//
// A case is the function's arguments as a flat list of doubles, in the prototype's order, and
// what it gives back is the boolean and the out-parameters (J then N), also flat.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace epure::check {

enum class Fn : std::uint8_t {
  projection,
  segments,
  circle,
  circle_canonical,
  square_canonical,
  ellipse,
  rectangle,
  sphere,
  cube_canonical,
};
inline constexpr int kFunctionCount = 9;
inline constexpr int kMaxInputs = 10;
inline constexpr int kMaxOutputs = 6;

struct FunctionInfo {
  Fn fn;
  std::string_view name;    // the C name
  std::string_view kind;    // the exercise kind whose key figure draws a case
  int inputs;               // doubles in a case
  int dimension;            // 2 or 3: the point J and the normal N have this many coordinates
  bool returns_bool;        // false: Projection (it returns the point)
  bool has_normal;          // J and N (the rays), or I / P alone
  bool course;              // one of the course's five
};

const FunctionInfo& info(Fn fn);
std::span<const FunctionInfo> all_functions();
std::optional<Fn> function_named(std::string_view c_name);

using Inputs = std::array<double, kMaxInputs>;

// What a function gave back: for Projection `hit` is true and J is P; for InterSegments J is I.
struct Outcome {
  bool hit = false;
  std::array<double, kMaxOutputs> out{};  // J (dimension), then N (dimension)
};

// The hard categories and the others a case belongs to (report.json names them).
enum class Category : std::uint8_t {
  sheet,          // the student's own sheet instance
  random,         // drawn like a sheet's data
  near_parallel,  // segments parallel as decimals, collinear, or crossing at a tiny angle
  touching_end,   // segments meeting exactly at an end of one
  tangent,        // a ray tangent, or within the data's rounding of it
  on_boundary,    // the origin on the figure (a side, the circle)
  just_inside,    // the origin inside, very near the boundary
  inside,         // the origin well inside
  corner,         // through a corner (an edge, a vertex) of the square or cube
  huge,           // the figure at a large scale
  tiny,           // the figure at a small scale
  far_origin,     // a canonical figure seen from far away
  non_unit,       // a direction that is not of length 1 where the contract allows it
  perpendicular,  // u·AC = 0: the ray perpendicular to the centre's direction
};
std::string_view category_name(Category c);

struct Case {
  Fn fn;
  Category category;
  Inputs in{};
};

}  // namespace epure::check
