#pragma once
// The crops `epure scan --crops` writes (DIR/crops/<sheet id>/<question id>.png: each field as
// it was scanned), read back for the feedback sheets, which show each answer's crop under its
// prompt so that a student sees what was read. A missing crop is not an error (a typed answer
// has none); a file that is not a PNG is reported once and left out, the sheet still written.
#include <cstddef>
#include <filesystem>
#include <string_view>

#include "render/scene.h"

namespace epure::grading {

class ScannedCrops {
 public:
  // `dir`: the crops directory; empty, or a directory that does not exist: no crops.
  explicit ScannedCrops(std::filesystem::path dir) : dir_(std::move(dir)) {}

  // The crop of `question` on `sheet`; empty when there is none or it cannot be used.
  render::Raster crop(std::string_view sheet, std::string_view question) const;

  bool any() const { return !dir_.empty(); }

 private:
  std::filesystem::path dir_;
};

// The resolution of a crop whose PNG states none (crops written before scan recorded it in a
// pHYs chunk were all 216 dpi): its size on paper.
inline constexpr double kUnstatedCropDpi = 216;

// Larger than any crop scan writes (a field at 216 dpi is a few kilobytes).
inline constexpr std::size_t kMaxCropBytes = 4 << 20;

}  // namespace epure::grading
