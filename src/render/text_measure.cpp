#include "render/text_measure.h"

#include <utility>

namespace epure::render::layout_detail {

TextMeasure::Wrapped& TextMeasure::wrapped(const RichText& text, double size, double width) {
  const WrapView view{text, size, width};
  auto it = wrapped_.find(view);
  if (it == wrapped_.end())
    it = wrapped_.emplace(WrapKey{text, size, width}, Wrapped{wrap_measured(measured(text, size), width), {}}).first;
  return it->second;
}

std::size_t TextMeasure::line_count(const RichText& text, double size, double width) {
  return wrapped(text, size, width).lines.size();
}

const std::vector<std::vector<TextRun>>& TextMeasure::wrap(const RichText& text, double size, double width) {
  Wrapped& w = wrapped(text, size, width);
  if (!w.runs) {
    w.runs.emplace();
    for (const auto& line : w.lines) w.runs->push_back(parse_rich_text(line));
  }
  return *w.runs;
}

const std::vector<std::string>& TextMeasure::wrap_source(const RichText& text, double size, double width) {
  return wrapped(text, size, width).lines;
}

const MeasuredText& TextMeasure::measured(const RichText& text, double size) {
  const WrapView view{text, size, 0};
  auto it = measured_.find(view);
  if (it == measured_.end()) it = measured_.emplace(WrapKey{text, size, 0}, measure_text(text, size)).first;
  return it->second;
}

}  // namespace epure::render::layout_detail
