#include "scan/pdf_input.h"

#include <fmt/format.h>
#include <poppler/cpp/poppler-document.h>
#include <poppler/cpp/poppler-global.h>
#include <poppler/cpp/poppler-image.h>
#include <poppler/cpp/poppler-page-renderer.h>
#include <poppler/cpp/poppler-page.h>
#include <qpdf/Buffer.hh>
#include <qpdf/QPDF.hh>
#include <qpdf/QPDFPageDocumentHelper.hh>
#include <qpdf/QPDFPageObjectHelper.hh>

#include <cmath>
#include <cstring>
#include <mutex>

namespace epure::scan {

namespace {

void quiet_poppler(const std::string&, void*) {}

// A page's one image, decoded, or an empty Mat when the page is not a plain scanned image (no
// image, several, an image that does not fill the page, or an encoding qpdf cannot undo: CCITT
// fax, JBIG2, JPEG 2000, indexed colours): poppler renders those.
cv::Mat embedded_image(QPDFPageObjectHelper& page) {
  auto images = page.getImages();
  if (images.size() != 1) return {};
  QPDFObjectHandle image = images.begin()->second;
  QPDFObjectHandle dict = image.getDict();
  auto integer = [&](const char* key) -> long long {
    auto v = dict.getKey(key);
    return v.isInteger() ? v.getIntValue() : -1;
  };
  const long long w = integer("/Width"), h = integer("/Height"), bpc = integer("/BitsPerComponent");
  if (w <= 0 || h <= 0 || w * h > kMaxPagePixels) return {};
  // the image must have the page's shape (either way round: a page may be turned by /Rotate)
  auto box = page.getMediaBox().getArrayAsRectangle();
  const double pw = std::abs(box.urx - box.llx), ph = std::abs(box.ury - box.lly);
  if (pw <= 0 || ph <= 0) return {};
  const double ratio = static_cast<double>(w) / static_cast<double>(h);
  if (std::abs(ratio / (pw / ph) - 1) > 0.03 && std::abs(ratio / (ph / pw) - 1) > 0.03) return {};
  if (dict.getKey("/ImageMask").isBool() && dict.getKey("/ImageMask").getBoolValue()) return {};
  QPDFObjectHandle filter = dict.getKey("/Filter");
  if (filter.isArray() && filter.getArrayNItems() == 1) filter = filter.getArrayItem(0);
  if (filter.isName() && filter.getName() == "/DCTDecode") {
    auto raw = image.getRawStreamData();
    try {
      cv::Mat m = decode_jpeg(std::string_view(reinterpret_cast<const char*>(raw->getBuffer()), raw->getSize()));
      if (m.cols == w && m.rows == h) return m;
    } catch (const ImageError&) {
    }
    return {};
  }
  if (!filter.isNull() && !(filter.isName() && filter.getName() == "/FlateDecode")) return {};
  QPDFObjectHandle cs = dict.getKey("/ColorSpace");
  int components = 0;
  if (cs.isName() && cs.getName() == "/DeviceGray") components = 1;
  else if (cs.isName() && cs.getName() == "/DeviceRGB") components = 3;
  else return {};
  if (!(bpc == 8 || (bpc == 1 && components == 1))) return {};
  if (!dict.getKey("/DecodeParms").isNull() && !dict.getKey("/DecodeParms").isDictionary()) return {};
  std::shared_ptr<Buffer> data;
  try {
    data = image.getStreamData(qpdf_dl_generalized);
  } catch (const std::exception&) {
    return {};
  }
  const std::size_t row = bpc == 1 ? static_cast<std::size_t>((w + 7) / 8) : static_cast<std::size_t>(w * components);
  if (data->getSize() < row * static_cast<std::size_t>(h)) return {};
  // /Decode [1 0] inverts (a bilevel scan written with 1 = black)
  bool invert = false;
  if (auto d = dict.getKey("/Decode"); d.isArray() && d.getArrayNItems() >= 2 && d.getArrayItem(0).isNumber())
    invert = d.getArrayItem(0).getNumericValue() > 0.5;
  cv::Mat out(static_cast<int>(h), static_cast<int>(w), CV_8UC1);
  const unsigned char* src = data->getBuffer();
  for (int y = 0; y < out.rows; ++y) {
    const unsigned char* s = src + static_cast<std::size_t>(y) * row;
    unsigned char* d = out.ptr<unsigned char>(y);
    for (int x = 0; x < out.cols; ++x) {
      unsigned char v;
      if (bpc == 1) v = (s[x >> 3] >> (7 - (x & 7))) & 1 ? 255 : 0;
      else if (components == 1) v = s[x];
      else v = static_cast<unsigned char>((77 * s[3 * x] + 150 * s[3 * x + 1] + 29 * s[3 * x + 2]) >> 8);
      d[x] = invert ? static_cast<unsigned char>(255 - v) : v;
    }
  }
  return out;
}

class PdfPages : public PageStream {
 public:
  PdfPages(std::string name, std::string bytes, bool in_memory, int dpi) : name_(std::move(name)), bytes_(std::move(bytes)), dpi_(dpi) {
    static std::once_flag quiet;
    std::call_once(quiet, [] { poppler::set_debug_error_function(quiet_poppler, nullptr); });
    try {
      qpdf_.setSuppressWarnings(true);
      qpdf_.setAttemptRecovery(true);
      if (in_memory) qpdf_.processMemoryFile(name_.c_str(), bytes_.data(), bytes_.size());
      else qpdf_.processFile(name_.c_str());
      pages_ = QPDFPageDocumentHelper(qpdf_).getAllPages();
      if (pages_.size() > kMaxPdfPages) pages_.erase(pages_.begin() + kMaxPdfPages, pages_.end());
      qpdf_ok_ = true;
    } catch (const std::exception& e) {
      qpdf_error_ = e.what();
    }
  }

  std::optional<InputPage> next() override {
    if (finished_) return std::nullopt;
    InputPage p{name_, index_ + 1, {}, {}, 0};
    if (!qpdf_ok_) {
      // qpdf could not read it: perhaps poppler can; otherwise the file is one unreadable page
      if (!poppler_tried_) open_poppler();
      if (!doc_) {
        finished_ = true;
        p.error = fmt::format("not a readable PDF file: {}", qpdf_error_);
        return p;
      }
      if (index_ >= doc_->pages()) {
        finished_ = true;
        if (index_ > 0) return std::nullopt;
        p.error = fmt::format("a PDF file with no page (qpdf: {})", qpdf_error_);
        return p;
      }
      render(p);
      ++index_;
      return p;
    }
    if (static_cast<std::size_t>(index_) >= pages_.size()) {
      finished_ = true;
      if (index_ == 0) {
        p.error = "a PDF file with no page";
        return p;
      }
      return std::nullopt;
    }
    try {
      p.image = embedded_image(pages_[static_cast<std::size_t>(index_)]);
    } catch (const std::exception&) {
      p.image = cv::Mat();
    }
    if (p.image.empty()) {
      if (!poppler_tried_) open_poppler();
      if (doc_ && index_ < doc_->pages()) render(p);
      else p.error = "a PDF page that cannot be rendered";
    }
    ++index_;
    return p;
  }

 private:
  static constexpr std::size_t kMaxPdfPages = 10'000;

  void open_poppler() {
    poppler_tried_ = true;
    if (!bytes_.empty())
      doc_.reset(poppler::document::load_from_raw_data(bytes_.data(), static_cast<int>(std::min<std::size_t>(bytes_.size(), 0x7fffffff))));
    else
      doc_.reset(poppler::document::load_from_file(name_));
    if (doc_ && doc_->is_locked()) doc_.reset();
  }

  void render(InputPage& p) {
    std::unique_ptr<poppler::page> page(doc_->create_page(index_));
    if (!page) {
      p.error = "a PDF page that cannot be read";
      return;
    }
    const auto rect = page->page_rect();
    const double px = rect.width() / 72.0 * dpi_ * (rect.height() / 72.0 * dpi_);
    if (!(px > 0) || px > static_cast<double>(kMaxPagePixels)) {
      p.error = fmt::format("a PDF page of {} x {} pt: too large to render at {} dpi", rect.width(), rect.height(), dpi_);
      return;
    }
    poppler::page_renderer r;
    r.set_image_format(poppler::image::format_gray8);
    r.set_render_hint(poppler::page_renderer::antialiasing, true);
    poppler::image img = r.render_page(page.get(), dpi_, dpi_);
    if (!img.is_valid() || img.width() <= 0 || img.height() <= 0) {
      p.error = "a PDF page that cannot be rendered";
      return;
    }
    cv::Mat view(img.height(), img.width(), CV_8UC1, const_cast<char*>(img.const_data()), static_cast<std::size_t>(img.bytes_per_row()));
    p.image = view.clone();
    p.dpi = dpi_;
  }

  std::string name_;
  std::string bytes_;  // empty when read from the file
  int dpi_;
  QPDF qpdf_;
  bool qpdf_ok_ = false;
  std::string qpdf_error_;
  std::vector<QPDFPageObjectHelper> pages_;
  std::unique_ptr<poppler::document> doc_;
  bool poppler_tried_ = false;
  int index_ = 0;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<PageStream> open_pdf_pages(const std::string& path, int render_dpi) {
  return std::make_unique<PdfPages>(path, std::string(), false, render_dpi);
}

std::unique_ptr<PageStream> open_pdf_pages_in_memory(std::string bytes, const std::string& name, int render_dpi) {
  return std::make_unique<PdfPages>(name, std::move(bytes), true, render_dpi);
}

}  // namespace epure::scan
