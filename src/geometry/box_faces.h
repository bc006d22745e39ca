#pragma once
// The faces of the canonical square [-1,1]² and cube [-1,1]³: face k·σ is the side x_k = σ
// (σ = ±1), whose outward normal is σ·e_k. Names as the contract spells them: "+x", "-y", …
#include <array>
#include <cstdint>
#include <string_view>

namespace epure::geo {

struct Face {
  int axis;  // 0 = x, 1 = y, 2 = z
  int sign;  // +1 or −1
  bool operator==(const Face&) const = default;
};

std::string_view face_name(Face f);

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
  static std::uint8_t bit(Face f) { return std::uint8_t(1u << (f.axis + (f.sign > 0 ? 0 : 3))); }
  std::uint8_t bits_ = 0;
};

}  // namespace epure::geo
