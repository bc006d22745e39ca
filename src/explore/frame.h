#pragma once
// The map of a view's first panel between math coordinates and the figure's (SVG user units),
// as the page hands it back on every move of a drag: written as JSON text once per frame, read
// once per drag.
#include <optional>
#include <string>
#include <string_view>

#include "render/scene.h"

namespace epure::explore {

struct FrameData {
  render::Box view, rect;  // the panel's math view, and its rectangle in the figure
};

// As JSON text ({"view": [x_min, y_min, x_max, y_max], "rect": […]}); the frame of a drag stays
// what it was (the view is held still): the text is written once while it does.
const std::string& frame_text(const FrameData& f);

// The frame the page handed back, or nothing for an empty or malformed text (read once while
// the page hands back the same text).
std::optional<FrameData> frame_from(std::string_view text);

// The figure point's math coordinates: render::Frame's map, inverted (one scale, y flipped).
render::P2 to_math(const FrameData& f, render::P2 figure_point);

}  // namespace epure::explore
