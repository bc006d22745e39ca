#pragma once
// The sections every exercise has, begun with their headings, and the view box of a figure.
#include <string_view>
#include <vector>

#include "exercises/exercise.h"
#include "geometry/vec.h"
#include "render/scene.h"

namespace epure::kinds {

// The conversion every kind needs between the core's points and the scene's.
inline render::P2 p2(geo::Point2 p) { return {p.x, p.y}; }
inline render::P2 p2(geo::Vec2 v) { return {v.x, v.y}; }

// A view box around the given points with a margin, at least `min_size` wide and high, snapped
// outward to whole grid steps.
render::Box view_around(const std::vector<render::P2>& points, double margin, double min_size = 4,
                        double step = 1);

// Says in the scene's legend what its highlighted strokes or areas mean (`text_key`: "a
// candidate side"), when any is drawn, and only then: orange keeps one meaning in a figure type.
void legend_highlight(render::Scene& scene, const ExerciseContext& ctx, std::string_view text_key,
                      render::LegendEntry::Swatch swatch);

// The two sections every exercise has, begun with their headings.
render::Section begin_sheet_section(const ExerciseContext& ctx, std::string_view title_key);
render::Section begin_key_section(const ExerciseContext& ctx, std::string_view title_key);

}  // namespace epure::kinds
