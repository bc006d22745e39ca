#include "render/qr_code.h"

#include <qrencode.h>

#include <array>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/qr_mask.h"

#ifdef EPURE_QR_ENCODE_MASK
// libqrencode's encoder with a given mask (-1: its own choice), declared only in its internal
// header (qrencode_inner.h) and static in 4.1 unless built with its tests: Debian's build is, and
// lists it in its symbols file. src/CMakeLists.txt defines EPURE_QR_ENCODE_MASK when it links.
extern "C" QRcode* QRcode_encodeMask(QRinput* input, int mask);
#endif

namespace epure::render {

namespace {

using CodePtr = std::unique_ptr<QRcode, decltype(&QRcode_free)>;

#ifdef EPURE_QR_ENCODE_MASK
// The 15 format bits of level M for masks 0–7 (ISO/IEC 18004, table C.1: the level's two bits and
// the mask's three, their BCH code, XOR 101010000010010), as libqrencode writes them.
constexpr std::array<unsigned, 8> kFormatLevelM = {0x5412, 0x5125, 0x5e7c, 0x5b4b, 0x45f9, 0x40ce, 0x4f97, 0x4aa0};

CodePtr encode_with_mask(const std::string& data, int mask) {
  // As QRcode_encodeString8bit builds its input: any version, level M, the text up to its first NUL.
  std::unique_ptr<QRinput, decltype(&QRinput_free)> input(QRinput_new2(0, QR_ECLEVEL_M), &QRinput_free);
  if (!input || QRinput_append(input.get(), QR_MODE_8, static_cast<int>(std::strlen(data.c_str())),
                               reinterpret_cast<const unsigned char*>(data.c_str())) < 0)
    return {nullptr, &QRcode_free};
  return {QRcode_encodeMask(input.get(), mask), &QRcode_free};
}

// The symbol libqrencode would make, from the one it drew with mask 0: its data modules flipped
// back and its format modules light, as its Mask_mask sees the frame, then masked here.
std::optional<MaskedQr> remasked(const QRcode& masked0) {
  const int w = masked0.width;
  std::vector<unsigned char> frame(masked0.data, masked0.data + static_cast<std::size_t>(w) * static_cast<std::size_t>(w));
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      unsigned char& m = frame[static_cast<std::size_t>(y * w + x)];
      if (!(m & 0x80))
        m ^= ((x + y) & 1) == 0 ? 1 : 0;  // mask 0 flips where (x + y) is even
      else if ((m & 0x84) == 0x84)
        m = 0x84;
    }
  return mask_qr(frame, w, kFormatLevelM);
}
#endif

}  // namespace

QrCode encode_qr(std::string_view text) {
  const std::string data(text);
  // 8-bit mode: sheet ids mix cases and digits, which the alphanumeric mode would upper-case.
#ifdef EPURE_QR_ENCODE_MASK
  // libqrencode's own mask choice costs nine tenths of an encoding: the symbol is encoded with
  // mask 0 and masked again here on rows of bits (render/qr_mask.h), with libqrencode's choice.
  CodePtr code = encode_with_mask(data, 0);
  if (!code) throw std::runtime_error("cannot encode '" + data + "' as a QR code");
  QrCode qr;
  qr.size = code->width;
  qr.modules.resize(static_cast<std::size_t>(qr.size * qr.size));
  if (const auto masked = remasked(*code)) {
    for (int y = 0; y < qr.size; ++y)
      for (int x = 0; x < qr.size; ++x)
        qr.modules[static_cast<std::size_t>(y * qr.size + x)] = (masked->rows[static_cast<std::size_t>(y)] >> x) & 1;
    return qr;
  }
  code = encode_with_mask(data, -1);  // wider than a row of bits: libqrencode chooses
  if (!code) throw std::runtime_error("cannot encode '" + data + "' as a QR code");
#else
  // A libqrencode without QRcode_encodeMask: its own choice of the mask.
  CodePtr code(QRcode_encodeString8bit(data.c_str(), 0, QR_ECLEVEL_M), &QRcode_free);
  if (!code) throw std::runtime_error("cannot encode '" + data + "' as a QR code");
  QrCode qr;
  qr.size = code->width;
  qr.modules.resize(static_cast<std::size_t>(qr.size * qr.size));
#endif
  // Bit 0 of each byte is the module's colour; the other bits say what the module is for.
  for (std::size_t i = 0; i < qr.modules.size(); ++i) qr.modules[i] = (code->data[i] & 1) != 0;
  return qr;
}

}  // namespace epure::render
