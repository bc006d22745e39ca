#include "explore/handles.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "exercises/kinds/space_common.h"
#include "render/scene_painter.h"

namespace epure::explore {

using nlohmann::json;
using render::P2;
using render::P3;

bool is_pair(const json& j) { return j.is_array() && j.size() == 2 && j[0].is_number() && j[1].is_number(); }
P2 pair_of(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }
bool is_triple(const json& j) {
  return j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
}
P3 triple_of(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

const json* pair_field(const json& instance, std::string_view name) {
  if (name.empty()) return nullptr;
  const auto it = instance.find(name);
  return it != instance.end() && is_pair(*it) ? &*it : nullptr;
}
const json* triple_field(const json& instance, std::string_view name) {
  if (name.empty()) return nullptr;
  const auto it = instance.find(name);
  return it != instance.end() && is_triple(*it) ? &*it : nullptr;
}

P2 anchor_of(const json& instance, const DataField& direction) {
  const json* from = pair_field(instance, direction.role.from);
  return from ? pair_of(*from) : P2{0, 0};
}
P3 anchor3_of(const json& instance, const DataField& direction) {
  const json* from = triple_field(instance, direction.role.from);
  return from ? triple_of(*from) : P3{0, 0, 0};
}

double degrees_of(const json& instance, const DataField& axes) {
  const auto it = axes.role.angle.empty() ? instance.end() : instance.find(axes.role.angle);
  return it != instance.end() && it->is_number() ? it->get<double>() : 0.0;
}

P2 axis(double degrees, int index) {
  const double a = degrees * std::numbers::pi / 180;
  return index == 0 ? P2{std::cos(a), std::sin(a)} : P2{-std::sin(a), std::cos(a)};
}

const render::Camera& camera() {
  static const render::Camera cam = kinds::space::camera();
  return cam;
}

bool in_space(std::span<const DataField> fields) {
  for (const DataField& f : fields)
    if (f.dim == 3) return true;
  return false;
}

namespace {

// The radius's handle: centre + (r, 0), when the instance gives both.
template <class Centre>
void radius_handle(std::vector<Handle>& out, const json& instance, const DataField& f, Centre&& centre) {
  const auto r = instance.find(f.name);
  if (r == instance.end() || !r->is_number()) return;
  if (const auto c = centre(f.role.from)) out.push_back({std::string(f.name), {c->x + r->get<double>(), c->y}});
}

std::vector<Handle> handles3_of(std::span<const DataField> fields, const json& instance) {
  const render::Camera& cam = camera();
  std::vector<Handle> out;
  for (const DataField& f : fields)
    if (f.role.role == FieldRole::point)
      if (const json* p = triple_field(instance, f.name)) out.push_back({std::string(f.name), cam.project(triple_of(*p))});
  for (const DataField& f : fields)
    if (f.role.role == FieldRole::direction)
      if (const json* u = triple_field(instance, f.name))
        out.push_back({std::string(f.name), cam.project(anchor3_of(instance, f) + triple_of(*u))});
  for (const DataField& f : fields)
    if (f.role.role == FieldRole::radius)
      radius_handle(out, instance, f, [&](std::string_view centre) -> std::optional<P2> {
        const json* c = triple_field(instance, centre);
        return c ? std::optional(cam.project(triple_of(*c))) : std::nullopt;
      });
  return out;
}

}  // namespace

std::vector<Handle> handles_of(std::span<const DataField> fields, const json& instance) {
  if (in_space(fields)) return handles3_of(fields, instance);
  std::vector<Handle> out;
  for (const DataField& f : fields)
    if (f.role.role == FieldRole::point)
      if (const json* p = pair_field(instance, f.name)) out.push_back({std::string(f.name), pair_of(*p)});
  for (const DataField& f : fields)
    if (f.role.role == FieldRole::direction)
      if (const json* u = pair_field(instance, f.name)) {
        const P2 o = anchor_of(instance, f), v = pair_of(*u);
        out.push_back({std::string(f.name), {o.x + v.x, o.y + v.y}});
      }
  const auto centre = [&](std::string_view name) -> std::optional<P2> {
    const json* c = pair_field(instance, name);
    return c ? std::optional(pair_of(*c)) : std::nullopt;
  };
  for (const DataField& f : fields)
    if (f.role.role == FieldRole::radius) radius_handle(out, instance, f, centre);
  for (const DataField& f : fields) {
    if (f.role.role != FieldRole::axes) continue;
    const auto c = centre(f.role.from);
    const json* sizes = pair_field(instance, f.name);
    if (!c || !sizes) continue;
    const P2 s = pair_of(*sizes);
    const double deg = degrees_of(instance, f);
    for (int i = 0; i < 2; ++i) {
      const P2 e = axis(deg, i);
      const double len = i == 0 ? s.x : s.y;
      out.push_back({fmt::format("{}.{}", f.name, i), {c->x + len * e.x, c->y + len * e.y}});
    }
  }
  return out;
}

std::string with_handles(std::string svg, const std::vector<Handle>& handles, const FrameData& f) {
  const render::Frame frame(f.view, f.rect);
  std::string g = "<g class=\"handles\">";
  for (const auto& h : handles) {
    const P2 p = frame.to_page(h.at);
    g += fmt::format(
        "<circle class=\"handle\" data-handle=\"{0}\" cx=\"{1:.3f}\" cy=\"{2:.3f}\" r=\"7\" tabindex=\"-1\" "
        "role=\"slider\" aria-label=\"{0}\"/>",
        h.id, p.x, p.y);
  }
  g += "</g>\n";  // one element per line, as the SVG writer writes them (the page patches by line)
  const auto end = svg.rfind("</svg>");
  if (end == std::string::npos) throw std::logic_error("explore: the figure is not an SVG document");
  svg.insert(end, g);
  // the XML declaration has no place inside HTML
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  return svg;
}

}  // namespace epure::explore
