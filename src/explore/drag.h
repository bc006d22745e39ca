#pragma once
// The instance with one handle moved (explore/handles.h): by a drag to a figure point, or by a
// keyboard step. What moves is the handle's datum, as its role says: a point to the pointer, a
// direction's tip, a radius to the pointer's distance from its centre, an axis's end (the first
// also turning the figure). Data land on the grid with snap (integers, angles on multiples of
// 15°), on hundredths without; a move that would leave a direction or a size zero is refused
// (the instance comes back unchanged).
//
// In space a projected point has a line of points behind it, so a drag moves it in a plane: by
// default the horizontal plane through it (z kept, x and y under the pointer), the plane of the
// floor grid the view draws, so that the point's dashed drop line slides on the grid with its
// foot under the pointer; in `height` mode (Shift, or the page's toggle) along its vertical (x
// and y kept, z under the pointer), along that drop line. Either way a move changes the
// coordinates one reads on the view's grid, never all three at once, as a drag in the plane
// parallel to the screen would (that plane is tilted in x, y and z).
#include <nlohmann/json.hpp>

#include <span>
#include <string_view>

#include "exercises/data_field.h"
#include "render/scene.h"

namespace epure::explore {

// The instance with handle `id` at math point m (of the 3D view for data in space).
nlohmann::json moved(nlohmann::json instance, std::span<const DataField> fields, std::string_view id, render::P2 m,
                     bool snap, bool height = false);

// A keyboard step (the arrow keys): one unit with snap, a tenth without. In the plane a handle
// moves by (dx, dy) steps in math coordinates, as a drag to that point.
double nudge_step(bool snap);

// The instance in space with handle `id` moved by keyboard steps: (dx, dy) is an arrow's
// direction on the screen and moves one step along the floor axis whose image points most nearly
// that way, dz one step along z; a radius grows with → and ↑.
nlohmann::json nudged_in_space(nlohmann::json instance, std::span<const DataField> fields, std::string_view id,
                               int dx, int dy, int dz, bool snap);

}  // namespace epure::explore
