// No text over text on the course's pages, by the layout's own boxes: every sheet and key of
// sets in both languages, every difficulty, A4 and Letter, painted through the page painter
// into a canvas that keeps each run's type box (the font's ascent to descent at the run's size
// and shift: what a reader, and pdftotext, takes a word to fill). Two runs collide when their
// boxes overlap by more than a point both across and down, as tests/tools/page_collisions.py
// decides on the PDFs; this test sees the same through the layout, without a PDF.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "exercises/spec.h"
#include "exercises/worksheet.h"
#include "render/canvas.h"
#include "render/font_metrics.h"
#include "render/layout.h"
#include "render/page_painter.h"
#include "render/text.h"

using namespace epure::render;

namespace {

// pdftotext's rule: boxes that overlap by this much or less, both ways, only touch.
constexpr double kTouch = 1.0;
constexpr int kSheetsPerSet = 20;  // 240 sheets and keys, about 3,800 pages, under 2 s

struct TypeBox {
  Box box;
  std::string text;
};

struct TypeBoxCanvas final : Canvas {
  std::vector<TypeBox> boxes;
  void begin_group(std::string_view, std::string_view) override {}
  void end_group() override {}
  void push_clip(const Box&) override {}
  void pop_clip() override {}
  void path(const Path&, const Paint&) override {}
  void disc(P2, double, const Paint&) override {}
  void image(const Raster&, const Box&) override {}
  void text(const TextLine& line) override {
    const double width = text_width(line.runs, line.size);
    double x0 = line.at.x;
    if (line.anchor == Anchor::middle) x0 -= width / 2;
    if (line.anchor == Anchor::end) x0 -= width;
    const VerticalMetrics vm = vertical_metrics();
    const auto placed = place_runs(line.runs, line.size);
    for (std::size_t i = 0; i < placed.size(); ++i) {
      const RunPlacement& p = placed[i];
      if (line.runs[i].text.find_first_not_of(' ') == std::string::npos) continue;
      const double base = line.at.y - p.rise;
      boxes.push_back({{x0 + p.x, base - vm.ascent * p.size, x0 + p.x + p.width, base + vm.descent * p.size},
                       line.runs[i].text});
    }
  }
};

int collisions(const std::vector<TypeBox>& boxes, std::string& first) {
  int n = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Box& a = boxes[i].box;
      const Box& b = boxes[j].box;
      const double across = std::min(a.x_max, b.x_max) - std::max(a.x_min, b.x_min);
      const double down = std::min(a.y_max, b.y_max) - std::max(a.y_min, b.y_min);
      if (across > kTouch && down > kTouch) {
        if (n++ == 0) first = fmt::format("'{}' over '{}' at ({:.0f}, {:.0f})", boxes[i].text, boxes[j].text, a.x_min, a.y_min);
      }
    }
  }
  return n;
}

}  // namespace

TEST_CASE("pages: the check sees text printed over text") {
  LaidOutPage page;
  TextRun run;
  run.text = "t";
  PlacedText a{{100, 100}, 10, {run}, Ink::text};
  run.text = "cd";
  run.shift = Shift::sub;
  PlacedText b{{100, 100}, 10, {run}, Ink::text};  // a subscript on its own line, under t
  page.texts = {a, b};
  TypeBoxCanvas canvas;
  paint_page(canvas, page);
  std::string first;
  CHECK(collisions(canvas.boxes, first) == 1);
  // Two lines of body text, one line apart, only touch.
  page.texts[1] = PlacedText{{100, 100 + 10 * 1.4}, 10, {a.runs}, Ink::text};
  TypeBoxCanvas apart;
  paint_page(apart, page);
  CHECK(collisions(apart.boxes, first) == 0);
}

TEST_CASE("pages: no text over text on the course's sheets and keys (type boxes, many seeds)") {
  int pages = 0, set = 0;
  for (const char* lang : {"en", "fr"}) {
    for (epure::Difficulty difficulty :
         {epure::Difficulty::easy, epure::Difficulty::standard, epure::Difficulty::hard}) {
      for (const char* paper : {"A4", "letter"}) {
        epure::SetOptions options;
        options.language = lang;
        options.difficulty = difficulty;
        options.page = paper;
        const std::uint64_t seed = 500 + static_cast<std::uint64_t>(set++);
        epure::WorksheetSet worksheets(epure::builtin_spec(), seed, options);
        for (int s = 0; s < kSheetsPerSet; ++s) {
          const epure::Sheet sheet = worksheets.next();
          for (const Document& doc : {worksheets.sheet_document(sheet), worksheets.key_document(sheet)}) {
            for (const LaidOutPage& page : layout_document(doc)) {
              TypeBoxCanvas canvas;
              paint_page(canvas, page);
              std::string first;
              CAPTURE(lang);
              CAPTURE(paper);
              CAPTURE(seed);
              CAPTURE(doc.sheet_id);
              CAPTURE(page.number);
              CHECK(collisions(canvas.boxes, first) == 0);
              if (!first.empty()) MESSAGE(first);
              ++pages;
            }
          }
        }
      }
    }
  }
  CHECK(pages > 0);
}
