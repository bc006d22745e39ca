#pragma once
// Where a scanned page lies in its image. The page's four corner marks (solid squares) are
// found in a reduced copy of the image; each hypothesis of orientation (upright, 180°, then the
// quarter turns) maps the page onto them (four marks: a homography, so that a phone photo's
// perspective is undone; three, one hidden by a staple: an affine map), and the page code is
// decoded where that map puts it. The hypothesis whose code decodes is the page's orientation;
// the code's four corners, measured, are then a check of the map away from the marks: when they
// lie further than kMaxResidual from where the map puts them, the page is reported, not read.
#include <opencv2/core.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "scan/layout_file.h"
#include "exercises/page_code.h"

namespace epure::scan {

// From page points (y down from the top-left corner) to image pixels.
struct PageMap {
  cv::Matx33d h = cv::Matx33d::eye();
  Point to_image(Point p) const {
    const double w = h(2, 0) * p.x + h(2, 1) * p.y + h(2, 2);
    return {(h(0, 0) * p.x + h(0, 1) * p.y + h(0, 2)) / w, (h(1, 0) * p.x + h(1, 1) * p.y + h(1, 2)) / w};
  }
  // Image pixels per page point near p (the square root of the local area scale).
  double scale_at(Point p) const;
};

// Where the marks and the code are on every page of the set (the layout's first page: the
// furniture is the same on every page).
struct PageFrame {
  double width = 595.276, height = 841.89;
  std::array<Point, 4> marks;
  double mark_size = 14;
  Rect code;  // the code's modules, without the quiet zone
};
PageFrame frame_of(const PageLayout& page);

// Past this distance between where the code's corners are measured and where the marks' map
// puts them, a page is not read: its marks or its code were taken from something else.
inline constexpr double kMaxResidual = 4.0;  // points (1.4 mm)

struct PageFinding {
  std::optional<PageCode> code;  // the page code, when one was read and checks
  std::string code_text;         // what the code said, even when it is no page code
  std::optional<PageMap> map;    // set when the page is registered
  int marks = 0;                 // marks found (3 or 4 register a page)
  double residual = 0;           // points
  double ink = -1;               // the grey level of the marks' ink (full ink on this page), -1 unknown
  bool blank = false;            // no mark, no code and almost no ink
  std::string problem;           // why the page is not registered, for pages.csv
};

PageFinding find_page(const cv::Mat& grey, const PageFrame& frame);

// The code alone, anywhere on the page (a page whose marks cannot be found is still identified).
std::optional<std::string> read_any_code(const cv::Mat& grey);

// The map fitted to corresponding points (page → image): a homography from four or more, an
// affine map from three; nothing from fewer or from points in a line.
std::optional<PageMap> fit_map(const std::vector<Point>& page, const std::vector<Point>& image);

}  // namespace epure::scan
