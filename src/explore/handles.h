#pragma once
// The explorer's handles: one per datum, placed by the datum's role as the kind's schema states it
// (exercises/data_field.h), never guessed from a field's name. A point is held where it is; a
// direction by its tip, drawn from the point it hangs on (from the origin when it hangs on none:
// the vectors kind); a radius at centre + (r, 0); a pair of sizes by the ends of the two axes
// ("radii.0", "radii.1"), the first also turning the figure.
//
// Data in space (a field of three components) are held where the key's 3D view (its first
// panel, drawn by kinds::space::camera()) projects them; the radius at its centre's image +
// (r, 0), on the sphere's outline (orthographic: the outline is a circle of radius r).
#include <nlohmann/json.hpp>

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "exercises/data_field.h"
#include "explore/frame.h"
#include "render/camera.h"

namespace epure::explore {

struct Handle {
  std::string id;    // the field's name; an axis end: "<field>.<0|1>"
  render::P2 at;     // math coordinates (of the 3D view: the camera's projection)
};

// Whether the kind's data are in space (the view's first panel is the camera's).
bool in_space(std::span<const DataField> fields);

// The handles of an instance of a kind with these fields: points, then directions, then radii,
// then axes, each in the schema's order. A field the instance lacks (or gives in another shape)
// has none.
std::vector<Handle> handles_of(std::span<const DataField> fields, const nlohmann::json& instance);

// The figure's SVG with the handles drawn over it, as circles the page's script can grab, and
// without the XML declaration (the SVG goes inside HTML).
std::string with_handles(std::string svg, const std::vector<Handle>& handles, const FrameData& frame);

// ---- the instance's data as the handles read them (also drag.cpp's)
bool is_pair(const nlohmann::json& j);
render::P2 pair_of(const nlohmann::json& j);
bool is_triple(const nlohmann::json& j);
render::P3 triple_of(const nlohmann::json& j);
// The instance's field `name` when it is a pair (a triple), else null.
const nlohmann::json* pair_field(const nlohmann::json& instance, std::string_view name);
const nlohmann::json* triple_field(const nlohmann::json& instance, std::string_view name);
// The point a direction hangs on (the origin when it hangs on none, or the instance lacks it).
render::P2 anchor_of(const nlohmann::json& instance, const DataField& direction);
render::P3 anchor3_of(const nlohmann::json& instance, const DataField& direction);
// The angle of the axes, degrees (0 when the instance gives none), and the unit vector of the
// axis `index` (0: the first, turned by that angle; 1: a quarter turn further).
double degrees_of(const nlohmann::json& instance, const DataField& axes);
render::P2 axis(double degrees, int index);
// The camera of the 3D views (kinds::space::camera()).
const render::Camera& camera();

}  // namespace epure::explore
