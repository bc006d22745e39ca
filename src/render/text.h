#pragma once
// Text as the backends set it: the label markup of scene.h (t_{ab}, r^{2}, \vec{AB}) parsed into
// runs, and widths measured with the advance widths of DejaVu Sans (the font epure's pages name),
// so that line breaking and label placement are decided once, deterministically, before any
// backend draws. Backends draw the runs; they do not re-wrap.
#include <string>
#include <string_view>
#include <vector>

namespace epure::render {

enum class Shift { none, sub, super };

struct TextRun {
  std::string text;  // UTF-8, markup removed
  Shift shift = Shift::none;
  bool arrow = false;  // \vec{…}: an arrow drawn over this run
  bool bold = false;
};

enum class Weight { regular, bold };

// Parses the markup; unbalanced braces are taken literally (a label never fails to draw).
std::vector<TextRun> parse_rich_text(std::string_view rich, Weight weight = Weight::regular);

// Sub- and superscripts are set at this fraction of the font size, shifted by these fractions.
inline constexpr double kScriptScale = 0.7;
inline constexpr double kSubShift = 0.25;   // down, × font size
inline constexpr double kSuperShift = 0.38; // up, × font size

// Advance width of the runs at `font_size` (same unit as font_size).
double text_width(const std::vector<TextRun>& runs, double font_size);
double text_width(std::string_view rich, double font_size, Weight weight = Weight::regular);

// Greedy line breaking of rich text into lines no wider than `max_width`; breaks at spaces,
// never inside a markup group; a word longer than a line gets a line of its own; a '\n' forces a
// break (two in a row give an empty line). Empty text gives no line.
std::vector<std::vector<TextRun>> wrap_rich_text(std::string_view rich, double font_size,
                                                 double max_width, Weight weight = Weight::regular);

}  // namespace epure::render
