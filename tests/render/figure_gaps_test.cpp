// The figures of the course's sheets and keys, as printed, keep their labels legible (issue 34):
// every figure is painted where layout_document puts it, into a canvas that records what a
// backend draws, over many seeds (both languages, the plane and space courses, every
// difficulty, sheets and keys), and measured:
// - a label's box keeps kGap from every other label's box, from every point, from every axis
//   number and from the ink of every stroke (its centre line less half the pen's width) — the
//   one it names as well, which the placer keeps clear the same way;
// - no stroke crosses an axis number (the number gives way: it is not printed).
// The placer keeps render::kLabelClearance (a little more than kGap): what it could not keep
// clear is counted and must stay rare, and is never text over text.
// 96 sheets and their keys, and 32 feedback sheets (the student's wrong points and vectors drawn
// on the key's figure, "I (you)"); about a second.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "exercises/key_json.h"
#include "exercises/spec.h"
#include "exercises/worksheet.h"
#include "grading/answer_key.h"
#include "grading/feedback_sheet.h"
#include "grading/feedback_text.h"
#include "grading/key_diagrams.h"
#include "grading/marking.h"
#include "grading/submission.h"
#include "render/label_placer.h"
#include "render/layout.h"
#include "render/scene_painter.h"
#include "render/recording_canvas.h"

using namespace epure;
using namespace epure::render;
using epure::test::RecordingCanvas;

namespace {

// The least gap, points, between a label's ink box and anything else printed in its figure.
// 1.5 pt (half a millimetre): two strokes' width of white at the thickest pen of a figure, what
// the eye needs to read a label as set apart rather than touching; the placer keeps a little
// more (kLabelClearance), so that rounding never brings a clean label under it.
constexpr double kGap = 1.5;
constexpr double kSlack = 1e-6;
const int kSheetsPerSet = std::getenv("EPURE_GAP_SHEETS") ? std::atoi(std::getenv("EPURE_GAP_SHEETS")) : 8;

double point_box(P2 p, const Box& b) {
  const double dx = std::max({b.x_min - p.x, 0.0, p.x - b.x_max});
  const double dy = std::max({b.y_min - p.y, 0.0, p.y - b.y_max});
  return std::hypot(dx, dy);
}

double point_segment(P2 p, P2 a, P2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// The distance between a segment and a box: 0 when it enters it.
double segment_box(P2 a, P2 b, const Box& box) {
  if (segment_hits_box(a, b, box)) return 0;
  double d = std::min(point_box(a, box), point_box(b, box));
  for (P2 c : {P2{box.x_min, box.y_min}, P2{box.x_max, box.y_min}, P2{box.x_min, box.y_max}, P2{box.x_max, box.y_max}})
    d = std::min(d, point_segment(c, a, b));
  return d;
}

double box_box(const Box& a, const Box& b) {
  const double dx = std::max({a.x_min - b.x_max, 0.0, b.x_min - a.x_max});
  const double dy = std::max({a.y_min - b.y_max, 0.0, b.y_min - a.y_max});
  return std::hypot(dx, dy);
}

struct Tally {
  int figures = 0, labels = 0, unclean = 0, leaders = 0, numbers = 0;
  int near_label = 0, near_stroke = 0, near_point = 0, near_number = 0, crossed_numbers = 0;
  std::vector<std::string> examples;
  void note(const std::string& what) {
    if (examples.size() < 12) examples.push_back(what);
  }
};

void measure(const Scene& scene, const PageRect& rect, const std::string& where, Tally& n) {
  RecordingCanvas canvas;
  const SceneReport report = paint_scene(canvas, scene, rect.x, rect.y, rect.width);
  ++n.figures;
  std::vector<Box> numbers;
  for (const auto& t : canvas.texts)
    if (t.group == "grid") numbers.push_back(t.box);
  n.numbers += static_cast<int>(numbers.size());
  // No stroke of the figure through an axis number.
  for (const Box& b : numbers)
    for (const auto& s : canvas.strokes)
      if (s.group != "panel" && segment_hits_box(s.a, s.b, inflate(b, -0.2))) {
        ++n.crossed_numbers;
        n.note(fmt::format("{}: a stroke ({}) crosses an axis number", where, s.group));
        break;
      }
  for (std::size_t p = 0; p < report.panels.size(); ++p) {
    const PanelReport& panel = report.panels[p];
    for (std::size_t i = 0; i < panel.labels.size(); ++i) {
      const Placement& l = panel.labels[i];
      const std::string& text = panel.texts[i];
      ++n.labels;
      n.leaders += l.leader ? 1 : 0;
      if (!l.clean) {
        ++n.unclean;
        const Box& a = panel.area;
        const bool out = l.box.x_min < a.x_min || l.box.x_max > a.x_max || l.box.y_min < a.y_min || l.box.y_max > a.y_max;
        n.note(fmt::format("{}: '{}' has no clean spot{}", where, text, out ? " (out of its panel)" : ""));
      }
      for (std::size_t j = 0; j < panel.labels.size(); ++j) {
        if (j == i) continue;
        if (const double d = box_box(l.box, panel.labels[j].box); d < kGap - kSlack && j > i) {
          ++n.near_label;
          n.note(fmt::format("{}: '{}' {:.2f} pt from '{}'", where, text, d, panel.texts[j]));
        }
      }
      for (const auto& s : canvas.strokes) {
        if (s.group == "panel") continue;  // the frame: a label stays inside it, as the placer says
        if (const double d = segment_box(s.a, s.b, l.box) - s.width / 2; d < kGap - kSlack) {
          ++n.near_stroke;
          n.note(fmt::format("{}: '{}' {:.2f} pt from a stroke ({})", where, text, d, s.group));
          break;
        }
      }
      for (const auto& d : canvas.discs)
        if (const double g = point_box(d.c, l.box) - d.r; g < kGap - kSlack) {
          ++n.near_point;
          n.note(fmt::format("{}: '{}' {:.2f} pt from a point", where, text, g));
          break;
        }
      for (const Box& b : numbers)
        if (const double d = box_box(l.box, b); d < kGap - kSlack) {
          ++n.near_number;
          n.note(fmt::format("{}: '{}' {:.2f} pt from an axis number", where, text, d));
          break;
        }
    }
  }
}

void measure_document(const Document& doc, const std::string& name, Tally& n) {
  const std::vector<LaidOutPage> pages = layout_document(doc);
  for (const LaidOutPage& page : pages)
    for (const PlacedFigure& f : page.figures) measure(*f.scene, f.rect, fmt::format("{} p.{}", name, page.number), n);
}

}  // namespace

TEST_CASE("figures as printed: labels set apart from labels, points, numbers and strokes; no stroke over a number") {
  Tally n;
  int seed = 500;
  for (const char* spec_name : {"builtin", "builtin:3d"}) {
    const WorksheetSpec spec = *builtin_spec(spec_name);
    for (const char* lang : {"en", "fr"}) {
      for (const Difficulty difficulty : {Difficulty::easy, Difficulty::standard, Difficulty::hard}) {
        SetOptions options;
        options.language = lang;
        options.difficulty = difficulty;
        WorksheetSet set(spec, static_cast<std::uint64_t>(++seed), options);
        set.measure_combs();  // as `epure generate` does
        for (int i = 0; i < kSheetsPerSet; ++i) {
          const Sheet sheet = set.next();
          const std::string id = fmt::format("{} {} {}", spec_name, lang, sheet.id.str());
          measure_document(set.sheet_document(sheet), id + " sheet", n);
          measure_document(set.key_document(sheet), id + " key", n);
        }
      }
    }
  }
  std::string examples;
  for (const auto& e : n.examples) examples += "\n  " + e;
  MESSAGE(fmt::format("{} figures, {} labels ({} with a leader, {} not clean), {} axis numbers; under {} pt: {} label "
                      "pairs, {} labels by a stroke, {} by a point, {} by a number; {} numbers crossed{}",
                      n.figures, n.labels, n.leaders, n.unclean, n.numbers, kGap, n.near_label, n.near_stroke,
                      n.near_point, n.near_number, n.crossed_numbers, examples));
  CHECK(n.figures > 500);
  CHECK(n.crossed_numbers == 0);
  CHECK(n.near_label == 0);
  CHECK(n.near_point == 0);
  CHECK(n.near_number == 0);
  CHECK(n.near_stroke == 0);
  CHECK(n.unclean == 0);
}

TEST_CASE("feedback sheets: the student's wrong points and vectors on the key's figure keep the same gaps") {
  Tally n;
  int seed = 600;
  for (const char* spec_name : {"builtin", "builtin:3d"}) {
    const WorksheetSpec spec = *builtin_spec(spec_name);
    for (const char* lang : {"en", "fr"}) {
      SetOptions options;
      options.language = lang;
      WorksheetSet set(spec, static_cast<std::uint64_t>(++seed), options);
      set.measure_combs();  // as `epure generate` does
      fmt::memory_buffer json;
      KeyJson::begin(json, set, "test");
      for (int i = 0; i < kSheetsPerSet; ++i) KeyJson::sheet(json, set.next(), i == 0);
      KeyJson::end(json);
      const grading::AnswerKey key = grading::read_key_json(std::string_view(json.data(), json.size()), "test");
      grading::KeyDiagrams diagrams(key, lang);
      REQUIRE(diagrams.available());
      const grading::FeedbackText text(lang, 2);
      for (const grading::SheetKey& sheet : key.sheets()) {
        // Every number right but the points' and vectors' coordinates, off by (0.7, −0.6): each
        // is drawn, with its "(you)" label, beside the key's.
        std::vector<std::vector<std::string>> cells;
        std::vector<grading::ExerciseMarks> marks(sheet.exercises.size());
        for (std::size_t e = 0; e < sheet.exercises.size(); ++e) {
          const grading::ExerciseKey& ex = sheet.exercises[e];
          std::vector<std::string>& row = cells.emplace_back();
          for (const grading::QuestionKey& q : ex.questions) {
            const bool x = q.field.ends_with(".x"), y = q.field.ends_with(".y");
            if (q.type != grading::AnswerType::number) row.emplace_back();
            else row.push_back(fmt::format("{:.2f}", q.number + (x ? 0.7 : y ? -0.6 : 0)));
          }
          std::vector<std::string_view> views(row.begin(), row.end());
          grading::mark_exercise(ex, views, {}, marks[e]);
        }
        grading::Submission s;
        s.line = 2;
        s.student = "T";
        s.sheet = &sheet;
        s.marks = marks;
        const Document doc = grading::feedback_document(s, key, text, &diagrams, {});
        measure_document(doc, fmt::format("{} {} {} feedback", spec_name, lang, sheet.sheet.str()), n);
      }
    }
  }
  std::string examples;
  for (const auto& e : n.examples) examples += "\n  " + e;
  MESSAGE(fmt::format("{} figures, {} labels ({} with a leader, {} not clean); under {} pt: {} label pairs, {} labels "
                      "by a stroke, {} by a point, {} by a number; {} numbers crossed{}",
                      n.figures, n.labels, n.leaders, n.unclean, kGap, n.near_label, n.near_stroke, n.near_point,
                      n.near_number, n.crossed_numbers, examples));
  CHECK(n.figures > 100);
  CHECK(n.crossed_numbers == 0);
  CHECK(n.near_label == 0);
  CHECK(n.near_point == 0);
  CHECK(n.near_number == 0);
  CHECK(n.near_stroke == 0);
  // A student's point falls anywhere, often on the key's own (a near miss): a label that finds no
  // spot clear of every type box and inside its panel stays rare, and still keeps the gaps above.
  CHECK(n.unclean * 100 <= n.labels);
}
