#include "exercises/sections.h"

#include <algorithm>
#include <cmath>

#include "exercises/instance_identity.h"

namespace epure::kinds {

void legend_highlight(render::Scene& scene, const ExerciseContext& ctx, std::string_view text_key,
                      render::LegendEntry::Swatch swatch) {
  if (render::uses_role(scene, render::Role::highlight)) scene.legend.push_back({render::Role::highlight, swatch, ctx.texts.get(std::string(text_key))});
}

render::Box view_around(const std::vector<render::P2>& points, double margin, double min_size,
                        double step) {
  double x0 = points.front().x, x1 = x0, y0 = points.front().y, y1 = y0;
  for (const auto& p : points) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  x0 -= margin, x1 += margin, y0 -= margin, y1 += margin;
  if (x1 - x0 < min_size) {
    const double grow = (min_size - (x1 - x0)) / 2;
    x0 -= grow, x1 += grow;
  }
  if (y1 - y0 < min_size) {
    const double grow = (min_size - (y1 - y0)) / 2;
    y0 -= grow, y1 += grow;
  }
  return {std::floor(x0 / step) * step, std::floor(y0 / step) * step, std::ceil(x1 / step) * step,
          std::ceil(y1 / step) * step};
}

namespace {

render::Section begin_section(const ExerciseContext& ctx, std::string_view title_key) {
  render::Section s;
  if (ctx.n == 0 && ctx.label.empty()) {
    // not on a sheet (the explorer's view of a kind): no number to give it
    s.add(render::Heading{ctx.texts.get(title_key), 1});
    return s;
  }
  const std::string label = !ctx.label.empty()
                                ? ctx.label
                                : ctx.texts.format("common.exercise_label", {{"n", number_of(ctx)}});
  s.add(render::Heading{ctx.texts.format("common.exercise_heading", {{"label", label}, {"title", ctx.texts.get(title_key)}}), 1});
  return s;
}
}  // namespace

render::Section begin_sheet_section(const ExerciseContext& ctx, std::string_view title_key) {
  return begin_section(ctx, title_key);
}

render::Section begin_key_section(const ExerciseContext& ctx, std::string_view title_key) {
  return begin_section(ctx, title_key);
}

}  // namespace epure::kinds
