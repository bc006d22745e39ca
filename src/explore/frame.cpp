#include "explore/frame.h"

#include <nlohmann/json.hpp>

#include <cstring>

#include "render/scene_painter.h"

namespace epure::explore {

namespace {

using nlohmann::json;
using render::Box;

std::optional<FrameData> read_frame(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const json j = json::parse(text, nullptr, false);
  const auto box = [&](const char* key, Box& b) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_array() || j[key].size() != 4) return false;
    for (const auto& x : j[key])
      if (!x.is_number()) return false;
    b = {j[key][0].get<double>(), j[key][1].get<double>(), j[key][2].get<double>(), j[key][3].get<double>()};
    return b.width() > 0 && b.height() > 0;
  };
  FrameData f;
  if (!box("view", f.view) || !box("rect", f.rect)) return std::nullopt;
  return f;
}

}  // namespace

const std::string& frame_text(const FrameData& f) {
  thread_local FrameData last{};
  thread_local std::string text;
  if (text.empty() || std::memcmp(&last, &f, sizeof f) != 0) {  // bits: −0 is not 0 in JSON
    last = f;
    text = json{{"view", {f.view.x_min, f.view.y_min, f.view.x_max, f.view.y_max}},
                {"rect", {f.rect.x_min, f.rect.y_min, f.rect.x_max, f.rect.y_max}}}
               .dump();
  }
  return text;
}

std::optional<FrameData> frame_from(std::string_view text) {
  thread_local std::string last_text;
  thread_local std::optional<FrameData> last;
  if (text != last_text) {
    last = read_frame(text);
    last_text = text;
  }
  return last;
}

render::P2 to_math(const FrameData& f, render::P2 page) {
  const render::Frame frame(f.view, f.rect);
  const render::P2 corner = frame.to_page({f.view.x_min, f.view.y_max});
  return {f.view.x_min + (page.x - corner.x) / frame.scale(), f.view.y_max - (page.y - corner.y) / frame.scale()};
}

}  // namespace epure::explore
