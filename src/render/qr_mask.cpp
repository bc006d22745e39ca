#include "render/qr_mask.h"

#include <bit>
#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>

namespace epure::render {

namespace {

// libqrencode's weights (JIS X0510:2004, 8.8.2): runs of five or more, 2 × 2 blocks of one
// colour, finder-like 1:1:3:1:1 runs, the distance of the dark share from 50 %.
constexpr int kN1 = 3, kN2 = 3, kN3 = 40, kN4 = 10;

// Where a mask flips a data module: libqrencode flips where its expression is 0.
bool flips(int mask, int x, int y) {
  switch (mask) {
    case 0: return ((x + y) & 1) == 0;
    case 1: return (y & 1) == 0;
    case 2: return x % 3 == 0;
    case 3: return (x + y) % 3 == 0;
    case 4: return (((y / 2) + (x / 3)) & 1) == 0;
    case 5: return ((x * y) & 1) + (x * y) % 3 == 0;
    case 6: return ((((x * y) & 1) + (x * y) % 3) & 1) == 0;
    default: return ((((x * y) % 3) + ((x + y) & 1)) & 1) == 0;
  }
}

// The eight masks' flips as rows of bits, for one width.
struct MaskRows {
  std::uint64_t rows[8][kQrMaskMaxWidth] = {};
  std::uint64_t cols[8][kQrMaskMaxWidth] = {};  // the same flips by column: bit y of cols[m][x]
};

const MaskRows& mask_rows(int width) {
  // A thread's flips, made once a width (a set alternates a few versions) and kept on the heap: a
  // thread_local table of 8 KB a width would be part of the executable's static TLS block, which
  // every thread the process creates gets zeroed.
  using Table = std::array<std::unique_ptr<MaskRows>, kQrMaskMaxWidth + 1>;
  thread_local std::unique_ptr<Table> table;
  if (!table) table = std::make_unique<Table>();
  std::unique_ptr<MaskRows>& flips_of = (*table)[static_cast<std::size_t>(width)];
  if (!flips_of) {
    flips_of = std::make_unique<MaskRows>();
    MaskRows& made = *flips_of;
    for (int m = 0; m < 8; ++m)
      for (int y = 0; y < width; ++y) {
        std::uint64_t r = 0;
        for (int x = 0; x < width; ++x)
          if (flips(m, x, y)) {
            r |= std::uint64_t{1} << x;
            made.cols[m][x] |= std::uint64_t{1} << y;
          }
        made.rows[m][y] = r;
      }
  }
  return *flips_of;
}

std::uint64_t low_bits(int n) { return n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1; }

// The dark modules of a word, inline: without -mpopcnt, std::popcount is a call into libgcc.
int ones(std::uint64_t v) {
  v -= (v >> 1) & 0x5555555555555555ULL;
  v = (v & 0x3333333333333333ULL) + ((v >> 2) & 0x3333333333333333ULL);
  v = (v + (v >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
  return static_cast<int>((v * 0x0101010101010101ULL) >> 56);
}

// N1 and N3 of one line of modules (bit x dark), as libqrencode's Mask_calcN1N3 counts them on
// its list of runs, but from the bits.
int line_penalty(std::uint64_t line, int width) {
  const std::uint64_t all = low_bits(width);
  // N1: a run of len >= 5 modules of one colour costs 3 + (len - 5). Bit x of `same4`: modules
  // x to x + 4 are of one colour, so a run of len >= 5 sets len - 4 adjacent bits of it, apart
  // from the next run's: their count plus twice the number of blocks.
  const std::uint64_t same = ~(line ^ (line >> 1)) & low_bits(width - 1);
  const std::uint64_t same4 = same & (same >> 1) & (same >> 2) & (same >> 3);
  int demerit = ones(same4) + 2 * ones(same4 & ~(same4 << 1));
  // N3: runs dark f, light f, dark 3f, light f, dark f (as runs: nothing dark just before nor just
  // after), counted when the line holds nothing dark before it or after it, or when 4f light
  // modules precede or follow it. dark[k] (light[k]): bit x when modules x to x + k - 1 are.
  std::uint64_t dark[kQrMaskMaxWidth + 1], light[kQrMaskMaxWidth / 3 + 2];
  dark[1] = line;
  int longest = 1;  // dark[longest + 1] would be empty
  while (longest < width && (dark[longest + 1] = dark[longest] & (line >> longest)) != 0) ++longest;
  const int largest = std::min(longest / 3, width / 7);  // f: a dark run of 3f, seven runs of f
  if (largest == 0) return demerit;
  light[1] = ~line & all;
  for (int k = 1; k < largest; ++k) light[k + 1] = light[k] & (light[1] >> k);
  for (int f = 1; f <= largest; ++f) {
    const int end = 7 * f;  // the pattern's length
    std::uint64_t at = dark[f] & (light[f] >> f) & (dark[3 * f] >> (2 * f)) & (light[f] >> (5 * f)) &
                       (dark[f] >> (6 * f)) & ~(line << 1) & low_bits(width - end + 1);
    if (end < width) at &= ~(line >> end);
    for (; at; at &= at - 1) {
      const int x = std::countr_zero(at);
      const int after = x + end;  // first module after the pattern
      const bool nothing_before = (line & low_bits(x)) == 0;
      const bool light_before = x >= 4 * f && ((line >> (x - 4 * f)) & low_bits(4 * f)) == 0;
      const bool nothing_after = after >= width || (line >> after) == 0;
      const bool light_after = after + 4 * f <= width && ((line >> after) & low_bits(4 * f)) == 0;
      if (nothing_before || light_before || nothing_after || light_after) demerit += kN3;
    }
  }
  return demerit;
}

}  // namespace

int qr_mask_penalty(std::span<const std::uint64_t> rows, std::span<const std::uint64_t> cols, int width, int stop) {
  const std::uint64_t pairs = low_bits(width - 1);
  int demerit = 0;
  // N2: every 2 × 2 block of one colour, overlapping ones each counted.
  for (int y = 1; y < width; ++y) {
    const std::uint64_t a = rows[static_cast<std::size_t>(y - 1)], b = rows[static_cast<std::size_t>(y)];
    const std::uint64_t dark = a & b & (a >> 1) & (b >> 1);
    const std::uint64_t light = ~(a | b | (a >> 1) | (b >> 1));
    demerit += kN2 * ones((dark | light) & pairs);
  }
  for (int y = 0; y < width && demerit < stop; ++y) demerit += line_penalty(rows[static_cast<std::size_t>(y)], width);
  for (int x = 0; x < width && demerit < stop; ++x) demerit += line_penalty(cols[static_cast<std::size_t>(x)], width);
  return demerit;
}

std::optional<MaskedQr> mask_qr(std::span<const unsigned char> frame, int width,
                                const std::array<unsigned, 8>& format) {
  if (width < 21 || width > kQrMaskMaxWidth || frame.size() != static_cast<std::size_t>(width * width))
    return std::nullopt;
  // The frame by rows and by columns (the runs are counted both ways).
  std::uint64_t dark[kQrMaskMaxWidth] = {}, data[kQrMaskMaxWidth] = {};
  std::uint64_t dark_cols[kQrMaskMaxWidth] = {}, data_cols[kQrMaskMaxWidth] = {};
  for (int y = 0; y < width; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char m = frame[static_cast<std::size_t>(y * width + x)];
      if (m & 1) {
        dark[y] |= std::uint64_t{1} << x;
        dark_cols[x] |= std::uint64_t{1} << y;
      }
      if (!(m & 0x80)) {
        data[y] |= std::uint64_t{1} << x;
        data_cols[x] |= std::uint64_t{1} << y;
      }
    }
  const MaskRows& flip = mask_rows(width);
  const int w2 = width * width;
  MaskedQr best;
  int least = std::numeric_limits<int>::max();
  for (int m = 0; m < 8; ++m) {
    std::array<std::uint64_t, kQrMaskMaxWidth> rows{}, cols{};
    for (int i = 0; i < width; ++i) {
      rows[static_cast<std::size_t>(i)] = dark[i] ^ (flip.rows[m][i] & data[i]);
      cols[static_cast<std::size_t>(i)] = dark_cols[i] ^ (flip.cols[m][i] & data_cols[i]);
    }
    // The format information, written twice as libqrencode's Mask_writeFormatInformation
    // places it: bits 0–7 along row 8 from the right and down column 8 (skipping the timing
    // row), bits 8–14 up column 8 from the bottom and along row 8 (skipping the timing column).
    auto set = [&](int x, int y) {
      rows[static_cast<std::size_t>(y)] |= std::uint64_t{1} << x;
      cols[static_cast<std::size_t>(x)] |= std::uint64_t{1} << y;
    };
    unsigned bits = format[static_cast<std::size_t>(m)];
    for (int i = 0; i < 8; ++i, bits >>= 1)
      if (bits & 1) {
        set(width - 1 - i, 8);
        set(8, i < 6 ? i : i + 1);
      }
    for (int i = 0; i < 7; ++i, bits >>= 1)
      if (bits & 1) {
        set(8, width - 7 + i);
        set(i == 0 ? 7 : 6 - i, 8);
      }
    int blacks = 0;
    for (int y = 0; y < width; ++y) blacks += ones(rows[static_cast<std::size_t>(y)]);
    const int ratio = (200 * blacks + w2) / w2 / 2;  // libqrencode's rounded percentage
    const int demerit = (std::abs(ratio - 50) / 5) * kN4;
    if (demerit >= least) continue;  // the penalties only add: it cannot be lower
    const int total = demerit + qr_mask_penalty(std::span(rows.data(), static_cast<std::size_t>(width)),
                                                 std::span(cols.data(), static_cast<std::size_t>(width)), width, least - demerit);
    if (total < least) {
      least = total;
      best.mask = m;
      best.rows = rows;
    }
  }
  return best;
}

}  // namespace epure::render
