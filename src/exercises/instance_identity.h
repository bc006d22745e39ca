#pragma once
// An instance's identity: its data written as a solve input (the key's "instance"), the solve
// output for it, its fingerprint, and the set's check that no earlier sheet holds it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "exercises/exercise.h"
#include "geometry/vec.h"

namespace epure::kinds {

// The instance as a solve input, written field by field in the contract's names.
class InstanceWriter {
 public:
  explicit InstanceWriter(std::string_view kind);
  InstanceWriter& number(std::string_view field, double x);
  InstanceWriter& point(std::string_view field, geo::Point2 p);
  InstanceWriter& vec(std::string_view field, geo::Vec2 v);
  InstanceWriter& pair(std::string_view field, double a, double b);
  InstanceWriter& triple(std::string_view field, double a, double b, double c);
  std::string finish();

 private:
  std::string text_;
  bool first_ = true;
};

// The solve output for an instance: the one `epure solve` prints for it. Throws
// std::logic_error if the contract refuses the instance (a generator bug).
std::string solve_instance(std::string_view instance);

// 64-bit FNV-1a of the instance text: equal data, equal fingerprint.
std::uint64_t fingerprint(std::string_view text);

// The exercise's number as its question ids start ("3.3", "P"): the context's, else its place.
std::string number_of(const ExerciseContext& ctx);

// The set's collision check, made before the costly part of an instance (solution, exact forms,
// texts, scenes): when an earlier sheet already holds this instance (ctx.taken), only its
// identity (instance text and fingerprint) comes back, and the set draws again. Nothing else
// changes: the random draws are the same, so are the sheets.
std::optional<ExerciseInstance> already_taken(const ExerciseContext& ctx, std::string instance);

}  // namespace epure::kinds
