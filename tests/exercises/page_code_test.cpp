#include <doctest/doctest.h>

#include "exercises/sheet_id.h"
#include "exercises/page_code.h"

using namespace epure;

TEST_CASE("page code: written and read back, and every single change caught") {
  const std::string sheet = SheetId{kDrawVersion, 5, 17}.str();
  for (int pages = 1; pages <= 12; ++pages)
    for (int page = 1; page <= pages; ++page) {
      const std::string text = page_code_text({sheet, page, pages});
      CAPTURE(text);
      const auto back = parse_page_code(text);
      REQUIRE(back);
      CHECK(back->sheet == sheet);
      CHECK(back->page == page);
      CHECK(back->pages == pages);
    }
  const std::string text = page_code_text({sheet, 2, 4});
  CHECK(text.size() == 20);  // a version-2 QR code at level M holds 26 bytes
  // a page number changed (even keeping the check) is refused
  std::string other = text;
  other[15] = '3';
  CHECK_FALSE(parse_page_code(other));
  // every other character changed is refused
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::string t = text;
    t[i] = t[i] == 'A' ? 'B' : 'A';
    CAPTURE(t);
    CHECK_FALSE(parse_page_code(t));
  }
  CHECK_FALSE(parse_page_code(sheet));                  // a first page's old QR code: the sheet id alone
  CHECK_FALSE(parse_page_code(sheet + "/5/4/0"));       // a page past the count
  CHECK_FALSE(parse_page_code(sheet + "/01/4/0"));      // not as written
  CHECK_FALSE(parse_page_code("https://example.org"));  // another QR code
}
