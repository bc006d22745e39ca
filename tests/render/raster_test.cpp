// A raster on a page (AnswerLine::shown: the crop of a scanned field on a feedback sheet): laid
// out under its prompt, within the prompt's column and its row, and drawn by both backends as
// the PNG it is (SVG: an inline data: URI; PDF: an image object).
#include <doctest/doctest.h>

#include <memory>
#include <string>

#include "recording_canvas.h"
#include "render/layout.h"
#include "render/page_painter.h"
#include "render/pdf_document.h"
#include "render/svg_page.h"
#include "support/base64.h"
#include "support/png_size.h"
#include "support/tiny_png.h"

using namespace epure;
using namespace epure::render;

namespace {

const std::string& kPng = test::kTinyPng;

Document answers(bool with_crop, const std::string& prompt = "t =") {
  Document doc;
  doc.title = "feedback";
  Section s;
  s.add(Heading{"Exercise 1", 1});
  for (int q = 0; q < 3; ++q) {
    AnswerLine line{"1.t" + std::to_string(q), prompt, "✓ 1.25  (1/1)"};
    if (with_crop && q == 1) line.shown = Raster{std::make_shared<const std::string>(kPng), 4, 2};
    s.add(std::move(line));
  }
  doc.sections.push_back(std::move(s));
  return doc;
}

}  // namespace

TEST_CASE("a PNG's size from its header; bytes that are not a PNG have none") {
  const auto size = png_size(kPng);
  REQUIRE(size);
  CHECK(size->width == 4);
  CHECK(size->height == 2);
  CHECK_FALSE(png_size(kPng.substr(0, 20)));
  CHECK_FALSE(png_size("GIF89a" + kPng));
  std::string huge = kPng;
  huge[16] = '\x7f';  // width 2^31 - …: beyond kMaxPngSide
  CHECK_FALSE(png_size(huge));
  CHECK(base64("epure") == "ZXB1cmU=");
}

// The row's texts (prompt, answer) above the crop, the next row's below it; the crop in the
// prompt's column (left of the answers) when it fits there, else under the whole row.
void check_crop_row(const std::string& prompt_text, bool in_prompt_column) {
  CAPTURE(prompt_text);
  const auto plain = layout_document(answers(false, prompt_text));
  const auto pages = layout_document(answers(true, prompt_text));
  REQUIRE(pages.size() == 1);
  REQUIRE(pages[0].images.size() == 1);
  CHECK(plain[0].images.empty());
  const PlacedImage& image = pages[0].images[0];
  // as wide as its pixels say for its height (4 : 2), two lines high
  CHECK(image.rect.width == doctest::Approx(2 * image.rect.height));
  CHECK(image.rect.height <= 2 * 14.0);
  const PlacedText* prompt = nullptr;
  const PlacedText* answer = nullptr;
  double next_row = 1e300;
  for (const auto& t : pages[0].texts) {
    if (t.runs.empty()) continue;
    const double y = t.baseline.y;
    const bool is_prompt = t.runs[0].text == prompt_text.substr(0, t.runs[0].text.size()) && t.ink == Ink::text;
    if (is_prompt && y < image.rect.y && (!prompt || y > prompt->baseline.y)) prompt = &t;
    if (t.ink == Ink::answer && y < image.rect.y && (!answer || y > answer->baseline.y)) answer = &t;
    if (is_prompt && y > image.rect.bottom()) next_row = std::min(next_row, y);
  }
  REQUIRE(prompt);
  REQUIRE(answer);
  CHECK(image.rect.x == doctest::Approx(prompt->baseline.x));
  CHECK(image.rect.y > prompt->baseline.y + 2);  // below the prompt's descenders
  if (in_prompt_column) {
    CHECK(image.rect.right() < answer->baseline.x);
  } else {
    CHECK(image.rect.y > answer->baseline.y + 2);
  }
  REQUIRE(next_row < 1e300);
  CHECK(next_row - 10 > image.rect.bottom());  // the next row's text (10 pt) starts below it
  // the row grew by the crop
  double last_plain = 0, last = 0;
  for (const auto& r : plain[0].rules) last_plain = std::max(last_plain, r.a.y);
  for (const auto& r : pages[0].rules) last = std::max(last, r.a.y);
  CHECK(last > last_plain + image.rect.height);

  // drawn where it was placed
  test::RecordingCanvas canvas;
  paint_page(canvas, pages[0]);
  REQUIRE(canvas.images.size() == 1);
  CHECK(canvas.images[0].x_min == doctest::Approx(image.rect.x));
  CHECK(canvas.images[0].y_max == doctest::Approx(image.rect.bottom()));
}

TEST_CASE("a crop is laid out under its prompt, in the prompt's column or under the whole row") {
  check_crop_row("the parameter t of the point P on the line =", true);
  check_crop_row("t =", false);  // a column too narrow for it
}

TEST_CASE("a crop in SVG is the PNG inline; in PDF an image object") {
  const Document doc = answers(true);
  const auto pages = layout_document(doc);
  const std::string svg = pages_to_svg(pages, doc);
  CHECK(svg.find("<image ") != std::string::npos);
  CHECK(svg.find("href=\"data:image/png;base64," + base64(kPng) + "\"") != std::string::npos);
  const std::string pdf = pages_to_pdf(pages, "feedback", {});
  CHECK(pdf.find("/Subtype /Image") != std::string::npos);
  const std::string pdf_plain = pages_to_pdf(layout_document(answers(false)), "feedback", {});
  CHECK(pdf_plain.find("/Subtype /Image") == std::string::npos);
}
