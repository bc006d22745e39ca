#pragma once
// The class report's plots, as scenes (render/scene.h) that the SVG and cairo backends draw like
// every figure of a sheet: no plotting library, the same fonts and roles as the keys. Each is
// laid out for a figure `width` points wide (the page's text width): rows of 20 points, labels
// at 10 points, so that a name's room is measured (render/text.h) and never guessed.
//
//   marks      the distribution of the marks (out of N, or points), mean and median marked;
//   questions  per exercise, two panels side by side: each question's facility (share of the
//              class that earned it) and its discrimination (item–rest r, a dashed line at 0.2,
//              the usual floor of a question that tells stronger students from weaker ones;
//              below it, or negative, the bar is in the highlight colour);
//   branches   per exercise: each branch's facility with its number of sheets (a branch
//              significantly harder than the others in the highlight colour), and beside it the
//              named mistakes made in the exercise, counted.
#include <cstddef>
#include <optional>

#include "grading/class_words.h"
#include "grading/feedback_text.h"
#include "grading/item_analysis.h"
#include "grading/mark_scale.h"
#include "grading/statistics.h"
#include "render/scene.h"

namespace epure::grading {

inline constexpr double kPlotWidth = 480;  // points: an A4 page's text width, about

render::Scene marks_plot(const ClassStatistics& stats, const MarkScale& scale, const FeedbackText& text);
render::Scene questions_plot(const ItemAnalysis& items, std::size_t exercise, const FeedbackText& text);
// Nothing when the exercise drew one branch and no mistake was named in it.
std::optional<render::Scene> branches_plot(const ItemAnalysis& items, std::size_t exercise, const ClassWords& words,
                                           const FeedbackText& text);
// The width a scene of this file takes when drawn: the full width, or less for a lone panel.
double plot_width(const render::Scene& scene);

}  // namespace epure::grading
