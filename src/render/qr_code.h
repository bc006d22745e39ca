#pragma once
// A QR code as a square of modules, for the sheet id printed on a sheet's first page (a scanned
// sheet is matched to its key by reading it). Encoded by libqrencode; drawn by the page painter
// like any other ink, so the SVG and PDF pages carry the same symbol.
#include <string_view>
#include <vector>

namespace epure::render {

struct QrCode {
  int size = 0;               // modules per side, without the quiet zone
  std::vector<bool> modules;  // row by row, true for a dark module

  bool dark(int x, int y) const { return modules[static_cast<std::size_t>(y * size + x)]; }
};

// The modules must be surrounded by this many light modules for a reader to find the symbol.
inline constexpr int kQrQuietZone = 4;

// Encodes `text` (8-bit mode, error correction level M: a sheet may be scanned crumpled).
// Throws std::runtime_error when libqrencode cannot (text too long for any version).
QrCode encode_qr(std::string_view text);

}  // namespace epure::render
