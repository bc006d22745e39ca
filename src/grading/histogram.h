#pragma once
// The class's score histogram, drawn with the scene model (render/scene.h) and our SVG backend:
// one bar per bin, its count above it, score ticks along the bottom. Counts are scaled so that
// the panel keeps a readable aspect whatever the class size (the scene has one scale for both
// axes); the labels give the true counts.
#include <string>

#include "grading/feedback_text.h"
#include "grading/statistics.h"
#include "render/scene.h"

namespace epure::grading {

render::Scene histogram_scene(const ClassStatistics& stats, const FeedbackText& text);
std::string histogram_svg(const ClassStatistics& stats, const FeedbackText& text);

}  // namespace epure::grading
