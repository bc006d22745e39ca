#include "render/qr_code.h"

#include <qrencode.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace epure::render {

QrCode encode_qr(std::string_view text) {
  const std::string data(text);
  // 8-bit mode: sheet ids mix cases and digits, which the alphanumeric mode would upper-case.
  std::unique_ptr<QRcode, decltype(&QRcode_free)> code(
      QRcode_encodeString8bit(data.c_str(), 0, QR_ECLEVEL_M), &QRcode_free);
  if (!code) throw std::runtime_error("cannot encode '" + data + "' as a QR code");
  QrCode qr;
  qr.size = code->width;
  qr.modules.resize(static_cast<std::size_t>(qr.size * qr.size));
  // Bit 0 of each byte is the module's colour; the other bits say what the module is for.
  for (std::size_t i = 0; i < qr.modules.size(); ++i) qr.modules[i] = (code->data[i] & 1) != 0;
  return qr;
}

}  // namespace epure::render
