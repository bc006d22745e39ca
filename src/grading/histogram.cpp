#include "grading/histogram.h"

#include <algorithm>

#include "render/svg_scene.h"

namespace epure::grading {

render::Scene histogram_scene(const ClassStatistics& stats, const FeedbackText& text) {
  const Texts& T = text.texts();
  const auto bins = stats.histogram();
  const double top = bins.empty() ? 1 : bins.back().to;
  int highest = 1;
  for (const auto& b : bins) highest = std::max(highest, b.count);
  // the tallest bar half as high as the scores' range is wide
  const double unit = top * 0.5 / highest;

  render::Scene s;
  s.title = T.get("grading.class.title");
  s.description = T.format("grading.class.description", {{"count", std::to_string(stats.marked())},
                                                          {"max", text.points(stats.max_points())},
                                                          {"mean", text.number(stats.mean())},
                                                          {"median", text.number(stats.median())}});
  render::Panel p;
  // room right of the axis for its name, so that it never sits on the last bar
  p.view = {-top * 0.08, -top * 0.12, top * 1.14, highest * unit + top * 0.1};
  p.caption = s.description;
  for (const auto& b : bins) {
    if (b.count > 0) {
      const double h = b.count * unit;
      p.add(render::Polygon{{{b.from, 0}, {b.to, 0}, {b.to, h}, {b.from, h}}, true, render::Role::result, true});
      p.add(render::Label{std::to_string(b.count), {(b.from + b.to) / 2, h}, render::Side::above, render::Role::result});
    }
    p.add(render::Tick{{b.from, 0}, {1, 0}, text.points(b.from), render::Role::data});
  }
  p.add(render::Tick{{top, 0}, {1, 0}, text.points(top), render::Role::data});
  p.add(render::Segment{{0, 0}, {top, 0}, render::Role::data});
  p.add(render::Label{T.get("grading.class.score_axis"), {top, 0}, render::Side::right, render::Role::data});
  p.add(render::Label{T.get("grading.class.count_axis"), {0, highest * unit}, render::Side::left, render::Role::data});
  s.panels.push_back(std::move(p));
  return s;
}

std::string histogram_svg(const ClassStatistics& stats, const FeedbackText& text) {
  return render::scene_to_svg(histogram_scene(stats, text), 480);
}

}  // namespace epure::grading
