#pragma once
// Text as the backends set it: the label markup of scene.h (t_{ab}, r^{2}, \vec{AB}) parsed into
// runs, and widths measured with the advance widths of DejaVu Sans (the font epure's pages name),
// so that line breaking and label placement are decided once, deterministically, before any
// backend draws. Backends draw the runs; they do not re-wrap.
#include <span>
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

// The same parse as pieces of text, in order, each with its shift and arrow: what
// parse_rich_text gathers into runs (consecutive pieces of one shift and arrow make one run),
// for a writer that needs no runs (the explorer's HTML).
class RichSink {
 public:
  virtual void piece(std::string_view text, Shift shift, bool arrow) = 0;

 protected:
  ~RichSink() = default;
};
void parse_rich_pieces(std::string_view rich, RichSink& sink);

// Sub- and superscripts are set at this fraction of the font size, shifted by these fractions.
inline constexpr double kScriptScale = 0.7;
inline constexpr double kSubShift = 0.25;    // down, × font size
inline constexpr double kSuperShift = 0.38;  // up, × font size

// Advance width of the runs at `font_size` (same unit as font_size).
double text_width(std::span<const TextRun> runs, double font_size);
double text_width(std::string_view rich, double font_size, Weight weight = Weight::regular);

// Where a run sits in its line: everything a backend needs to set it and the painter needs to
// draw a \vec arrow over it. Lengths in the unit of font_size; `rise` is the baseline shift,
// positive up; `top` is the height of the run's letters above its own baseline (capitals and
// ascenders, or the x-height for a run of short lower-case letters).
struct RunPlacement {
  double x = 0;
  double width = 0;
  double size = 0;
  double rise = 0;
  double top = 0;
};
std::vector<RunPlacement> place_runs(std::span<const TextRun> runs, double font_size);

// The arrow over a \vec run, × the run's size: its stroke kArrowGap above the run's letters,
// its head kArrowHead long and 2 × kArrowHeadHalf wide, its stroke kArrowStroke thick.
inline constexpr double kArrowGap = 0.12;
inline constexpr double kArrowHead = 0.24;
inline constexpr double kArrowHeadHalf = 0.1;
inline constexpr double kArrowStroke = 0.06;

// The box a line of runs inks, from its baseline's left end: width, height above the baseline
// (arrows included), depth below it (descenders and subscripts). A little generous, never
// short: label placement keeps this box clear.
struct TextExtent {
  double width = 0, ascent = 0, descent = 0;
};
TextExtent text_extent(std::span<const TextRun> runs, double font_size);

// Greedy line breaking of rich text into lines no wider than `max_width`; breaks at spaces,
// never inside a markup group; a word longer than a line gets a line of its own; a '\n' forces a
// break (two in a row give an empty line). Empty text gives no line.
std::vector<std::vector<TextRun>> wrap_rich_text(std::string_view rich, double font_size,
                                                 double max_width, Weight weight = Weight::regular);
// The same lines, as the markup each is set from: joined with spaces they give the text back
// (but its '\n'), so that a paragraph can be split after its first lines.
std::vector<std::string> wrap_rich_source(std::string_view rich, double font_size, double max_width,
                                          Weight weight = Weight::regular);

// A text cut into the words a line may break between, each measured once: wrapping the same
// text at several widths (a layout trying options) then costs only the breaking.
struct MeasuredText {
  struct Word {
    std::size_t offset = 0, size = 0;  // in `text`
    double width = 0;
    bool glued = false;  // the space before it is not a place to break the line
  };
  std::string text;
  double space = 0;                      // a space's width
  std::vector<std::vector<Word>> pieces;  // the text's pieces between '\n's
};
MeasuredText measure_text(std::string_view rich, double font_size, Weight weight = Weight::regular);
// wrap_rich_source of a measured text: the same lines.
std::vector<std::string> wrap_measured(const MeasuredText& text, double max_width);

// The same lines as spans of the measured words, without building their text: what counting
// lines, or telling where a sentence ends, needs. `width` is the line's width as the breaking
// measured it (its words' widths and the spaces between them).
struct MeasuredLine {
  std::size_t piece = 0;             // index in MeasuredText::pieces
  std::size_t first = 0, end = 0;    // its words, [first, end) in that piece
  double width = 0;
};
// From `first_word` of the text's first piece on, when given: the rest of a paragraph after its
// first lines.
std::vector<MeasuredLine> break_measured(const MeasuredText& text, double max_width, std::size_t first_word = 0);
// A line's markup: its words joined by single spaces (wrap_measured's line).
std::string line_source(const MeasuredText& text, const MeasuredLine& line);

}  // namespace epure::render
