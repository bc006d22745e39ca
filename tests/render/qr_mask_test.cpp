#include "render/qr_mask.h"

#include <doctest/doctest.h>
#include <qrencode.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "exercises/rng.h"
#include "render/qr_code.h"

#ifdef EPURE_QR_MASK_REFERENCE
// libqrencode's mask functions and format bits, declared only in its internal headers (mask.h,
// qrspec.h), as its own tests use them: the reference for the choice made on bits. 4.1 makes
// Mask_evaluateSymbol and Mask_makeMask static unless built with its tests; Debian's build is, and
// lists them in its symbols file. src/CMakeLists.txt checks that they link and defines
// EPURE_QR_MASK_REFERENCE; without them the reference cases below are compiled out, and the
// widths' and encode_qr's cases still run.
extern "C" {
unsigned char* Mask_mask(int width, unsigned char* frame, QRecLevel level);
unsigned char* Mask_makeMask(int width, unsigned char* frame, int mask, QRecLevel level);
int Mask_evaluateSymbol(int width, unsigned char* frame);
unsigned int QRspec_getFormatInfo(int mask, QRecLevel level);
}
#endif

using namespace epure::render;

namespace {

#ifdef EPURE_QR_MASK_REFERENCE
// The 15 format bits libqrencode writes at level M for masks 0–7.
std::array<unsigned, 8> format_m() {
  std::array<unsigned, 8> format{};
  for (int m = 0; m < 8; ++m) format[static_cast<std::size_t>(m)] = QRspec_getFormatInfo(m, QR_ECLEVEL_M);
  return format;
}

bool format_module(int w, int x, int y) {
  if (y == 8 && (x >= w - 8 || x <= 8)) return x != 6;
  if (x == 8 && (y <= 8 || y >= w - 7)) return y != 6;
  return false;
}

// A random frame: data modules (bit 1) and function modules (bit 7) of random colours, its
// format modules light as libqrencode leaves them before masking. `dark` is the chance of a dark
// module, to reach the black-ratio rule's steps and the long runs.
std::vector<unsigned char> random_frame(epure::Rng& rng, int w, double dark, double function) {
  std::vector<unsigned char> f(static_cast<std::size_t>(w * w));
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      unsigned char m = rng.uniform() < function ? 0x80 : 0x02;
      if (rng.uniform() < dark) m |= 1;
      if (format_module(w, x, y)) m = 0x84;
      f[static_cast<std::size_t>(y * w + x)] = m;
    }
  return f;
}

std::vector<std::uint64_t> rows_of(const unsigned char* s, int w) {
  std::vector<std::uint64_t> rows(static_cast<std::size_t>(w));
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x)
      if (s[y * w + x] & 1) rows[static_cast<std::size_t>(y)] |= std::uint64_t{1} << x;
  return rows;
}
#endif

}  // namespace

#ifdef EPURE_QR_MASK_REFERENCE

TEST_CASE("qr mask: the penalty on bits is libqrencode's (N1, N2, N3) on random symbols") {
  for (int seed = 0; seed < 400; ++seed) {
    CAPTURE(seed);
    epure::Rng rng(static_cast<std::uint64_t>(seed), 41);
    const int w = 21 + 4 * (seed % 11);  // versions 1–11, 21 to 61 modules
    // Mostly structured symbols (runs of one colour, finder-like 1:1:3:1:1 rows) and some noise.
    std::vector<unsigned char> f(static_cast<std::size_t>(w * w));
    const double stay = seed % 3 == 0 ? 0.0 : 0.5 + 0.45 * rng.uniform();
    unsigned char colour = 0;
    for (auto& m : f) {
      if (rng.uniform() >= stay) colour = rng.uniform() < 0.5 ? 1 : 0;
      m = colour;
    }
    if (seed % 4 == 1)  // a finder's row pattern here and there
      for (int k = 0; k < 6; ++k) {
        const int y = static_cast<int>(rng.uniform() * w), x0 = static_cast<int>(rng.uniform() * (w - 11));
        const int pattern[11] = {0, 0, 0, 0, 1, 0, 1, 1, 1, 0, 1};
        for (int i = 0; i < 11; ++i) f[static_cast<std::size_t>(y * w + x0 + i)] = static_cast<unsigned char>(pattern[i]);
      }
    const auto rows = rows_of(f.data(), w);
    std::vector<std::uint64_t> cols(static_cast<std::size_t>(w));
    for (int y = 0; y < w; ++y)
      for (int x = 0; x < w; ++x)
        if (f[static_cast<std::size_t>(y * w + x)] & 1) cols[static_cast<std::size_t>(x)] |= std::uint64_t{1} << y;
    CHECK(qr_mask_penalty(rows, cols, w, 1 << 30) == Mask_evaluateSymbol(w, f.data()));
  }
}

TEST_CASE("qr mask: the mask chosen and the symbol made are libqrencode's on random frames") {
  const auto format = format_m();
  for (int seed = 0; seed < 600; ++seed) {
    CAPTURE(seed);
    epure::Rng rng(static_cast<std::uint64_t>(seed), 42);
    const int w = 21 + 4 * (seed % 11);
    const double dark = seed % 5 == 0 ? 0.5 : 0.2 + 0.6 * rng.uniform();
    auto frame = random_frame(rng, w, dark, 0.1 + 0.3 * rng.uniform());
    const auto masked = mask_qr(frame, w, format);
    REQUIRE(masked.has_value());
    REQUIRE(masked->mask >= 0);
    REQUIRE(masked->mask < 8);
    unsigned char* theirs = Mask_mask(w, frame.data(), QR_ECLEVEL_M);
    unsigned char* ours = Mask_makeMask(w, frame.data(), masked->mask, QR_ECLEVEL_M);
    REQUIRE(theirs != nullptr);
    REQUIRE(ours != nullptr);
    CHECK(std::memcmp(theirs, ours, static_cast<std::size_t>(w * w)) == 0);
    const auto rows = rows_of(theirs, w);
    CHECK(std::equal(rows.begin(), rows.end(), masked->rows.begin()));
    std::free(theirs);
    std::free(ours);
  }
}

#endif

TEST_CASE("qr mask: widths out of range are left to libqrencode") {
  std::vector<unsigned char> frame(65 * 65, 0x02);
  const std::array<unsigned, 8> format{};  // no symbol is made: any bits do
  CHECK_FALSE(mask_qr(frame, 65, format).has_value());
  CHECK_FALSE(mask_qr(std::span<const unsigned char>(frame.data(), 10), 21, format).has_value());
}

TEST_CASE("qr mask: encode_qr gives QRcode_encodeString8bit's symbols") {
  // Page codes as the sheets print them, then random texts of every length up to version 15 (400
  // 8-bit characters at level M; versions 12–15 are wider than a row of bits).
  std::vector<std::string> texts;
  for (int i = 0; i < 300; ++i)
    texts.push_back("1" + std::to_string(100 + i % 900) + "-000" + std::to_string(i % 10) + "-00" +
                    std::string(1, "0123456789ABCDEFGHJKMNPQRSTVWXYZ"[i % 32]) + "X/" + std::to_string(1 + i % 5) + "/" +
                    std::to_string(4 + i % 3) + "/" + std::string(1, "ABCDEFGHIJ"[i % 10]));
  epure::Rng rng(7, 43);
  for (int i = 0; i < 1500; ++i) {
    const int length = 1 + static_cast<int>(rng.uniform() * (i < 1200 ? 80 : 400));
    std::string t;
    for (int k = 0; k < length; ++k) t.push_back(static_cast<char>(32 + static_cast<int>(rng.uniform() * 95)));
    texts.push_back(t);
  }
  for (const auto& text : texts) {
    CAPTURE(text);
    QRcode* reference = QRcode_encodeString8bit(text.c_str(), 0, QR_ECLEVEL_M);
    REQUIRE(reference != nullptr);
    const QrCode qr = encode_qr(text);
    REQUIRE(qr.size == reference->width);
    bool same = true;
    for (int i = 0; i < qr.size * qr.size; ++i)
      same = same && qr.modules[static_cast<std::size_t>(i)] == ((reference->data[i] & 1) != 0);
    CHECK(same);
    QRcode_free(reference);
  }
}
