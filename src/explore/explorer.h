#pragma once
// The core side of `epure explore` (the interactive page): everything the page shows is
// computed here, in the same C++ as the sheets, and compiled to WebAssembly (explore_wasm.cpp
// binds these functions; the page's script only handles input and puts the SVG and the steps it
// gets into the DOM). Strings in, strings out (JSON text), so that the binding is trivial and
// the same calls can be made natively.
//
// A view is a kind's answer key for the current data: the key's construction diagram (the
// kind's own key scene, drawn by the SVG backend of the sheets) with a draggable handle per
// datum, and the key's worked steps in the chosen language. Any kind registered with a key
// (ExerciseKind::key_of) has a view; its handles follow from its schema's data fields and their
// roles (ExerciseKind::data_fields; explore/handles.h places them, explore/drag.h moves them).
// This file is the page's API; the parts: handles.h, drag.h, frame.h (the figure's map),
// key_html.h (the key's steps as HTML).
#include <optional>
#include <string>
#include <string_view>

#include "render/scene.h"

namespace epure::explore {

// What `epure solve` prints for that line (its one semantics: the decimals written), without the
// newline.
std::string solve(std::string_view line);

// The kinds that have a view (every exercise kind, the preamble in space too, whose instances
// are the contract's vectors with three components), in the course's order, as a JSON array of
// names.
std::string kinds();

// The page's own words in `language` (templates/text/<lang>/explore.toml), as a JSON object
// {"title": …, "snap": …, …}. Throws std::invalid_argument for a language without texts.
std::string words(std::string_view language);

// A well-posed instance of `kind` to start from (its generator's first draw at seed 1), as a
// solve input. Throws std::runtime_error for a kind without a view.
std::string starting_instance(std::string_view kind);

// The view of `instance` (a solve input) in `language` ("en", "fr"), for exercise `n` of a
// sheet, or outside one with n = 0 (the key's heading is then the exercise's name alone, not
// "Exercise 1"), as a JSON object:
//   {"kind", "instance" (canonical text), "solution" (the key's solve output), "svg" (the figure with its handles),
//    "steps" (HTML of the worked solution), "frame" (the map of the figure's first panel, to be
//    handed back to drag), "handles": [{"id", "x", "y"}], "space" (true when the data are in
//    space: the first panel is the 3D view, and a drag has two modes, see drag), "error" (only
//    when the data cannot be solved: then no svg nor steps)}.
// With `frozen` (a frame this function returned), the first panel keeps that view, so that
// the figure stays still under a dragging pointer; the kind's own framing comes back on release.
// `label`: what the sheet calls exercise n ("Exercise 3", "Preamble"), so that the heading is
// the paper's; empty: "Exercise n".
std::string view(std::string_view instance, std::string_view language, int n = 0,
                 std::string_view frozen = {}, std::string_view label = {});

// The same view in three parts, for the page: `head` is view's JSON object without "svg" and
// "steps" (with "error" alone when the data cannot be solved: then svg and steps are empty),
// `svg` and `steps` the two long texts as they are, so that no figure is escaped into JSON and
// parsed out of it again. view() is head with the two texts put back in.
struct ViewParts {
  std::string head, svg, steps;
};
ViewParts view_parts(std::string_view instance, std::string_view language, int n = 0,
                     std::string_view frozen = {}, std::string_view label = {});

// The instance with handle `handle` moved to the figure point (x, y) (SVG user units of the
// view's figure, `frame` as view returned it). With `snap`, points land on the integer grid,
// sizes on whole numbers and angles on multiples of 15°; otherwise on hundredths. A move that
// would leave a direction or a size zero is refused (the instance comes back unchanged).
// Data in space (a 3D view): a point moves in the horizontal plane through it (z kept: its drop
// line's foot follows the pointer on the floor grid), or with `height` along its vertical (x and
// y kept, z under the pointer); r is the distance from C's image to the pointer (the outline).
std::string drag(std::string_view instance, std::string_view handle, double x, double y,
                 std::string_view frame, bool snap, bool height = false);

// The instance with handle `handle` moved by grid steps (the arrow keys): one unit with `snap`, a
// tenth without. In the plane, by (dx, dy) in the figure's math coordinates (dz ignored). In
// space, (dx, dy) is an arrow's direction on the screen and moves one step along the floor axis
// whose image points most nearly that way (→ +y, ← −y, ↑ −x, ↓ +x with the views' camera), dz
// one step along z (PageUp/PageDown); r grows with → and ↑.
std::string nudge(std::string_view instance, std::string_view handle, int dx, int dy, int dz, bool snap);

}  // namespace epure::explore
