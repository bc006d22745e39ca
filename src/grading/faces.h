#pragma once
// Sets of face names ("+x", "-y", …) as bits, so that a set compares in any order with one
// integer comparison: +x +y +z -x -y -z are bits 0 … 5 (the contract's listing order, and the
// names: geometry/box_faces.h).
#include <cstdint>
#include <string>
#include <string_view>

#include "geometry/box_faces.h"

namespace epure::grading {

using FaceBits = std::uint8_t;

// The bit of a face name, 0 for a name that is not one.
inline FaceBits face_bit(std::string_view name) {
  const auto face = geo::face_named(name);
  return face ? FaceBits(1u << geo::face_index(*face)) : FaceBits(0);
}

// Every face swapped for its opposite: +x ↔ −x.
inline FaceBits opposite_faces(FaceBits f) { return FaceBits(((f & 7u) << 3) | ((f >> 3) & 7u)); }

// "+x, -y" in the contract's order; `none` for the empty set.
inline std::string face_list(FaceBits f, std::string_view none, std::string_view separator = ", ") {
  std::string out;
  for (int i = 0; i < 6; ++i)
    if (f & (1u << i)) {
      if (!out.empty()) out += separator;
      out += geo::kFaceNames[static_cast<std::size_t>(i)];
    }
  return out.empty() ? std::string(none) : out;
}

}  // namespace epure::grading
