// layout.json (src/scan/layout_file.cpp): a LayoutError naming the file, never another
// exception; a layout read has every cell on its page, comb fields with room for their integer
// part, tick fields with one value per box, and writes back to JSON that reads the same.
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "scan/layout_file.h"

using namespace epure;
using namespace epure::scan;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  SetLayout l;
  try {
    l = read_layout(text, "layout.json");
  } catch (const LayoutError& e) {
    fuzz::check(fuzz::starts_with(e.what(), "layout.json: "), "a layout error does not name the file", e.what());
    return 0;
  } catch (const std::exception& e) {
    fuzz::broken("not a LayoutError", e.what());
  }
  for (const auto& [id, s] : l.sheets)
    for (const auto& p : s.pages)
      for (const auto& f : p.fields) {
        for (const auto& c : f.cells)
          fuzz::check(c.x >= 0 && c.y >= 0 && c.width > 0 && c.height > 0 && c.x + c.width <= p.width + 1e-6 &&
                          c.y + c.height <= p.height + 1e-6,
                      "a cell off its page", f.question);
        if (f.type == FieldType::comb)
          fuzz::check(static_cast<std::size_t>(f.decimals + (f.sign ? 1 : 0)) < f.cells.size(), "a comb with no integer cell", f.question);
        else
          fuzz::check(f.values.size() == f.cells.size(), "a tick field without one value per box", f.question);
      }
  const std::string again = layout_json(l);
  try {
    fuzz::check(layout_json(read_layout(again, "again")) == again, "a layout does not read back the same");
  } catch (const LayoutError& e) {
    fuzz::broken("a layout written does not read back", e.what());
  }
  return 0;
}
