#pragma once
// The pages of the files a teacher scans: PDF (a scanner's or a copier's: one image per page, or
// anything else, rendered), PNG, JPEG, multi-page TIFF. Each page becomes a grey image; a page
// that cannot be read becomes an error that names the file and the page, and the reading goes
// on with the next page or file. Pages come one at a time, so that a stack of 1,000 pages is
// never held whole.
//
// Libraries (Debian's): libpng's simplified API, libjpeg(-turbo), libtiff; for PDF, qpdf (already
// epure's, for the keys' links) takes a page's one embedded image as it is where there is one
// (a scanner's JPEG, Flate or raw pixels: no rendering, 5 to 20 times faster), and poppler-cpp
// renders every other page. OpenCV's imgcodecs would bring GDAL and about 45 packages with it
// for the same three formats.
#include <opencv2/core.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace epure::scan {

struct InputPage {
  std::string file;
  int page = 1;       // 1-based, in the file
  cv::Mat image;      // CV_8UC1, empty when `error` says why
  std::string error;  // "not a PNG file: …", empty when read
  double dpi = 0;     // as the file says (0: unknown)
};

// A page image larger than this is refused (a 600 dpi A3 page is 70 M pixels).
inline constexpr std::int64_t kMaxPagePixels = 120'000'000;

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class FileKind { pdf, png, jpeg, tiff, unknown };
FileKind sniff_file_kind(std::string_view head);

// Single images from memory (throw ImageError).
cv::Mat decode_png(std::string_view bytes);
cv::Mat decode_jpeg(std::string_view bytes);

// Every page of an input, one at a time.
class PageStream {
 public:
  virtual ~PageStream() = default;
  // The next page (its image or its error), or nothing past the last.
  virtual std::optional<InputPage> next() = 0;
};

// A file on disk by its kind (read from its first bytes, not its name). A file that cannot be
// opened or is of no known kind gives one page with the error. `render_dpi` is the resolution
// at which PDF pages without one embedded image are rendered.
std::unique_ptr<PageStream> open_pages(const std::string& path, int render_dpi = 200);
// The same from bytes in memory (the fuzz targets); `name` for messages.
std::unique_ptr<PageStream> open_pages_in_memory(std::string bytes, const std::string& name, int render_dpi = 200);

// A grey image as PNG bytes (review crops, test fixtures). With `dots_per_inch` > 0 the file
// says its resolution (a pHYs chunk), so that a reader sizes it on paper as it was scanned.
std::string encode_png(const cv::Mat& grey, double dots_per_inch = 0);
// A grey image as JPEG bytes at a quality from 1 to 100 (test fixtures: a copier's JPEG).
std::string encode_jpeg(const cv::Mat& grey, int quality);

}  // namespace epure::scan
