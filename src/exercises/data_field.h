#pragma once
// What a datum of a kind's schema is (kind_method.h: `v("u", d.u, role::from("A"))`): a point,
// a direction drawn from a point, a radius about a centre, the two axes of a figure about its
// centre, turned by an angle. The schema says it once, beside the field, and whoever needs the
// data's meaning reads it from there: the explorer's drag handles (explore/handles.h) hold a
// point where it is, a direction by its tip, a radius on the outline, the axes by their ends.
#include <string_view>
#include <vector>

namespace epure {

enum class FieldRole {
  point,      // a point of the figure (A, C): held where it is
  direction,  // a vector, drawn from `from` (the origin when empty): held by its tip
  radius,     // a length about the centre `from`: held at from + (r, 0)
  axes,       // a pair of sizes about the centre `from`, along axes turned by `angle`: held by the axes' ends
  number,     // a datum with no handle of its own (the angle the axes' first end sets)
};

// A role as a schema states it beside its field; the field's type gives the rest (a point, a
// vector, a number, a pair).
struct Role {
  FieldRole role = FieldRole::number;
  std::string_view from;   // direction, radius, axes: the point field it hangs on
  std::string_view angle;  // axes: the field of their angle, in degrees
  bool given = false;      // stated by the schema (else the field's type says: point, direction from the origin)
};

namespace role {
// A direction drawn from the point field `point`.
constexpr Role from(std::string_view point) { return {FieldRole::direction, point, {}, true}; }
// A length about the centre field `centre`.
constexpr Role radius_about(std::string_view centre) { return {FieldRole::radius, centre, {}, true}; }
// Two sizes about `centre` along the axes the field `angle` turns.
constexpr Role axes_about(std::string_view centre, std::string_view angle) {
  return {FieldRole::axes, centre, angle, true};
}
}  // namespace role

// One datum of an instance, as the schema declares it.
struct DataField {
  std::string_view name;
  int dim = 1;  // components: 2 or 3 for a point or a vector, 2 for a pair of sizes, 1 for a number
  Role role;
};

}  // namespace epure
