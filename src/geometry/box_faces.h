#pragma once
// The faces of the canonical square [-1,1]² and cube [-1,1]³: face k·σ is the side x_k = σ
// (σ = ±1), whose outward normal is σ·e_k. Names as the contract spells them: "+x", "-y", …
// This file is the one home of those names and of their order (the contract's listing order,
// also the bits of a face set: FaceSet here, method::FaceMask, grading::FaceBits).
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace epure::geo {

struct Face {
  int axis;  // 0 = x, 1 = y, 2 = z
  int sign;  // +1 or −1
  bool operator==(const Face&) const = default;
};

// Every face in the contract's listing order, +x +y +z −x −y −z: face i is bit i of a face set.
inline constexpr std::array<std::string_view, 6> kFaceNames = {"+x", "+y", "+z", "-x", "-y", "-z"};
constexpr int face_index(Face f) { return f.axis + (f.sign > 0 ? 0 : 3); }
constexpr Face face_at(int index) { return {index % 3, index < 3 ? +1 : -1}; }

// The face's name as the contract spells it ("+x", "-y").
constexpr std::string_view face_name(Face f) { return kFaceNames[static_cast<std::size_t>(face_index(f))]; }
// The face a name spells; none for a name that is not one of the six.
constexpr std::optional<Face> face_named(std::string_view name) {
  for (int i = 0; i < 6; ++i)
    if (kFaceNames[static_cast<std::size_t>(i)] == name) return face_at(i);
  return std::nullopt;
}

// A set of faces, listed in the contract's order: "+x","+y"(,"+z"),"-x","-y"(,"-z").
template <int Dim>
class FaceSet {
 public:
  void insert(Face f) { bits_ |= bit(f); }
  bool contains(Face f) const { return (bits_ & bit(f)) != 0; }
  bool empty() const { return bits_ == 0; }
  int size() const { return __builtin_popcount(bits_); }
  template <class F>
  void for_each(F&& f) const {
    for (int sign : {+1, -1})
      for (int axis = 0; axis < Dim; ++axis)
        if (contains({axis, sign})) f(Face{axis, sign});
  }
  bool operator==(const FaceSet&) const = default;

 private:
  static std::uint8_t bit(Face f) { return std::uint8_t(1u << face_index(f)); }
  std::uint8_t bits_ = 0;
};

}  // namespace epure::geo
