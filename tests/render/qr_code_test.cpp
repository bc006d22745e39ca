#include "render/qr_code.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

using namespace epure::render;

namespace {

// A finder pattern: a 7 × 7 dark ring, a light ring inside it, a 3 × 3 dark centre.
bool finder_at(const QrCode& qr, int x0, int y0) {
  for (int y = 0; y < 7; ++y) {
    for (int x = 0; x < 7; ++x) {
      const int ring = std::min(std::min(x, y), std::min(6 - x, 6 - y));
      const bool dark = ring != 1;
      if (qr.dark(x0 + x, y0 + y) != dark) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("qr code: a sheet id is a version 1 or 2 symbol with its three finder patterns") {
  for (const std::string id : {"1000-0001-000X", "K7QF-3M2X", "FFFF-FFFF-FFFF-FFFF"}) {
    CAPTURE(id);
    const QrCode qr = encode_qr(id);
    CHECK((qr.size == 21 || qr.size == 25));
    REQUIRE(qr.modules.size() == static_cast<std::size_t>(qr.size * qr.size));
    CHECK(finder_at(qr, 0, 0));
    CHECK(finder_at(qr, qr.size - 7, 0));
    CHECK(finder_at(qr, 0, qr.size - 7));
    CHECK_FALSE(finder_at(qr, qr.size - 7, qr.size - 7));  // the fourth corner has none
    // The timing pattern: row 6 alternates between the finders.
    for (int x = 8; x < qr.size - 8; ++x) CHECK(qr.dark(x, 6) == (x % 2 == 0));
  }
}

TEST_CASE("qr code: the same text gives the same symbol, another text another one") {
  CHECK(encode_qr("1000-0001-000X").modules == encode_qr("1000-0001-000X").modules);
  CHECK(encode_qr("1000-0001-000X").modules != encode_qr("1000-0001-000Y").modules);
}

TEST_CASE("qr code: a text longer than any symbol holds is refused") {
  CHECK_THROWS_AS(encode_qr(std::string(8000, 'x')), std::runtime_error);
}
