#include "explore/drag.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "explore/handles.h"

namespace epure::explore {

namespace {

using nlohmann::json;
using render::P2;
using render::P3;

// Grid steps of a keyboard nudge, and the rounding of dragged data: integers with snap (the
// exact forms of an easy sheet), hundredths without (data as a worksheet prints it).
constexpr double kSnapStep = 1, kFreeStep = 0.1, kFreeScale = 100;
constexpr double kSnapAngle = 15;  // degrees

double quantise(double x, bool snap) {
  // k / 100 as the nearest double, the one a worksheet's "3.51" denotes
  return snap ? std::round(x) : std::round(x * kFreeScale) / kFreeScale;
}

// The field a handle holds: its name, or for an axis's end "<name>.<index>" (index 0 or 1).
struct Held {
  const DataField* field = nullptr;
  int axis = -1;
};
Held held_by(std::span<const DataField> fields, std::string_view id) {
  for (const DataField& f : fields) {
    if (f.role.role == FieldRole::axes) {
      for (int i = 0; i < 2; ++i)
        if (id == fmt::format("{}.{}", f.name, i)) return {&f, i};
    } else if (f.role.role != FieldRole::number && id == f.name) {
      return {&f, -1};
    }
  }
  return {};
}

// The point of space that projects to m: in the horizontal plane through p, or (height) on the
// vertical through p. The projection is linear: m = x·X + y·Y + z·Z with X, Y, Z the axes' images.
P3 unprojected(P3 p, P2 m, bool height) {
  const render::Camera& cam = camera();
  const P2 X = cam.project({1, 0, 0}), Y = cam.project({0, 1, 0}), Z = cam.project({0, 0, 1});
  if (height) {
    // the vertical's image is a vertical line (Z.x = 0: the camera keeps z upright)
    const P2 foot = cam.project({p.x, p.y, 0});
    return {p.x, p.y, (m.y - foot.y) / Z.y};
  }
  // x·X + y·Y = m − z·Z, by Cramer's rule (X ∧ Y = sin(elevation) ≠ 0)
  const P2 r{m.x - p.z * Z.x, m.y - p.z * Z.y};
  const double det = X.x * Y.y - Y.x * X.y;
  return {(r.x * Y.y - Y.x * r.y) / det, (X.x * r.y - r.x * X.y) / det, p.z};
}

json triple_json(P3 p) { return json::array({p.x, p.y, p.z}); }

json moved3(json instance, const Held& held, P2 m, bool snap, bool height) {
  const DataField& f = *held.field;
  const std::string name(f.name);
  const auto placed = [&](P3 p) {
    const P3 q = unprojected(p, m, height);
    // only the coordinates the move changes are rounded; the others stay as they were
    return height ? P3{p.x, p.y, quantise(q.z, snap)} : P3{quantise(q.x, snap), quantise(q.y, snap), p.z};
  };
  switch (f.role.role) {
    case FieldRole::point:
      if (const json* p = triple_field(instance, f.name)) instance[name] = triple_json(placed(triple_of(*p)));
      return instance;
    case FieldRole::direction: {
      const json* field = triple_field(instance, f.name);
      if (!field) return instance;
      const P3 o = anchor3_of(instance, f), u = triple_of(*field);
      const P3 tip = placed(o + u);
      const P3 w = height ? P3{u.x, u.y, quantise(tip.z - o.z, snap)}
                          : P3{quantise(tip.x - o.x, snap), quantise(tip.y - o.y, snap), u.z};
      if (w.x == 0 && w.y == 0 && w.z == 0) return instance;  // a direction is never zero
      instance[name] = triple_json(w);
      return instance;
    }
    case FieldRole::radius:
      if (const json* c = triple_field(instance, f.role.from)) {
        // the outline is a circle of radius r around the centre's image
        const P2 ci = camera().project(triple_of(*c));
        const double r = quantise(std::hypot(m.x - ci.x, m.y - ci.y), snap);
        if (r > 0) instance[name] = r;
      }
      return instance;
    case FieldRole::axes:
    case FieldRole::number: return instance;
  }
  return instance;
}

json moved2(json instance, const Held& held, P2 m, bool snap) {
  const DataField& f = *held.field;
  const std::string name(f.name);
  const auto set_pair = [&](double a, double b) { instance[name] = json::array({a, b}); };
  switch (f.role.role) {
    case FieldRole::point:
      if (instance.contains(name)) set_pair(quantise(m.x, snap), quantise(m.y, snap));
      return instance;
    case FieldRole::direction: {
      const P2 o = anchor_of(instance, f);
      const double x = quantise(m.x - o.x, snap), y = quantise(m.y - o.y, snap);
      if (x == 0 && y == 0) return instance;  // a direction is never zero
      set_pair(x, y);
      return instance;
    }
    case FieldRole::number: return instance;
    case FieldRole::radius:
    case FieldRole::axes: break;
  }
  const json* centre = pair_field(instance, f.role.from);
  if (!centre) return instance;
  const P2 c = pair_of(*centre);
  const P2 d{m.x - c.x, m.y - c.y};
  if (f.role.role == FieldRole::radius) {
    const double r = quantise(std::hypot(d.x, d.y), snap);
    if (r > 0) instance[name] = r;
    return instance;
  }
  const json* sizes = pair_field(instance, f.name);
  if (!sizes) return instance;
  P2 s = pair_of(*sizes);
  if (held.axis == 0) {
    // the first axis's end: its length, and the figure's angle
    const double len = quantise(std::hypot(d.x, d.y), snap);
    double deg = std::atan2(d.y, d.x) * 180 / std::numbers::pi;
    deg = snap ? std::round(deg / kSnapAngle) * kSnapAngle : std::round(deg);
    if (deg <= -180) deg += 360;
    if (len <= 0) return instance;
    s.x = len;
    instance[std::string(f.role.angle)] = deg;
  } else {
    const P2 e = axis(degrees_of(instance, f), 1);
    const double len = quantise(std::abs(d.x * e.x + d.y * e.y), snap);
    if (len <= 0) return instance;
    s.y = len;
  }
  set_pair(s.x, s.y);
  return instance;
}

// A keyboard step in space: (dx, dy), an arrow's direction on the screen, moves along the floor
// axis (±x or ±y) whose image points most nearly that way (with the view's camera: → +y, ↑ −x);
// dz moves along z. A step of `step` on that coordinate, rounded as a drag rounds.
json nudged3(json instance, const Held& held, int dx, int dy, int dz, double step, bool snap) {
  const DataField& f = *held.field;
  const std::string name(f.name);
  if (f.role.role == FieldRole::radius) {
    const auto r = instance.find(name);
    if (r == instance.end() || !r->is_number()) return instance;
    const double grown = quantise(r->get<double>() + (dx != 0 ? dx : dy != 0 ? dy : dz) * step, snap);
    if (grown > 0) instance[name] = grown;
    return instance;
  }
  const json* field = triple_field(instance, f.name);
  if (!field) return instance;
  P3 p = triple_of(*field);
  if (dz != 0) {
    p.z = quantise(p.z + dz * step, snap);
  } else if (dx != 0 || dy != 0) {
    const P2 X = camera().project({1, 0, 0}), Y = camera().project({0, 1, 0});
    const double along_x = (dx * X.x + dy * X.y) / std::hypot(X.x, X.y);
    const double along_y = (dx * Y.x + dy * Y.y) / std::hypot(Y.x, Y.y);
    if (std::abs(along_x) >= std::abs(along_y)) p.x = quantise(p.x + (along_x > 0 ? step : -step), snap);
    else p.y = quantise(p.y + (along_y > 0 ? step : -step), snap);
  }
  if (f.role.role == FieldRole::direction && p.x == 0 && p.y == 0 && p.z == 0) return instance;
  instance[name] = triple_json(p);
  return instance;
}

}  // namespace

json moved(json instance, std::span<const DataField> fields, std::string_view id, P2 m, bool snap, bool height) {
  const Held held = held_by(fields, id);
  if (!held.field) return instance;
  if (in_space(fields)) return moved3(std::move(instance), held, m, snap, height);
  return moved2(std::move(instance), held, m, snap);
}

double nudge_step(bool snap) { return snap ? kSnapStep : kFreeStep; }

json nudged_in_space(json instance, std::span<const DataField> fields, std::string_view id, int dx, int dy, int dz,
                     bool snap) {
  const Held held = held_by(fields, id);
  return held.field ? nudged3(std::move(instance), held, dx, dy, dz, nudge_step(snap), snap) : instance;
}

}  // namespace epure::explore
