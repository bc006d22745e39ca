#include "scan/registration.h"

#include <ZXing/ReadBarcode.h>
#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace epure::scan {

namespace {

struct Candidate {
  Point centre;  // full-resolution pixels
  double side = 0;
};

// A dark, solid, squarish blob of about the mark's size.
std::vector<Candidate> mark_candidates(const cv::Mat& small, double factor, double expected_side) {
  cv::Mat bin, labels, stats, centroids;
  cv::threshold(small, bin, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
  const int n = cv::connectedComponentsWithStats(bin, labels, stats, centroids, 8, CV_32S);
  std::vector<Candidate> out;
  const double s = expected_side;
  for (int i = 1; i < n; ++i) {
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    if (w < 0.7 * s || h < 0.7 * s || w > 1.6 * s || h > 1.6 * s) continue;
    if (area < 0.6 * s * s || area > 1.6 * s * s) continue;
    if (std::max(w, h) > 1.45 * std::min(w, h)) continue;
    // solid: its area fills its smallest enclosing rotated rectangle
    std::vector<cv::Point> pts;
    const int x0 = stats.at<int>(i, cv::CC_STAT_LEFT), y0 = stats.at<int>(i, cv::CC_STAT_TOP);
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x)
        if (labels.at<int>(y, x) == i) pts.emplace_back(x, y);
    const cv::RotatedRect rr = cv::minAreaRect(pts);
    const double rect_area = (rr.size.width + 1) * (rr.size.height + 1);
    if (area < 0.8 * rect_area) continue;
    if (std::max(rr.size.width, rr.size.height) > 1.3 * std::min(rr.size.width, rr.size.height) + 1) continue;
    out.push_back({{(centroids.at<double>(i, 0) + 0.5) * factor - 0.5, (centroids.at<double>(i, 1) + 0.5) * factor - 0.5},
                   std::sqrt(static_cast<double>(area)) * factor});
  }
  return out;
}

// The centre of the dark square around `c`, at full resolution: the centroid of the ink darker
// than halfway between the window's darkest and lightest pixels. `ink`: the mean grey level of
// that ink.
Point refine(const cv::Mat& grey, Point c, double side, double& ink) {
  const int r = static_cast<int>(std::ceil(side * 0.9));
  const cv::Rect win = cv::Rect(static_cast<int>(c.x) - r, static_cast<int>(c.y) - r, 2 * r + 1, 2 * r + 1) &
                       cv::Rect(0, 0, grey.cols, grey.rows);
  if (win.area() == 0) return c;
  const cv::Mat w = grey(win);
  double lo, hi;
  cv::minMaxLoc(w, &lo, &hi);
  const double mid = (lo + hi) / 2;
  double sx = 0, sy = 0, sw = 0, sum = 0;
  int n = 0;
  for (int y = 0; y < w.rows; ++y) {
    const unsigned char* row = w.ptr<unsigned char>(y);
    for (int x = 0; x < w.cols; ++x)
      if (row[x] < mid) {
        const double wt = mid - row[x];
        sx += wt * x;
        sy += wt * y;
        sw += wt;
        sum += row[x];
        ++n;
      }
  }
  if (sw <= 0) return c;
  ink = sum / n;
  return {win.x + sx / sw, win.y + sy / sw};
}

std::optional<ZXing::Result> decode_qr(const cv::Mat& img) {
  ZXing::DecodeHints hints;
  hints.setFormats(ZXing::BarcodeFormat::QRCode);
  hints.setTryRotate(true);
  hints.setTryHarder(true);
  hints.setTryDownscale(false);
  auto r = ZXing::ReadBarcode(ZXing::ImageView(img.data, img.cols, img.rows, ZXing::ImageFormat::Lum, static_cast<int>(img.step[0])), hints);
  if (!r.isValid()) return std::nullopt;
  return r;
}

constexpr double kCodeCropScale = 4.0;  // crop pixels per page point: a 1.3 pt module is 5 pixels

// The page code where `map` puts it, and the check of the map there: nothing when no code
// reads there upright; a finding without a map when the code is too far from where the map
// puts it. The crop is taken at 4 pixels a point (`second_look` false); find_page looks again,
// once no orientation read, at the scan's own resolution, then 3 and 6 pixels a point: a blurred
// 150 dpi copy, whose smeared modules the upsampling smears further, reads at one of them (7 of
// 72 such pages failed at 4 alone, none with them).
std::optional<PageFinding> read_code_at(const cv::Mat& grey, const PageFrame& frame, const PageMap& map, bool second_look) {
  const double margin = frame.code.width * 0.5;
  const Rect area{frame.code.x - margin, frame.code.y - margin, frame.code.width + 2 * margin, frame.code.height + 2 * margin};
  const double native = map.scale_at({frame.code.x + frame.code.width / 2, frame.code.y + frame.code.height / 2});
  std::vector<double> scales{kCodeCropScale};
  if (second_look) {
    scales.clear();
    for (const double scale : {native, 3.0, 6.0})
      if (scale >= 1 && std::abs(scale - kCodeCropScale) >= 0.5 &&
          std::none_of(scales.begin(), scales.end(), [&](double t) { return std::abs(scale - t) < 0.5; }))
        scales.push_back(scale);
  }
  std::optional<ZXing::Result> r;
  double s = kCodeCropScale;
  for (const double scale : scales) {
    s = scale;
    // crop pixel (u, v) is page point (area.x + u / s, area.y + v / s)
    const cv::Matx33d crop_to_page(1 / s, 0, area.x, 0, 1 / s, area.y, 0, 0, 1);
    cv::Mat crop;
    cv::warpPerspective(grey, crop, map.h * crop_to_page,
                        cv::Size(static_cast<int>(area.width * s), static_cast<int>(area.height * s)),
                        cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar(255));
    r = decode_qr(crop);
    if (r) break;
  }
  if (!r) return std::nullopt;
  const auto pos = r->position();
  if (!(pos.topLeft().x < pos.bottomRight().x && pos.topLeft().y < pos.bottomRight().y)) return std::nullopt;
  PageFinding out;
  out.code_text = r->text();
  out.code = parse_page_code(out.code_text);
  // the residual: the code's corners as measured against the layout's
  const Point expected[4] = {{frame.code.x, frame.code.y},
                             {frame.code.x + frame.code.width, frame.code.y},
                             {frame.code.x + frame.code.width, frame.code.y + frame.code.height},
                             {frame.code.x, frame.code.y + frame.code.height}};
  const ZXing::PointI measured[4] = {pos.topLeft(), pos.topRight(), pos.bottomRight(), pos.bottomLeft()};
  for (int i = 0; i < 4; ++i) {
    const Point m{area.x + (measured[i].x + 0.5) / s, area.y + (measured[i].y + 0.5) / s};
    out.residual = std::max(out.residual, std::hypot(m.x - expected[i].x, m.y - expected[i].y));
  }
  if (out.residual > kMaxResidual)
    out.problem = fmt::format("registration: the code lies {:.1f} pt from where the marks put it (at most {})", out.residual, kMaxResidual);
  else
    out.map = map;
  return out;
}

}  // namespace

double PageMap::scale_at(Point p) const {
  const Point a = to_image(p), b = to_image({p.x + 1, p.y}), c = to_image({p.x, p.y + 1});
  const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return std::sqrt(std::abs(cross));
}

PageFrame frame_of(const PageLayout& page) {
  return {page.width, page.height, page.marks, page.mark_size, page.code};
}

std::optional<PageMap> fit_map(const std::vector<Point>& page, const std::vector<Point>& image) {
  const std::size_t n = page.size();
  if (n < 3 || image.size() != n) return std::nullopt;
  // Hartley's normalisation: both point sets centred and scaled to a mean distance of √2
  auto normaliser = [](const std::vector<Point>& pts) {
    double mx = 0, my = 0;
    for (auto p : pts) mx += p.x, my += p.y;
    mx /= static_cast<double>(pts.size());
    my /= static_cast<double>(pts.size());
    double d = 0;
    for (auto p : pts) d += std::hypot(p.x - mx, p.y - my);
    d /= static_cast<double>(pts.size());
    const double s = d > 0 ? std::sqrt(2.0) / d : 1;
    return cv::Matx33d(s, 0, -s * mx, 0, s, -s * my, 0, 0, 1);
  };
  const cv::Matx33d tp = normaliser(page), ti = normaliser(image);
  auto apply = [](const cv::Matx33d& t, Point p) { return Point{t(0, 0) * p.x + t(0, 2), t(1, 1) * p.y + t(1, 2)}; };
  cv::Matx33d hn;
  if (n == 3) {
    // affine: x' = a x + b y + c, y' = d x + e y + f
    cv::Mat A = cv::Mat::zeros(6, 6, CV_64F), b(6, 1, CV_64F);
    for (int i = 0; i < 3; ++i) {
      const Point p = apply(tp, page[static_cast<std::size_t>(i)]), q = apply(ti, image[static_cast<std::size_t>(i)]);
      A.at<double>(2 * i, 0) = p.x, A.at<double>(2 * i, 1) = p.y, A.at<double>(2 * i, 2) = 1;
      A.at<double>(2 * i + 1, 3) = p.x, A.at<double>(2 * i + 1, 4) = p.y, A.at<double>(2 * i + 1, 5) = 1;
      b.at<double>(2 * i) = q.x, b.at<double>(2 * i + 1) = q.y;
    }
    cv::Mat x;
    if (!cv::solve(A, b, x, cv::DECOMP_LU)) return std::nullopt;
    hn = cv::Matx33d(x.at<double>(0), x.at<double>(1), x.at<double>(2), x.at<double>(3), x.at<double>(4), x.at<double>(5), 0, 0, 1);
  } else {
    // homography with h33 = 1, least squares over every correspondence
    cv::Mat A(static_cast<int>(2 * n), 8, CV_64F), b(static_cast<int>(2 * n), 1, CV_64F);
    for (std::size_t i = 0; i < n; ++i) {
      const Point p = apply(tp, page[i]), q = apply(ti, image[i]);
      const int r = static_cast<int>(2 * i);
      double* a0 = A.ptr<double>(r);
      double* a1 = A.ptr<double>(r + 1);
      a0[0] = p.x, a0[1] = p.y, a0[2] = 1, a0[3] = 0, a0[4] = 0, a0[5] = 0, a0[6] = -p.x * q.x, a0[7] = -p.y * q.x;
      a1[0] = 0, a1[1] = 0, a1[2] = 0, a1[3] = p.x, a1[4] = p.y, a1[5] = 1, a1[6] = -p.x * q.y, a1[7] = -p.y * q.y;
      b.at<double>(r) = q.x, b.at<double>(r + 1) = q.y;
    }
    cv::Mat x;
    if (!cv::solve(A, b, x, n == 4 ? cv::DECOMP_LU : cv::DECOMP_SVD)) return std::nullopt;
    hn = cv::Matx33d(x.at<double>(0), x.at<double>(1), x.at<double>(2), x.at<double>(3), x.at<double>(4), x.at<double>(5),
                     x.at<double>(6), x.at<double>(7), 1);
  }
  PageMap m;
  m.h = ti.inv() * hn * tp;
  if (!std::isfinite(m.h(2, 2)) || std::abs(m.h(2, 2)) < 1e-12) return std::nullopt;
  m.h *= 1.0 / m.h(2, 2);
  return m;
}

std::optional<std::string> read_any_code(const cv::Mat& grey) {
  auto r = decode_qr(grey);
  if (!r) return std::nullopt;
  return r->text();
}

PageFinding find_page(const cv::Mat& grey, const PageFrame& frame) {
  PageFinding out;
  // pixels per point, from the image's size: either way round (a page scanned landscape)
  const double long_px = std::max(grey.cols, grey.rows), long_pt = std::max(frame.width, frame.height);
  const double scale = long_px / long_pt;
  // work on a copy of about 1 pixel per point (72 dpi): a 14 pt mark is 14 pixels there
  const int factor = std::max(1, static_cast<int>(std::floor(scale)));
  cv::Mat small;
  if (factor > 1) cv::resize(grey, small, cv::Size(grey.cols / factor, grey.rows / factor), 0, 0, cv::INTER_AREA);
  else small = grey;
  const double side = frame.mark_size * scale / factor;
  auto candidates = mark_candidates(small, factor, side);

  // Each corner of the image takes the candidate nearest to it, if near enough.
  const std::array<Point, 4> corners{{{0, 0}, {static_cast<double>(grey.cols), 0},
                                      {static_cast<double>(grey.cols), static_cast<double>(grey.rows)},
                                      {0, static_cast<double>(grey.rows)}}};
  const double reach = 0.25 * std::hypot(grey.cols, grey.rows);
  std::array<std::optional<Point>, 4> found;
  std::vector<double> inks;
  std::vector<bool> used(candidates.size(), false);
  for (int c = 0; c < 4; ++c) {
    double best = reach;
    int pick = -1;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (used[i]) continue;
      const double d = std::hypot(candidates[i].centre.x - corners[static_cast<std::size_t>(c)].x,
                                  candidates[i].centre.y - corners[static_cast<std::size_t>(c)].y);
      if (d < best) best = d, pick = static_cast<int>(i);
    }
    if (pick >= 0) {
      used[static_cast<std::size_t>(pick)] = true;
      double ink = -1;
      found[static_cast<std::size_t>(c)] = refine(grey, candidates[static_cast<std::size_t>(pick)].centre,
                                                  candidates[static_cast<std::size_t>(pick)].side, ink);
      if (ink >= 0) inks.push_back(ink);
      ++out.marks;
    }
  }

  if (out.marks < 3) {
    cv::Mat bin;
    const double ink = static_cast<double>(cv::countNonZero(small < 128)) / static_cast<double>(small.total());
    auto any = read_any_code(grey);
    if (any) {
      out.code_text = *any;
      out.code = parse_page_code(*any);
    }
    out.blank = !any && out.marks == 0 && ink < 0.002;
    out.problem = out.blank ? "blank" : fmt::format("{} of the 4 corner marks found: 3 are needed", out.marks);
    return out;
  }

  // Orientation: the page's mark k sits at image corner (k + turn) % 4. Upright and upside down
  // first, or the quarter turns first when the image is landscape and the page is not. With
  // four marks whose map misplaces the code (a blob taken for a hidden mark), each three of them
  // are tried. All of it at the code's first look, then at its second (read_code_at).
  const bool turned = (grey.cols > grey.rows) != (frame.width > frame.height);
  const int order[4] = {turned ? 1 : 0, turned ? 3 : 2, turned ? 0 : 1, turned ? 2 : 3};
  std::vector<int> skips{-1};
  if (out.marks == 4) skips.insert(skips.end(), {0, 1, 2, 3});
  std::optional<PageFinding> rejected;
  for (bool second_look : {false, true}) {
    for (int skip : skips) {
      for (int turn : order) {
        std::vector<Point> page_pts, image_pts;
        for (int k = 0; k < 4; ++k) {
          const int corner = (k + turn) % 4;
          const auto& m = found[static_cast<std::size_t>(corner)];
          if (!m || corner == skip) continue;
          page_pts.push_back(frame.marks[static_cast<std::size_t>(k)]);
          image_pts.push_back(*m);
        }
        auto map = fit_map(page_pts, image_pts);
        if (!map) continue;
        auto attempt = read_code_at(grey, frame, *map, second_look);
        if (!attempt) continue;
        attempt->marks = static_cast<int>(page_pts.size());
        if (!inks.empty()) {
          std::sort(inks.begin(), inks.end());
          attempt->ink = inks[inks.size() / 2];
        }
        if (attempt->map) return *attempt;
        if (!rejected) rejected = attempt;
      }
    }
  }
  if (rejected) return *rejected;
  // No orientation shows a code where the marks say: identify the page from its code alone.
  if (auto any = read_any_code(grey)) {
    out.code_text = *any;
    out.code = parse_page_code(*any);
  }
  out.problem = out.code ? "registration: the code is not where the marks put it" : "no page code found";
  return out;
}

}  // namespace epure::scan
