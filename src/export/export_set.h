#pragma once
// What the platform exports publish, read once from a generated set: every sheet's exercises
// as online questions. The numbers, rules and points are key.json's; the statement, the diagram
// and the answer fields are the sheet's own, drawn again from the key's spec and seed (and kept
// only when the drawn instance is exactly the key's); the named mistakes' values come from each
// kind's one method with that mistake switched on, and their feedback is the sentence the paper
// feedback prints. Moodle XML (moodle_xml.h) and QTI 2.1 (qti_package.h) only write this out.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exercises/exercise.h"

namespace epure::exporting {

// A set that cannot be exported: the message names the file and what is wrong.
class ExportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ImageFormat { png, svg };

struct Image {
  std::string name;        // "1000-0001-000X-2.png": unique in the set
  std::string media_type;  // "image/png", "image/svg+xml"
  std::string bytes;
  double width_px = 0;     // the width it is shown at
  std::string alt;         // plain text (the figure's description)
};

// A named mistake a platform recognises on one answer, with the paper feedback's sentence.
struct MistakeAnswer {
  std::string code;            // "far_intersection"
  double value = 0;            // a number's value the mistake gives
  double width = 0;            //   and the half-width it is recognised within (as on paper)
  std::vector<std::string> options;  // a choice's or a face set's option ids the mistake gives
  std::string feedback_html;   // the sentence, as HTML (sub- and superscripts)
};

struct Option {
  std::string id;    // the contract word ("between", "yes", "+x", "none")
  std::string html;  // the sheet's wording
  bool right = false;
};

// One answer field: a number, a choice (one of) or a set of faces (any of).
struct Part {
  enum class Type { number, choice, faces };
  std::string question_id;  // "2.P.x", as key.json names it
  Type type = Type::number;
  // false: a field the sheet prints but this case does not ask (t after a miss, the reason of a
  // hit). It is shown all the same, so that the question's shape does not tell the case, and
  // marked for nothing, as on paper (points 0, no right value, no mistakes).
  bool asked = true;
  double points = 1;
  double value = 0;  // number: the key's value
  double width = 0;  //   and the absolute half-width accepted, never looser than the key's rule
  // A coordinate of a point the key marks as a whole (a spec's whole_point): the distance to the
  // key's point that is accepted (the key's rule); `width` is then the per-coordinate square
  // inside that disc, for a platform that can only test coordinates one at a time.
  double radius = 0;
  std::vector<Option> options;  // choice, faces ("none" last, for a set that may be empty)
  std::vector<MistakeAnswer> mistakes;  // in the order grading tries them
};

// Every set of sides a faces part can be answered with, as the sheet's boxes allow any of them
// to be ticked (a named mistake may tick both sides of an axis): each as its option ids (empty:
// none), by size, then in the options' order (16 sets for the square's four sides, 64 for the
// cube's six faces).
std::vector<std::vector<std::string>> face_sets(const Part& faces);
// A set's wording, from the part's option wordings: "+x, −y", or the "none" option's.
std::string face_set_html(const Part& faces, const std::vector<std::string>& set);

// The question's body, in the sheet's order.
struct Block {
  enum class Kind { text, image, field } kind = Kind::text;
  std::string html;         // text: a paragraph's HTML; field: the prompt's HTML ("t =")
  int image = -1;           // image: index in Variant::images
  std::vector<int> parts;   // field: its parts (two for a point: x then y)
  bool point = false;       // field: a point, written (x, y)
  bool whole_point = false; // field: a point marked as a whole (its parts carry the radius)
};

// A piece of the key's worked solution, in the key's order.
struct SolutionBlock {
  enum class Kind { heading, text, image, answer } kind = Kind::text;
  std::string html;         // heading, text: its HTML; answer: the question's prompt ("t =")
  std::string answer_html;  // answer: the key's answer ("√10/2 ≈ 1.58")
  int image = -1;           // image: index in Variant::solution_images
};

// One student's instance of one exercise: one online question.
struct Variant {
  std::string sheet_id;
  std::string name;  // "Exercise 1 — Projection of a point on a line — 1000-0001-000X": the sheet's heading
  std::vector<Block> blocks;
  std::vector<Image> images;
  std::vector<Part> parts;
  double points = 0;  // the exercise's points (the parts' sum)
  // The key's worked steps, construction diagram and answers for this instance: what a platform
  // shows once the question is answered (Moodle's general feedback, QTI's solution feedback).
  std::vector<SolutionBlock> solution;
  std::vector<Image> solution_images;
};

struct ExerciseSlot {
  int n = 0;           // place on the sheet (the order of the slots)
  std::string number;  // what its question ids start with ("3.3")
  // The question ids some variant prints but does not ask: every variant then says that such a
  // box is not marked (export.not_asked_hint), and a platform that needs a right option in every
  // list offers "— (does not apply)" in these lists on every variant, so that neither tells the case.
  std::vector<std::string> not_asked;
  std::string kind;
  std::string title;  // the sheet's heading, "Exercise 1 — Projection of a point on a line", in the set's language
  std::vector<Variant> variants;  // in sheet order
};

struct ExportSet {
  std::filesystem::path key_path;
  std::string title;
  std::string language;
  std::vector<ExerciseSlot> exercises;
  std::string not_asked_feedback_html;  // what a box that is not asked says when filled in
  std::string does_not_apply_html;      // the option a list adds for a case that does not ask it
  std::string solution_title;           // plain text: what the worked solution is called ("Worked solution")
};

// Reads DIR/key.json and draws every exercise of every sheet again in `language` (the set's
// when empty). Throws ExportError naming the file: no key.json, a key that cannot be read, a
// key of another generator version, a set without exercises, an exercise that cannot be drawn
// again from the key's spec.
ExportSet read_set(const std::filesystem::path& dir, const std::string& language, ImageFormat images);

// ---- shared pieces of the writers

// RichText (the templates' label markup: t_{ab}, r^{2}, \vec{AB}) as HTML: text escaped,
// <sub>/<sup> for scripts, a combining arrow over a vector's name.
std::string html_of(std::string_view rich);
// (text escaped for XML and HTML: render/markup_escape.h)
// A variant's worked solution as XHTML that both Moodle and a QTI itemBody accept: paragraphs,
// the diagrams as <img src="<image_src><name>">, each run of answers as one two-column table.
std::string solution_html(const Variant& v, std::string_view image_src);
// The shortest decimal that reads back as x, with a '.' mark, no '+', no exponent when the
// plain form is as short ("0.26229508196721313", "-18", "1e-07").
std::string shortest(double x);
// The absolute half-width the key's rule accepts around `at` (isclose: max(rel·|at|, abs);
// a point marked by distance: abs/√2 per coordinate, so that both together stay within abs).
double rule_width(const ToleranceRule& rule, double at);
// A decimal half-width no larger than `width` even once a platform adds its own slack (Moodle
// adds 10^−14·max(tolerance, |value|)): `width` less 10^−12·max(1, |value|), rounded down to
// four significant digits.
double conservative_width(double width, double value);

}  // namespace epure::exporting
