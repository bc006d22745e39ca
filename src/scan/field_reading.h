#pragma once
// Reading a registered page's answer fields (layout_file.h's FieldLayout) through its map.
//
// Ink is measured against the page's own print, not a fixed grey level: the darkness of the
// corner marks (solid squares of the printer's ink, as scanned) is full ink, the paper around
// the field's boxes none; a pixel's ink is where it lies between the two. So a pale copy, a dark
// scan and a bilevel one read the same. (The boxes' own thin borders are no measure of full ink:
// at 150 dpi a 0.7 pt line is scanned grey.) The borders tell whether the boxes are where the
// map puts them: a field whose borders are not found is sent to review.
//
// A tick box: the share of its inside (away from the border, by more than a registration
// error) that is inked. Empty below kTickEmpty, ticked (a cross, a check mark) from kTickMarked;
// cancelled (filled, as the first page asks to correct a tick) when it is inked from kTickFilled
// and so are the middles of its four sides, which a cross or a check mark leaves white. A mark in
// a light pen (a cross at 40 % ink, as a worn felt-tip or a hard pencil writes it) is still a
// tick: it has no pixel past halfway, but a tick's share of the box past kLightInk, and it too
// leaves the sides' middles white (a box filled that lightly does not, and is not a tick). AMC
// reads such a mark as ticked too (its pixels are darker than its 60 % grey threshold). Between
// those, or a mark fainter still (what an eraser leaves), the box is uncertain and the field
// goes to review: never guessed.
//
// A box inked from kTickFilled is told by its shape as well as its share: a pen's fill inks it
// evenly, while a mark, however heavy, leaves the middle of some side lighter than the box's
// diagonals (a cross's wedges, the top of a check mark). Such a box is cancelled only when every
// side's middle is inked and none is lighter than the diagonals by kMarkContrast; ticked when
// the least inked side's middle is under kSidesOpen dark and lighter than the diagonals by
// kMarkContrast. Between those (a side's middle a third to half inked) lie both a cross in a heavy
// pen at 150 dpi (strokes of 3 px in a box of 21 ink 80 % of the inside: 6 to 14 tick fields a
// sample of 24-sheet stacks went to review for them) and a fill gone short of one side: a cross
// leaves four wedges, so it is ticked there only when three of the four sides' middles are
// lighter than the diagonals by kCrossContrast; a fill short of one side, or inked unevenly (a
// copier's speckle over a light fill), is uncertain. Under kTickFilled every mark is a tick: a
// "+" or a circled box leaves no side's middle white, so the shape is not asked there.
//
// A comb cell: its crop (digit_classifier.h) read by the network; the field's value is
// assembled from its cells (a sign cell, the integer digits, the decimals after the printed
// separator; empty decimal cells read as zeros) with a confidence, the product of its cells'.
#include <opencv2/core.hpp>

#include <array>

#include <string>
#include <vector>

#include "scan/digit_classifier.h"
#include "scan/layout_file.h"
#include "scan/registration.h"

namespace epure::scan {

enum class TickState { empty, ticked, cancelled, uncertain };
const char* tick_state_name(TickState s);

inline constexpr double kTickEmpty = 0.03;   // at most this share inked: empty
inline constexpr double kTickMarked = 0.07;  // from this share: a tick
inline constexpr double kTickFilled = 0.7;   // from this share, the sides' middles inked too: filled
inline constexpr double kSidesFilled = 0.6;  // the least inked side's middle of a filled box
// The shape's measures, from five samples of four stacks of 24 sheets (4,389 boxes inked past 0.4,
// every format, 2026-12-06): kMarkContrast, the diagonals' mean ink less the least inked side
// middle's: 1,024 filled boxes -0.008 to 0.028, the 421 marks inked from kTickFilled 0.374 up, every
// mark 0.206 up; halfway, rounded down. kCrossContrast, the diagonals' mean ink less the third
// least inked side middle's: the filled boxes -0.017 to 0.013, the 46 heavy crosses whose least
// inked side is between kSidesOpen and kSidesFilled 0.213 to 0.455 (a fill short of one side has
// three sides inked: under 0).
inline constexpr double kMarkContrast = 0.2;
inline constexpr double kCrossContrast = 0.15;
inline constexpr double kSidesOpen = 0.3;    // a mark leaves the dark share of a side's middle under this
inline constexpr double kTickFaint = 0.06;   // this share of faint ink (a quarter of the way) with no tick: uncertain
// A light pen's tick: this share of the inside past kLightInk, the sides' middles under
// kSidesOpen. Measured on the suite's four stacks of 24 sheets (221 crosses at 40 % ink, every
// format): their share past 0.3 is 0.33 to 0.76; an empty box's is 0 (its darkest pixel 0.085).
inline constexpr double kLightInk = 0.3;
inline constexpr double kTickLight = 0.15;

struct TickReading {
  TickState state = TickState::empty;
  double filled = 0;  // share of the inside darker than halfway to the border's ink
  double faint = 0;   // share darker than a quarter of the way
  double sides = 0;   // the least inked of the four sides' middles
  double light = 0;        // share past kLightInk
  double light_sides = 0;  // the least of the four sides' middles past kLightInk
  double open_side = 0;       // the least inked side middle's mean ink
  double contrast = 0;        // the diagonals' mean ink less open_side
  double cross_contrast = 0;  // the diagonals' mean ink less the third least inked side middle's
};

// What a box's measures say it holds (the rules above).
TickState tick_state(const TickReading& r);

// A cell read by the network below this confidence (after the second look and the sign cell's
// reading below) sends its field to review. Chosen on the trade-off between fields sent to
// review and silent errors (a wrong value not sent to review) measured on the suite's scans of
// generate's French sheets (README, "epure scan": samples of four stacks of 24 sheets, sets of
// seeds 5, 6 and 7, about 3,660 comb fields each; comb fields to review / silent errors with the
// three networks of depth 2, the second look from seven crops and the sign cell, 2026-12-06,
// noon: 0.80: 202 / 3, 196 / 3, 209 / 10; 0.81: 210 / 3, 204 / 2, 218 / 8; 0.82: 227 / 3,
// 215 / 1, 230 / 4; 0.84: 253 / 2, 242 / 0, 244 / 4): 0.82 is the lowest whose silent errors
// stay under the 0.1 % (4.8 fields) on every sample; on a fourth (seed 8), not used to
// choose, 233 / 4. The networks are trained with label smoothing (0.05), so their confidence
// never passes about 0.95: a threshold near that would send every field.
inline constexpr float kCellConfidence = 0.82f;

// A cell read under kSecondLook is read again from kSecondLookCrops other crops
// (second_look_cells: moved left, right, up, down by kSecondLookShift of its height; smaller and
// larger by kSecondLookScale about its centre; field_reading.cpp, second_look), and its
// confidence is then the seven readings' mean. The shift is train_digits.py's registration error
// (its cell borders drawn off by up to 0.08 H); the scale is within its scale augmentation.
inline constexpr float kSecondLook = 0.90f;
inline constexpr double kSecondLookShift = 0.08;
inline constexpr double kSecondLookScale = 0.08;
inline constexpr std::size_t kSecondLookCrops = 6;
std::array<Rect, kSecondLookCrops> second_look_cells(const Rect& cell);

// A sign cell holds a minus or nothing: the assembly takes nothing else there. Its reading is
// the likelier of the two, at its share of their probability (in_sign_cell): the mass the
// network gives the digits there is a digit it sees where none can stand, which only matters if
// one does. In the suite's scans the networks' doubts about a minus are digits (a minus at 0.63
// with a 7 at 0.20; 2,901 minus signs in three samples, their digits' mass up to 0.72, 0.23-0.27
// at the 99th centile), and such cells sent 15 to 19 comb fields a sample to review, of about
// 250. A sign cell whose minus and empty together hold less than kSignCellHeld of its mass is
// left as read: a digit there is likelier than not (a number begun a cell too far left), which
// the assembly sends to review ("the sign cell holds a digit"), never takes as a sign. Of the
// 29,276 digits written in the samples' other cells, none gave the minus and the empty cell
// together half their mass: a digit written in a sign cell would have been sent every time.
inline constexpr double kSignCellHeld = 0.5;
CellReading in_sign_cell(const CellReading& r);

// A comb cell as a field's reading keeps it: the network's best class and its probability, not
// the other classes' (a stack's readings are all kept until the outputs are written).
struct CellRead {
  CellClass best = CellClass::empty;
  float confidence = 0;
};

struct FieldReading {
  std::string question;
  std::string value;        // as a student types it in the answers spreadsheet; empty: blank
  bool blank = false;       // nothing written (or ticked)
  bool uncertain = false;   // goes to review
  double confidence = 1;    // the product of its cells' confidences
  std::string why;          // what made it uncertain ("cell 3: 0.62", "two boxes ticked")
  std::vector<TickReading> ticks;
  std::vector<CellRead> cells;
  std::string chars;        // comb: each cell's character as read ('?' below confidence)
};

// Paper and ink levels around a field: the paper around its boxes, and full ink (the marks').
struct InkLevels {
  double paper = 255;
  double ink = 0;
  double border = 0;  // the boxes' printed borders, as scanned
  double to_ink(double grey) const;  // 0 (paper) .. 1 (ink), not clamped
};

// Samples the crop the network reads for a cell: the cell with a margin of 0.15 of its height,
// centred in a square of side 1.3 × its height, 28 × 28 (each value the mean of 3 × 3 samples).
CellCrop crop_cell(const cv::Mat& grey, const PageMap& map, const Rect& cell, const InkLevels& levels);

// Reads one field of a registered page. `decimal_separator`: how a comb's value is written.
// `paper`: the page's paper level; `ink`: the marks' ink level (-1: take the boxes' borders').
FieldReading read_field(const cv::Mat& grey, const PageMap& map, const FieldLayout& field, double paper, double ink,
                        const std::string& decimal_separator, const DigitClassifier& net);

// The page's paper level: the 90th percentile of a reduced copy's grey levels.
double paper_level(const cv::Mat& grey);

// A field's crop for review.html and feedback: the field's cells with a margin, upright, at
// `scale` pixels per point.
cv::Mat field_image(const cv::Mat& grey, const PageMap& map, const FieldLayout& field, double scale);

}  // namespace epure::scan
