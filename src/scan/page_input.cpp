#include "scan/page_input.h"

#include <fmt/format.h>
#include <jpeglib.h>
#include <png.h>
#include <tiffio.h>

#include <cmath>
#include <csetjmp>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "scan/pdf_input.h"
#include "support/png_size.h"

namespace epure::scan {

namespace {

void check_size(std::int64_t w, std::int64_t h, std::string_view what) {
  if (w <= 0 || h <= 0) throw ImageError(fmt::format("{} has no pixels", what));
  if (w * h > kMaxPagePixels)
    throw ImageError(fmt::format("{} of {} x {} pixels: a page holds at most {} pixels", what, w, h, kMaxPagePixels));
}

// libjpeg reports errors through a callback that must not return: it jumps back to the decoder.
struct JpegError {
  jpeg_error_mgr mgr;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void jpeg_error_exit(j_common_ptr cinfo) {
  auto* err = reinterpret_cast<JpegError*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, err->message);
  std::longjmp(err->jump, 1);
}
void jpeg_silent(j_common_ptr, int) {}

// Decodes into `out` (allocated once the size is known); returns an error message or nothing.
// No object with a destructor lives in this frame across the setjmp.
const char* jpeg_decode(const unsigned char* data, unsigned long size, cv::Mat* out, JpegError* err,
                        jpeg_decompress_struct* cinfo) {
  cinfo->err = jpeg_std_error(&err->mgr);
  err->mgr.error_exit = jpeg_error_exit;
  err->mgr.emit_message = jpeg_silent;
  if (setjmp(err->jump)) {
    jpeg_destroy_decompress(cinfo);
    return err->message;
  }
  jpeg_create_decompress(cinfo);
  jpeg_mem_src(cinfo, data, size);
  jpeg_read_header(cinfo, TRUE);
  cinfo->out_color_space = JCS_GRAYSCALE;
  if (static_cast<std::int64_t>(cinfo->image_width) * cinfo->image_height > kMaxPagePixels) {
    std::snprintf(err->message, sizeof err->message, "an image of %u x %u pixels: a page holds at most %lld",
                  cinfo->image_width, cinfo->image_height, static_cast<long long>(kMaxPagePixels));
    jpeg_destroy_decompress(cinfo);
    return err->message;
  }
  jpeg_start_decompress(cinfo);
  out->create(static_cast<int>(cinfo->output_height), static_cast<int>(cinfo->output_width), CV_8UC1);
  while (cinfo->output_scanline < cinfo->output_height) {
    JSAMPROW row = out->ptr<unsigned char>(static_cast<int>(cinfo->output_scanline));
    jpeg_read_scanlines(cinfo, &row, 1);
  }
  jpeg_finish_decompress(cinfo);
  jpeg_destroy_decompress(cinfo);
  return nullptr;
}

// --- TIFF, from memory or a file, one directory (page) at a time --------------------------------

struct MemoryFile {
  std::string bytes;
  toff_t at = 0;
};

tsize_t mem_read(thandle_t h, tdata_t buf, tsize_t size) {
  auto* m = static_cast<MemoryFile*>(h);
  const toff_t left = m->at < m->bytes.size() ? m->bytes.size() - m->at : 0;
  const toff_t n = std::min<toff_t>(left, static_cast<toff_t>(size));
  std::memcpy(buf, m->bytes.data() + m->at, n);
  m->at += n;
  return static_cast<tsize_t>(n);
}
tsize_t mem_write(thandle_t, tdata_t, tsize_t) { return -1; }
toff_t mem_seek(thandle_t h, toff_t off, int whence) {
  auto* m = static_cast<MemoryFile*>(h);
  toff_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? m->at : m->bytes.size();
  m->at = base + off;
  return m->at;
}
int mem_close(thandle_t) { return 0; }
toff_t mem_size(thandle_t h) { return static_cast<MemoryFile*>(h)->bytes.size(); }
int mem_map(thandle_t, tdata_t*, toff_t*) { return 0; }
void mem_unmap(thandle_t, tdata_t, toff_t) {}

thread_local std::string tiff_message;
int tiff_error(TIFF*, void*, const char* module, const char* fmt_, va_list ap) {
  char buf[512];
  std::vsnprintf(buf, sizeof buf, fmt_, ap);
  tiff_message = module ? fmt::format("{}: {}", module, buf) : buf;
  return 1;
}
int tiff_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

class TiffPages : public PageStream {
 public:
  TiffPages(std::string name, std::string bytes) : name_(std::move(name)) {
    mem_.bytes = std::move(bytes);
    TIFFOpenOptions* opts = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetMaxSingleMemAlloc(opts, 512 << 20);
    TIFFOpenOptionsSetErrorHandlerExtR(opts, tiff_error, nullptr);
    TIFFOpenOptionsSetWarningHandlerExtR(opts, tiff_warning, nullptr);
    tiff_message.clear();
    tif_ = TIFFClientOpenExt(name_.c_str(), "rm", &mem_, mem_read, mem_write, mem_seek, mem_close, mem_size,
                             mem_map, mem_unmap, opts);
    TIFFOpenOptionsFree(opts);
    if (!tif_) open_error_ = tiff_message.empty() ? "not a readable TIFF file" : tiff_message;
  }
  ~TiffPages() override {
    if (tif_) TIFFClose(tif_);
  }

  std::optional<InputPage> next() override {
    InputPage p{name_, page_ + 1, {}, {}, 0};
    if (!tif_) {
      if (done_) return std::nullopt;
      done_ = true;
      p.error = open_error_;
      return p;
    }
    if (done_) return std::nullopt;
    ++page_;
    if (page_ > kMaxTiffPages) {
      done_ = true;
      p.error = fmt::format("more than {} pages in one TIFF file: the rest is not read", kMaxTiffPages);
      return p;
    }
    try {
      p.image = read_directory(p.dpi);
    } catch (const ImageError& e) {
      p.error = e.what();
    }
    tiff_message.clear();
    if (!TIFFReadDirectory(tif_)) done_ = true;
    return p;
  }

 private:
  static constexpr int kMaxTiffPages = 10'000;

  cv::Mat read_directory(double& dpi) {
    std::uint32_t w = 0, h = 0;
    TIFFGetField(tif_, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(tif_, TIFFTAG_IMAGELENGTH, &h);
    check_size(w, h, "a TIFF page");
    float xres = 0;
    std::uint16_t unit = RESUNIT_INCH;
    if (TIFFGetField(tif_, TIFFTAG_XRESOLUTION, &xres) && xres > 0) {
      TIFFGetFieldDefaulted(tif_, TIFFTAG_RESOLUTIONUNIT, &unit);
      dpi = unit == RESUNIT_CENTIMETER ? xres * 2.54 : xres;
    }
    std::vector<std::uint32_t> rgba(static_cast<std::size_t>(w) * h);
    tiff_message.clear();
    if (!TIFFReadRGBAImageOriented(tif_, w, h, rgba.data(), ORIENTATION_TOPLEFT, 0))
      throw ImageError(tiff_message.empty() ? "a TIFF page that cannot be decoded" : tiff_message);
    cv::Mat out(static_cast<int>(h), static_cast<int>(w), CV_8UC1);
    for (std::uint32_t y = 0; y < h; ++y) {
      unsigned char* row = out.ptr<unsigned char>(static_cast<int>(y));
      const std::uint32_t* src = rgba.data() + static_cast<std::size_t>(y) * w;
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::uint32_t v = src[x];
        // ITU-R BT.601 luma, in integers: (77 R + 150 G + 29 B) / 256
        row[x] = static_cast<unsigned char>((77 * TIFFGetR(v) + 150 * TIFFGetG(v) + 29 * TIFFGetB(v)) >> 8);
      }
    }
    return out;
  }

  std::string name_;
  MemoryFile mem_;
  TIFF* tif_ = nullptr;
  std::string open_error_;
  int page_ = 0;
  bool done_ = false;
};

// One page: a PNG or JPEG file, or a file that cannot be read.
class SinglePage : public PageStream {
 public:
  explicit SinglePage(InputPage page) : page_(std::move(page)) {}
  std::optional<InputPage> next() override {
    if (done_) return std::nullopt;
    done_ = true;
    return std::move(page_);
  }

 private:
  InputPage page_;
  bool done_ = false;
};

std::unique_ptr<PageStream> single(const std::string& name, FileKind kind, const std::string& bytes) {
  InputPage p{name, 1, {}, {}, 0};
  try {
    p.image = kind == FileKind::png ? decode_png(bytes) : decode_jpeg(bytes);
  } catch (const ImageError& e) {
    p.error = e.what();
  }
  return std::make_unique<SinglePage>(std::move(p));
}

std::string head_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char buf[8] = {};
  in.read(buf, sizeof buf);
  return std::string(buf, static_cast<std::size_t>(in.gcount()));
}

std::optional<std::string> read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::unique_ptr<PageStream> by_kind(FileKind kind, const std::string& name, std::string bytes, int dpi) {
  switch (kind) {
    case FileKind::pdf: return open_pdf_pages_in_memory(std::move(bytes), name, dpi);
    case FileKind::tiff: return std::make_unique<TiffPages>(name, std::move(bytes));
    case FileKind::png:
    case FileKind::jpeg: return single(name, kind, bytes);
    case FileKind::unknown: break;
  }
  return std::make_unique<SinglePage>(InputPage{name, 1, {}, "not a PDF, PNG, JPEG or TIFF file", 0});
}

}  // namespace

FileKind sniff_file_kind(std::string_view head) {
  if (head.substr(0, 5) == "%PDF-") return FileKind::pdf;
  if (head.substr(0, 8) == "\x89PNG\r\n\x1a\n") return FileKind::png;
  if (head.substr(0, 3) == "\xFF\xD8\xFF") return FileKind::jpeg;
  if (head.substr(0, 4) == std::string_view("II*\0", 4) || head.substr(0, 4) == std::string_view("MM\0*", 4) ||
      head.substr(0, 4) == std::string_view("II+\0", 4) || head.substr(0, 4) == std::string_view("MM\0+", 4))
    return FileKind::tiff;
  return FileKind::unknown;
}

cv::Mat decode_png(std::string_view bytes) {
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&img, bytes.data(), bytes.size()))
    throw ImageError(fmt::format("not a readable PNG file: {}", img.message));
  try {
    check_size(img.width, img.height, "a PNG image");
  } catch (...) {
    png_image_free(&img);
    throw;
  }
  img.format = PNG_FORMAT_GRAY;  // libpng converts every colour type and depth (and composes alpha on white)
  cv::Mat out(static_cast<int>(img.height), static_cast<int>(img.width), CV_8UC1);
  png_color white{255, 255, 255};
  if (!png_image_finish_read(&img, &white, out.data, static_cast<png_int_32>(out.step[0]), nullptr)) {
    std::string msg = img.message;
    png_image_free(&img);
    throw ImageError(fmt::format("a PNG file that cannot be decoded: {}", msg));
  }
  return out;
}

cv::Mat decode_jpeg(std::string_view bytes) {
  cv::Mat out;
  JpegError err;
  jpeg_decompress_struct cinfo;
  if (const char* msg = jpeg_decode(reinterpret_cast<const unsigned char*>(bytes.data()),
                                    static_cast<unsigned long>(bytes.size()), &out, &err, &cinfo))
    throw ImageError(fmt::format("a JPEG image that cannot be decoded: {}", msg));
  return out;
}

std::unique_ptr<PageStream> open_pages(const std::string& path, int render_dpi) {
  const std::string head = head_of(path);
  const FileKind kind = sniff_file_kind(head);
  if (kind == FileKind::pdf) return open_pdf_pages(path, render_dpi);  // qpdf and poppler read the file lazily
  auto bytes = read_all(path);
  if (!bytes) return std::make_unique<SinglePage>(InputPage{path, 1, {}, "cannot be read (no such file, or no permission)", 0});
  return by_kind(kind, path, std::move(*bytes), render_dpi);
}

std::unique_ptr<PageStream> open_pages_in_memory(std::string bytes, const std::string& name, int render_dpi) {
  const FileKind kind = sniff_file_kind(std::string_view(bytes).substr(0, 8));
  return by_kind(kind, name, std::move(bytes), render_dpi);
}

namespace {

// PNG's chunk CRC (ISO 3309, the one zlib computes), bit by bit: a chunk of 13 bytes a crop.
std::uint32_t png_crc(std::string_view bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (const char ch : bytes) {
    c ^= static_cast<unsigned char>(ch);
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xFFFFFFFFu;
}

void put_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((v >> shift) & 0xFF));
}

// The pHYs chunk for a resolution: pixels per metre on both axes, unit 1 (the metre).
std::string phys_chunk(double dots_per_inch) {
  const auto per_metre = static_cast<std::uint32_t>(std::lround(dots_per_inch / kMetresPerInch));
  std::string body = "pHYs";
  put_u32(body, per_metre);
  put_u32(body, per_metre);
  body.push_back('\x01');
  std::string chunk;
  put_u32(chunk, 9);
  chunk += body;
  put_u32(chunk, png_crc(body));
  return chunk;
}

}  // namespace

std::string encode_png(const cv::Mat& grey, double dots_per_inch) {
  CV_Assert(grey.type() == CV_8UC1);
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  img.width = static_cast<png_uint_32>(grey.cols);
  img.height = static_cast<png_uint_32>(grey.rows);
  img.format = PNG_FORMAT_GRAY;
  png_alloc_size_t size = 0;
  const auto stride = static_cast<png_int_32>(grey.step[0]);
  if (!png_image_write_to_memory(&img, nullptr, &size, 0, grey.data, stride, nullptr))
    throw ImageError(fmt::format("PNG: {}", img.message));
  std::string out(size, '\0');
  if (!png_image_write_to_memory(&img, out.data(), &size, 0, grey.data, stride, nullptr))
    throw ImageError(fmt::format("PNG: {}", img.message));
  out.resize(size);
  // pHYs goes after IHDR (the signature and IHDR are the first 33 bytes) and before IDAT
  if (dots_per_inch > 0) out.insert(8 + 8 + 13 + 4, phys_chunk(dots_per_inch));
  return out;
}

std::string encode_jpeg(const cv::Mat& grey, int quality) {
  CV_Assert(grey.type() == CV_8UC1);
  jpeg_compress_struct cinfo;
  jpeg_error_mgr err;
  cinfo.err = jpeg_std_error(&err);  // our own images: an error here is a bug, libjpeg exits
  jpeg_create_compress(&cinfo);
  unsigned char* mem = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&cinfo, &mem, &size);
  cinfo.image_width = static_cast<JDIMENSION>(grey.cols);
  cinfo.image_height = static_cast<JDIMENSION>(grey.rows);
  cinfo.input_components = 1;
  cinfo.in_color_space = JCS_GRAYSCALE;
  jpeg_set_defaults(&cinfo);
  jpeg_set_quality(&cinfo, quality, TRUE);
  jpeg_start_compress(&cinfo, TRUE);
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row = const_cast<unsigned char*>(grey.ptr<unsigned char>(static_cast<int>(cinfo.next_scanline)));
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  std::string out(reinterpret_cast<char*>(mem), size);
  jpeg_destroy_compress(&cinfo);
  std::free(mem);
  return out;
}

}  // namespace epure::scan
