#include "check/functions.h"

namespace epure::check {

namespace {

constexpr std::array<FunctionInfo, kFunctionCount> kFunctions{{
    {Fn::projection, "Projection", "projection", 6, 2, false, false, true},
    {Fn::segments, "InterSegments", "segments", 8, 2, true, false, true},
    {Fn::circle, "rayon_inter_cercle", "ray_circle", 7, 2, true, true, true},
    {Fn::circle_canonical, "rayon_inter_cercle_canonique", "ray_circle", 4, 2, true, true, true},
    {Fn::square_canonical, "rayon_inter_carre_canonique", "ray_square", 4, 2, true, true, true},
    {Fn::ellipse, "rayon_inter_ellipse", "ray_ellipse", 9, 2, true, true, false},
    {Fn::rectangle, "rayon_inter_rectangle", "ray_rectangle", 9, 2, true, true, false},
    {Fn::sphere, "rayon_inter_sphere", "ray_sphere", 10, 3, true, true, false},
    {Fn::cube_canonical, "rayon_inter_cube_canonique", "ray_cube", 6, 3, true, true, false},
}};

}  // namespace

const FunctionInfo& info(Fn fn) { return kFunctions[static_cast<std::size_t>(fn)]; }

std::span<const FunctionInfo> all_functions() { return kFunctions; }

std::optional<Fn> function_named(std::string_view c_name) {
  for (const auto& f : kFunctions)
    if (f.name == c_name) return f.fn;
  return std::nullopt;
}

std::string_view category_name(Category c) {
  switch (c) {
    case Category::sheet: return "sheet";
    case Category::random: return "random";
    case Category::near_parallel: return "near_parallel";
    case Category::touching_end: return "touching_end";
    case Category::tangent: return "tangent";
    case Category::on_boundary: return "on_boundary";
    case Category::just_inside: return "just_inside";
    case Category::inside: return "inside";
    case Category::corner: return "corner";
    case Category::huge: return "huge";
    case Category::tiny: return "tiny";
    case Category::far_origin: return "far_origin";
    case Category::non_unit: return "non_unit";
    case Category::perpendicular: return "perpendicular";
  }
  return "?";
}

}  // namespace epure::check
