#pragma once
// The branches of a ray meeting a figure (the ball, the box and the transformed families): A
// inside the figure, or outside with the ray hitting it, the figure behind A (the ball's only),
// or missed. A type, so that a family's draw and diagrams compare branches, not strings; the
// names are the spec's and key.json's (and the texts' `figure.key.<branch>`).
#include <optional>
#include <string_view>

namespace epure::kinds {

enum class RayBranch { hit, behind, miss, inside };

constexpr std::string_view name(RayBranch b) {
  switch (b) {
    case RayBranch::hit: return "hit";
    case RayBranch::behind: return "behind";
    case RayBranch::miss: return "miss";
    case RayBranch::inside: return "inside";
  }
  return "hit";
}

// The branch a context asks for (its spec's word); none for another word (the explorer's views
// and key_of draw nothing and ask for no branch).
constexpr std::optional<RayBranch> ray_branch(std::string_view word) {
  for (RayBranch b : {RayBranch::hit, RayBranch::behind, RayBranch::miss, RayBranch::inside})
    if (name(b) == word) return b;
  return std::nullopt;
}

}  // namespace epure::kinds
