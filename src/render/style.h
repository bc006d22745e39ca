#pragma once
// The style sheet: how each Role of scene.h looks, and the sizes of a figure's furniture. One
// value passed to the painter, never a global. Every role differs from the others by its dash
// pattern or stroke width as well as by its colour, so that a key printed in grayscale still
// tells data from construction from result:
//
//   data          solid black, medium
//   construction  dashed grey-blue, thin
//   result        solid dark red, thick
//   normal        dash-dot dark green, medium, with an arrowhead
//   muted         dotted light grey, thin
//   highlight     solid orange, thickest
//   given         long-dashed purple, thickest (a student's answer: never orange, which means a
//                 candidate side)
//
// Lengths are in points (1/72 in).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene.h"

namespace epure::render {

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0;
  // "#rrggbb", for SVG.
  std::string hex() const {
    constexpr char kDigits[] = "0123456789abcdef";
    return {'#',
            kDigits[r >> 4],
            kDigits[r & 15],
            kDigits[g >> 4],
            kDigits[g & 15],
            kDigits[b >> 4],
            kDigits[b & 15]};
  }
  bool operator==(const Colour&) const = default;
};

struct RoleStyle {
  Colour colour;
  double width;              // stroke width
  std::vector<double> dash;  // on/off lengths; empty: solid
  double point_radius;       // a PointMark's disc
  Colour text;               // its labels
};

// The dash of a Segment drawn with `dashed` set, whatever its role.
inline const std::vector<double> kForcedDash = {5, 3};

struct Style {
  std::array<RoleStyle, 7> roles;

  // Text sizes.
  double label_size = 10;   // point and free labels
  double small_size = 8.5;  // ticks, dimensions, captions, links
  double number_size = 7;   // axis numbers

  // Furniture.
  Colour frame{0xb4, 0xb4, 0xb4};
  double frame_width = 0.5;
  Colour grid{0xe2, 0xe2, 0xe2};
  double grid_width = 0.5;
  Colour axis{0x8c, 0x8c, 0x8c};
  double axis_width = 0.8;
  Colour numbers{0x70, 0x70, 0x70};
  Colour caption{0x30, 0x30, 0x30};
  Colour background{0xff, 0xff, 0xff};  // behind labels, over the grid
  double fill_opacity = 0.12;           // a filled polygon's fill, in its role's colour

  // Marks.
  double arrow_length = 7;        // arrowhead, along the shaft
  double arrow_half_width = 2.6;  // arrowhead, across
  double right_angle_size = 7;
  double tick_half_length = 5.5;
  double dimension_arrow = 4.5;  // the smaller heads of a dimension line
  double label_gap = 2.5;        // between a mark and its label's box

  const RoleStyle& of(Role r) const { return roles[static_cast<std::size_t>(r)]; }

  // The style of printed sheets.
  static Style print() {
    Style s;
    s.roles[static_cast<std::size_t>(Role::data)] = {
        {0x00, 0x00, 0x00}, 1.3, {}, 2.6, {0x00, 0x00, 0x00}};
    s.roles[static_cast<std::size_t>(Role::construction)] = {
        {0x3d, 0x64, 0x8c}, 0.9, {5, 3}, 2.2, {0x2c, 0x4c, 0x6c}};
    s.roles[static_cast<std::size_t>(Role::result)] = {
        {0xa0, 0x12, 0x12}, 2.1, {}, 3.2, {0x8c, 0x0e, 0x0e}};
    s.roles[static_cast<std::size_t>(Role::normal)] = {
        {0x1b, 0x6e, 0x20}, 1.4, {6, 2, 1.5, 2}, 2.6, {0x15, 0x5a, 0x19}};
    s.roles[static_cast<std::size_t>(Role::muted)] = {
        {0xa8, 0xa8, 0xa8}, 0.9, {1, 2}, 2.0, {0x90, 0x90, 0x90}};
    s.roles[static_cast<std::size_t>(Role::highlight)] = {
        {0xe0, 0x70, 0x00}, 3.0, {}, 3.2, {0xb0, 0x58, 0x00}};
    s.roles[static_cast<std::size_t>(Role::given)] = {
        {0x7b, 0x1f, 0xa2}, 3.0, {7, 3}, 3.2, {0x6a, 0x1b, 0x9a}};
    return s;
  }
};

}  // namespace epure::render
