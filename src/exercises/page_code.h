#pragma once
// The code printed on every page of a sheet (a QR code), so that a loose page, in any order or
// orientation, finds its sheet and its place:
//
//   <sheet id>/<page>/<pages>/<check>        2000-0G2R-0048/2/4/C
//
// The sheet id keeps its own check character; <check> is a Luhn mod 32 character (the sheet
// id's alphabet) over the whole: the id's characters, then the page's and the count's decimal
// digits, so that a page number misread or swapped is caught even where the QR code's own
// error correction would let it through. 20 bytes: a version-2 QR code at level M.
#include <optional>
#include <string>
#include <string_view>

namespace epure {

struct PageCode {
  std::string sheet;  // the sheet id as printed (canonical)
  int page = 1;       // 1-based
  int pages = 1;
};

std::string page_code_text(const PageCode& code);

// The code read back, or nothing when the text is not a page code or its check fails.
std::optional<PageCode> parse_page_code(std::string_view text);

}  // namespace epure
