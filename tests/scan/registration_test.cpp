#include <doctest/doctest.h>

#include <opencv2/imgproc.hpp>

#include "exercises/sheet_id.h"
#include "scan/field_reading.h"
#include "exercises/page_code.h"
#include "scan/registration.h"
#include "scan_fixture.h"

using namespace epure;
using namespace epure::scan;
using namespace epure::scan::fixture;

namespace {

const std::string kSheet = SheetId{kDrawVersion, 5, 3}.str();

PageLayout page_with_ticks() {
  std::vector<FieldSpec> f;
  for (int i = 0; i < 8; ++i) f.push_back({"t" + std::to_string(i), FieldType::tick, 0, 0, false, {"true", "false"}, false});
  return lay_out_fields(f)[0];
}

// Where the map puts a layout point, against where it is on the undamaged page turned as the
// degradation turned it: at most `tolerance` points apart.
void check_map(const PageMap& map, const PageLayout& page, double dpi, const Degradation& d, const cv::Size& image) {
  const double s = dpi / 72;
  const int mx = static_cast<int>(std::lround(page.width * s) * 0.04), my = static_cast<int>(std::lround(page.height * s) * 0.03);
  cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(static_cast<float>(std::lround(page.width * s) / 2.0), static_cast<float>(std::lround(page.height * s) / 2.0)), d.rotate_deg, d.scale);
  for (const auto& f : page.fields)
    for (const auto& c : f.cells) {
      const double x = c.cx() * s, y = c.cy() * s;
      double ix = m.at<double>(0, 0) * x + m.at<double>(0, 1) * y + m.at<double>(0, 2) + d.shift_x * s + mx;
      double iy = m.at<double>(1, 0) * x + m.at<double>(1, 1) * y + m.at<double>(1, 2) + d.shift_y * s + my;
      if (d.upside_down) ix = image.width - 1 - ix, iy = image.height - 1 - iy;
      const Point p = map.to_image({c.cx(), c.cy()});
      CHECK(std::hypot(p.x - ix, p.y - iy) / s < 0.8);
    }
}

}  // namespace

TEST_CASE("registration: marks and code found at any skew, upside down, with a mark hidden") {
  const PageLayout page = page_with_ticks();
  const double dpi = 150;
  Rng rng(11);
  const cv::Mat clean = draw_page(page, page_code_text({kSheet, 1, 1}), {}, dpi, rng);
  struct Case {
    double angle;
    bool upside_down;
    int hide;  // a mark painted over (-1: none)
  };
  for (const Case c : {Case{0, false, -1}, Case{5, false, -1}, Case{-5, true, -1}, Case{2.5, true, 2}, Case{-3, false, 0}}) {
    CAPTURE(c.angle);
    CAPTURE(c.upside_down);
    CAPTURE(c.hide);
    cv::Mat drawn = clean.clone();
    if (c.hide >= 0) {
      const Point m = page.marks[static_cast<std::size_t>(c.hide)];
      const double s = dpi / 72, h = page.mark_size;
      cv::rectangle(drawn, cv::Point(static_cast<int>((m.x - h) * s), static_cast<int>((m.y - h) * s)),
                    cv::Point(static_cast<int>((m.x + h) * s), static_cast<int>((m.y + h) * s)), cv::Scalar(255), cv::FILLED);
    }
    Degradation d;
    d.rotate_deg = c.angle;
    d.upside_down = c.upside_down;
    d.scale = 1.02;
    d.shift_x = 5;
    d.shift_y = -4;
    const cv::Mat scan = degrade(drawn, d, dpi, rng);
    const PageFinding f = find_page(scan, frame_of(page));
    REQUIRE(f.code);
    CHECK(f.code->sheet == kSheet);
    REQUIRE(f.map);
    CHECK(f.marks == (c.hide >= 0 ? 3 : 4));
    CHECK(f.residual < kMaxResidual);
    check_map(*f.map, page, dpi, d, scan.size());
  }
}

TEST_CASE("registration: a code away from where the marks put it is reported, not read") {
  PageLayout page = page_with_ticks();
  Rng rng(12);
  PageLayout moved = page;
  moved.code.x -= 10;  // printed 10 pt left of where the layout says
  const cv::Mat scan = draw_page(moved, page_code_text({kSheet, 1, 1}), {}, 150, rng);
  // the reader looks where the layout says, half the code's side around it: the code is found
  // there, 10 pt off
  const PageFinding f = find_page(scan, frame_of(page));
  CHECK_FALSE(f.map);
  CHECK(f.problem.find("registration: the code lies") == 0);
}

TEST_CASE("registration: a blank page, and a page with no marks") {
  Rng rng(13);
  const PageLayout page = page_with_ticks();
  const cv::Mat blank(1754, 1240, CV_8UC1, cv::Scalar(250));
  const PageFinding b = find_page(blank, frame_of(page));
  CHECK(b.blank);
  cv::Mat text = blank.clone();
  cv::putText(text, "a page of something else", cv::Point(100, 300), cv::FONT_HERSHEY_SIMPLEX, 2, cv::Scalar(0), 3);
  const PageFinding t = find_page(text, frame_of(page));
  CHECK_FALSE(t.blank);
  CHECK_FALSE(t.map);
  CHECK(t.problem == "0 of the 4 corner marks found: 3 are needed");
}

TEST_CASE("ticks: a cross, a check mark, a light pen's cross read as ticked; a filled box as cancelled; a mark "
          "an eraser leaves or a box filled lightly never as ticked") {
  const PageLayout page = page_with_ticks();
  const double dpi = 200;
  Writing w;
  const TickStyle styles[] = {TickStyle::cross, TickStyle::check, TickStyle::erased, TickStyle::light_fill,
                              TickStyle::faint, TickStyle::cross, TickStyle::check, TickStyle::cross};
  for (int i = 0; i < 8; ++i) {
    const std::string q = "t" + std::to_string(i);
    w.ticks[q] = {i % 2 ? "false" : "true"};
    w.tick_style[q] = styles[i];
  }
  w.cancelled["t5"] = "true";  // ticked "true", then filled to cancel it, and "false" ticked
  int seen = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    CAPTURE(seed);
    Rng rng(seed);
    Degradation d;
    d.rotate_deg = rng.uniform(-5, 5);
    d.blur_sigma = 0.7;
    d.noise = 5;
    d.jpeg_quality = seed % 2 ? 50 : 0;
    d.bilevel = seed == 6;
    const cv::Mat scan = degrade(draw_page(page, page_code_text({kSheet, 1, 1}), w, dpi, rng), d, dpi, rng);
    const PageFinding f = find_page(scan, frame_of(page));
    REQUIRE(f.map);
    const double paper = paper_level(scan);
    for (int i = 0; i < 8; ++i) {
      CAPTURE(i);
      const FieldReading r = read_field(scan, *f.map, page.fields[static_cast<std::size_t>(i)], paper, f.ink, ".", DigitClassifier::builtin());
      if (styles[i] == TickStyle::light_fill && d.bilevel) {
        // Not pinned: a copier thresholding at the fill's own grey turns it into 60 % black
        // speckle over the whole box, sides included, which the reader takes for a tick: under
        // 70 % inked any mark is one, whatever its shape (asking a side's middle to be left white
        // there was tried: it sent "+" marks and circled boxes to review; README, Limits). A
        // student who cancels fills the box in the pen they ticked with.
        continue;
      }
      if (styles[i] == TickStyle::erased || styles[i] == TickStyle::light_fill) {
        // the student's intent is not clear from the ink: review or nothing, never a tick
        const TickReading& marked = r.ticks[static_cast<std::size_t>(i % 2)];
        CAPTURE(marked.light);
        CAPTURE(marked.filled);
        CAPTURE(marked.sides);
        CAPTURE(marked.light_sides);
        CHECK(marked.state != TickState::ticked);
        CHECK((r.uncertain || r.blank));
        continue;
      }
      if (styles[i] == TickStyle::faint && d.bilevel) {
        // a copier's threshold may break a light pen's strokes: read right or sent to review
        CHECK((r.uncertain || r.value == "true"));
        continue;
      }
      ++seen;
      CHECK_FALSE(r.uncertain);
      CHECK(r.value == (i % 2 ? "false" : "true"));
      if (i == 5) CHECK(r.ticks[0].state == TickState::cancelled);
    }
  }
  CHECK(seen == 35);
}
