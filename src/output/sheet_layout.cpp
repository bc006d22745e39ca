#include "output/sheet_layout.h"

#include <stdexcept>

#include <fmt/format.h>

#include "render/qr_code.h"

namespace epure::output {
namespace {

scan::Rect rect(const render::PageRect& r) { return {r.x, r.y, r.width, r.height}; }

// The field a box belongs to: a comb cell's question and coordinate, a tick's question.
std::string field_question(const render::PlacedBox& b) {
  if (b.kind == render::BoxKind::cell && !b.value.empty()) return fmt::format("{}.{}", b.question_id, b.value);
  return b.question_id;
}

}  // namespace

scan::SheetLayout sheet_layout(const std::string& sheet_id, const std::vector<render::LaidOutPage>& pages) {
  scan::SheetLayout sheet;
  sheet.sheet = sheet_id;
  for (const auto& p : pages) {
    if (p.marks.size() != 4 || p.codes.empty())
      throw std::logic_error(fmt::format("sheet {}, page {}: no scan furniture", sheet_id, p.number));
    scan::PageLayout page;
    page.page = p.number;
    page.width = p.size.width_pt;
    page.height = p.size.height_pt;
    for (std::size_t i = 0; i < 4; ++i)
      page.marks[i] = {p.marks[i].x + p.marks[i].width / 2, p.marks[i].y + p.marks[i].height / 2};
    page.mark_size = p.marks[0].width;
    // the code's modules, without the quiet zone
    const render::PlacedQr& qr = p.codes.front();
    const double module = qr.rect.width / (qr.code.size + 2 * render::kQrQuietZone);
    page.code = {qr.rect.x + module * render::kQrQuietZone, qr.rect.y + module * render::kQrQuietZone,
                 module * qr.code.size, module * qr.code.size};
    // Boxes come in drawing order: a field's cells (or boxes) one after the other, in reading
    // order, the fields in the page's order.
    for (const auto& b : p.boxes) {
      if (b.kind != render::BoxKind::cell && b.kind != render::BoxKind::tick) continue;
      const std::string question = field_question(b);
      const auto type = b.kind == render::BoxKind::cell ? scan::FieldType::comb : scan::FieldType::tick;
      if (page.fields.empty() || page.fields.back().question != question || page.fields.back().type != type) {
        scan::FieldLayout f;
        f.question = question;
        f.type = type;
        f.sign = b.comb_sign;
        f.decimals = b.comb_decimals;
        f.multiple = b.any;
        page.fields.push_back(std::move(f));
      }
      scan::FieldLayout& f = page.fields.back();
      f.cells.push_back(rect(b.rect));
      if (type == scan::FieldType::tick) f.values.push_back(b.value);
    }
    sheet.pages.push_back(std::move(page));
  }
  return sheet;
}

}  // namespace epure::output
