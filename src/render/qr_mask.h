#pragma once
// The choice of a QR symbol's mask, made as libqrencode 4.1's Mask_mask makes it but on rows of
// bits: the eight masks' penalties (its N1–N4 rules, its run lists and its black-ratio rounding)
// and the first mask of the lowest penalty. libqrencode spends 90 % of a page code's encoding
// there, one byte a module; the page codes (one a sheet's page) were 7 % of an SVG set's
// instructions. The data and the frame are still libqrencode's (its encoding with mask 0, unmasked,
// through QRcode_encodeMask: declared only in its internal header, exported by Debian's build, which
// is built with its tests and lists it in its symbols file; src/CMakeLists.txt checks it links), so
// the choice must be exactly its own: tests/render/qr_mask_test.cpp compares the choice with
// Mask_mask's on random frames and the symbols with QRcode_encodeString8bit's on 1,800 texts.
#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace epure::render {

// Widest symbol this handles: a row of modules fits one 64-bit word (version 11 is 61 wide).
inline constexpr int kQrMaskMaxWidth = 64;

// `frame` is a width × width symbol in libqrencode's module bytes (bit 0 dark, bit 7 a function
// module, bits 7 and 2 a format-information module), unmasked, its format modules light.
// `format` holds the 15 format bits libqrencode writes for each mask at the symbol's level.
// Returns the mask libqrencode would choose and the symbol it makes (Mask_makeMask's colours),
// or nothing when the width is out of range (21, version 1, to kQrMaskMaxWidth).
struct MaskedQr {
  int mask = 0;
  std::array<std::uint64_t, kQrMaskMaxWidth> rows{};  // bit x of rows[y]: module (x, y) dark
};
std::optional<MaskedQr> mask_qr(std::span<const unsigned char> frame, int width,
                                const std::array<unsigned, 8>& format);

// libqrencode's penalty of one masked symbol given as rows of bits (bit x of rows[y] dark) and as
// columns (bit y of cols[x]), without its black-ratio term (N4): the 2 × 2 blocks (N2) and the
// runs of each row and column (N1, N3). Exposed for the tests. Stops adding once the penalty
// reaches `stop` (it then returns ≥ stop).
int qr_mask_penalty(std::span<const std::uint64_t> rows, std::span<const std::uint64_t> cols, int width, int stop);

}  // namespace epure::render
