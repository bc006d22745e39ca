#pragma once
// The size a PNG file's header gives (its signature, then the IHDR chunk), and its resolution
// when a pHYs chunk before the image data states one: enough to lay out an image without
// decoding it, and to refuse bytes that are not a PNG before a backend decodes them. Outside
// data (a crop read from a scan's directory): tests/fuzz/scan_crop_fuzz.cpp.
#include <cstdint>
#include <optional>
#include <string_view>

namespace epure {

struct PngSize {
  int width = 0, height = 0;
  // From pHYs in pixels per metre, the same on both axes (what epure writes); 0 when the file
  // states none, or another unit, or unequal axes.
  double dots_per_inch = 0;
};

inline constexpr double kMetresPerInch = 0.0254;

// Larger than any crop or figure epure embeds, small enough that width × height × 4 bytes of a
// decoded image stays far under what a page may hold.
inline constexpr std::uint32_t kMaxPngSide = 8192;

inline std::optional<PngSize> png_size(std::string_view bytes) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 + 8 + 13) return std::nullopt;
  for (int i = 0; i < 8; ++i)
    if (static_cast<unsigned char>(bytes[i]) != kSignature[i]) return std::nullopt;
  auto u32 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at])) << 24 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 1])) << 16 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 2])) << 8 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 3]));
  };
  if (u32(8) != 13 || bytes.substr(12, 4) != "IHDR") return std::nullopt;  // IHDR comes first, 13 bytes
  const std::uint32_t w = u32(16), h = u32(20);
  if (w == 0 || h == 0 || w > kMaxPngSide || h > kMaxPngSide) return std::nullopt;
  PngSize size{static_cast<int>(w), static_cast<int>(h)};
  // The chunks after IHDR up to the image data (pHYs must come before IDAT): length, type,
  // data, CRC (not checked: the resolution only sizes the image on the page).
  for (std::size_t at = 8 + 8 + 13 + 4; at + 8 <= bytes.size();) {
    const std::uint32_t length = u32(at);
    const std::string_view type = bytes.substr(at + 4, 4);
    if (type == "IDAT" || type == "IEND" || length > bytes.size() - at - 8) break;
    if (type == "pHYs" && length == 9) {
      const std::uint32_t x = u32(at + 8), y = u32(at + 12);
      if (x == y && x > 0 && bytes[at + 16] == 1) size.dots_per_inch = x * kMetresPerInch;
      break;
    }
    if (bytes.size() - at - 8 - length < 4) break;
    at += 8 + static_cast<std::size_t>(length) + 4;
  }
  return size;
}

}  // namespace epure
