#pragma once
// A path's `d` attribute, short: coordinates written to the hundredth of a point, each command
// absolute or relative to the current point, whichever is shorter, as SVG optimisers do.
#include <string>

#include "render/canvas.h"

namespace epure::render {

// Appends the path data of `path` to `d`. The relative steps are differences of the rounded
// absolute coordinates, so a long path draws exactly the points its absolute form would: no
// rounding accumulates along it.
void append_path_data(std::string& d, const Path& path);

}  // namespace epure::render
