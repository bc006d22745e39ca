#include "grading/scanned_crops.h"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "support/png_size.h"
#include "support/safe_file_name.h"

namespace epure::grading {

render::Raster ScannedCrops::crop(std::string_view sheet, std::string_view question) const {
  if (dir_.empty() || !safe_file_name(sheet) || !safe_file_name(question)) return {};
  const std::filesystem::path path = dir_ / std::string(sheet) / (std::string(question) + ".png");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return {};
  const auto size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || size > kMaxCropBytes || !in) {
    fmt::print(stderr, "epure grade: {}: {}: its feedback line shows no crop\n", path.string(),
               ec || !in ? "cannot be read" : fmt::format("larger than {} bytes", kMaxCropBytes));
    return {};
  }
  auto png = std::make_shared<std::string>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const auto px = png_size(*png);
  if (!px) {
    fmt::print(stderr, "epure grade: {}: not a PNG image: its feedback line shows no crop\n", path.string());
    return {};
  }
  // on paper as scanned: the height in points at the resolution the crop states
  const double dpi = px->dots_per_inch > 0 ? px->dots_per_inch : kUnstatedCropDpi;
  return render::Raster{std::move(png), px->width, px->height, px->height * 72.0 / dpi};
}

}  // namespace epure::grading
