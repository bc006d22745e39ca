#include "grading/kinds/transformed.h"

#include <cmath>

#include "geometry/ray_circle.h"
#include "geometry/ray_square.h"
#include "geometry/ray_transformed.h"
#include "grading/kinds/instance.h"
#include "grading/review.h"

namespace epure::grading::kinds {

namespace {

using geo::Point2;
using geo::Transform2;
using geo::Vec2;

struct Canonical {
  bool hit = false;
  double t = 0;
};

Canonical solve_canonical(bool ellipse, Point2 Ac, Vec2 uc) {
  const geo::Ray2 ray{Ac, uc};
  if (ellipse) {
    const auto c = geo::intersect_canonical_circle(ray);
    return c.hit ? Canonical{true, c.hit->t} : Canonical{};
  }
  const auto s = geo::intersect_canonical_square(ray);
  return s.hit ? Canonical{true, s.hit->t} : Canonical{};
}

bool inside_canonical(bool ellipse, Point2 Ac) {
  if (ellipse) return Ac.x * Ac.x + Ac.y * Ac.y < 1;
  return std::max(std::abs(Ac.x), std::abs(Ac.y)) < 1;
}

// The outward normal at a canonical point: the circle's radius, or the square's side (the
// larger coordinate).
Vec2 canonical_normal(bool ellipse, Point2 Ic) {
  if (ellipse) return geo::to_vec(Ic);
  return std::abs(Ic.x) >= std::abs(Ic.y) ? Vec2{Ic.x < 0 ? -1.0 : 1.0, 0} : Vec2{0, Ic.y < 0 ? -1.0 : 1.0};
}

Point2 unit_or_zero(Vec2 v) {
  const auto n = geo::normalized(v);
  return n ? geo::to_point(*n) : Point2{0, 0};
}

}  // namespace

TransformedData read_transformed(const nlohmann::json& instance, bool ellipse) {
  TransformedData d;
  d.ellipse = ellipse;
  d.A = instance_point(instance, "A");
  d.u = instance_vec(instance, "u");
  d.C = instance_point(instance, "C");
  const auto [sx, sy] = instance_pair(instance, ellipse ? "radii" : "half");
  d.sx = sx;
  d.sy = sy;
  d.angle = instance_number(instance, "angle");
  d.uh = unit_direction(d.u);
  const geo::Ray2 ray{d.A, d.uh};
  if (ellipse) {
    const geo::Ellipse e{d.C, sx, sy, d.angle};
    const auto res = geo::intersect(ray, e);
    d.to_world = res.to_world;
    d.canonical_ray = res.canonical_ray;
    d.inside = res.inside;
    d.hit = res.hit;
    d.canonical_hit = res.canonical.hit;
  } else {
    const geo::Rectangle rect{d.C, sx, sy, d.angle};
    const auto res = geo::intersect(ray, rect);
    d.to_world = res.to_world;
    d.canonical_ray = res.canonical_ray;
    d.inside = res.inside;
    d.hit = res.hit;
    d.canonical_hit = res.canonical.hit;
  }
  d.to_canonical = d.to_world.inverse();
  return d;
}

void review_transformed(const TransformedData& d, ExerciseReview& r) {
  const Transform2 unscale = Transform2::scale(1 / d.sx, 1 / d.sy);
  const Vec2 CA = d.A - d.C;
  r.mistake_point("Ac", geo::to_point((unscale * Transform2::rotate_degrees(d.angle)).apply(CA)), "rotation_sign");
  r.mistake_point("Ac", geo::to_point(d.to_canonical.apply(geo::to_vec(d.A))), "translation_forgotten");
  r.mistake_point("Ac", geo::to_point((Transform2::rotate_degrees(-d.angle) * unscale).apply(CA)), "transform_order");

  const Vec2 uc_key = d.canonical_ray.direction;
  r.mistake_point("uc", unit_or_zero(uc_key), "uc_renormalised");
  r.mistake_point("uc", geo::to_point(d.to_canonical.apply(d.u)), "direction_not_unit");
  r.mistake_point("uc", d.to_canonical.apply(geo::to_point(d.uh)), "direction_translated");

  const Point2 Ac = r.point("Ac").value_or(d.canonical_ray.origin);
  const Point2 uc_point = r.point("uc").value_or(geo::to_point(uc_key));
  const Vec2 uc = geo::to_vec(uc_point);
  r.follow_boolean("inside", inside_canonical(d.ellipse, Ac), "Ac");
  if (uc.x != 0 || uc.y != 0) {
    const Canonical theirs = solve_canonical(d.ellipse, Ac, uc);
    r.follow_boolean("hit", theirs.hit, "Ac uc");
    if (theirs.hit) r.follow("t", theirs.t, "Ac uc");
  }
  if (!d.hit) return;

  if (d.ellipse) {
    // |A_c + t·u_c|² = 1: the two roots, the key's is the first ahead of A
    const Vec2 a = geo::to_vec(d.canonical_ray.origin);
    const double qa = geo::dot(uc_key, uc_key), qb = 2 * geo::dot(a, uc_key), qc = geo::dot(a, a) - 1;
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0 && qa != 0) {  // guards the division
      const double root = std::sqrt(disc);
      const double near = (-qb - root) / (2 * qa), far = (-qb + root) / (2 * qa);
      if (d.inside) r.mistake("t", near, "near_root_inside");
      else r.mistake("t", far, "far_intersection");
      if (!d.inside) r.mistake_point("I", d.A + far * d.uh, "far_intersection");
    }
  }
  const double t = r.number("t").value_or(d.hit->t);
  r.follow_point("I", d.A + t * d.uh, "t");
  r.mistake_point("I", d.canonical_hit->I, "not_back_to_world");

  const Vec2 N = d.hit->N, Nc = d.canonical_hit->N;
  r.mistake_point("N", geo::to_point(-N), "normal_inward");
  r.mistake_point("N", geo::to_point(d.to_world.apply_normal(Nc)), "normal_not_unit");
  r.mistake_point("N", unit_or_zero(d.to_world.apply(Nc)), "normal_wrong_transform");
  r.mistake_point("N", geo::to_point(Nc), "not_back_to_world");
  if (const auto I = r.point("I")) {
    const Point2 Ic = d.to_canonical.apply(*I);
    r.follow_point("N", unit_or_zero(d.to_world.apply_normal(canonical_normal(d.ellipse, Ic))), "I");
  }
}

std::vector<std::string_view> transformed_mistakes() {
  return {"rotation_sign",        "translation_forgotten", "transform_order",   "uc_renormalised",
          "direction_not_unit",   "direction_translated",  "far_intersection",  "near_root_inside",
          "not_back_to_world",    "normal_inward",         "normal_not_unit",   "normal_wrong_transform"};
}

std::vector<DrawnField> transformed_drawn() {
  return {{"I", 0, {}}, {"N", 0, "I"}, {"Ac", 1, {}}, {"uc", 1, "Ac"}};
}

}  // namespace epure::grading::kinds
