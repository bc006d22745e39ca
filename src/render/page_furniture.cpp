#include "render/page_furniture.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "render/qr_code.h"

namespace epure::render::layout_detail {
namespace {

// The name fields: the name gets the larger share of the line (names are longer than student
// numbers); a writing line starts a little after its label and runs just under the baseline,
// below the descenders (0.24 em).
constexpr double kNameShare = 0.6;
constexpr double kWritingLineGap = 4;
constexpr double kWritingLineDrop = 3;

}  // namespace

Atom name_row(const Document& doc, const LayoutStyle& s, const TextArea& area) {
  Atom a;
  a.height = s.name_row_height;
  const double size = s.body_size;
  const double baseline = s.name_row_height - kWritingLineGap - kWritingLineDrop;
  const double line_y = baseline + kWritingLineDrop;
  auto name = plain(doc.words.name);
  auto number = plain(doc.words.student_number);
  const double name_w = text_width(name, size);
  const double number_w = text_width(number, size);
  const double left = area.left;
  if (!doc.student_name.empty() || !doc.student_number.empty()) {
    // A roster's student: name and number printed, nothing to write.
    auto who = plain(doc.student_name, true);
    const double who_w = text_width(who, size);
    a.content.text(std::move(name), left, baseline, size);
    a.content.text(std::move(who), left + name_w + kWritingLineGap, baseline, size);
    const double x = std::max(left + (area.right - left) * kNameShare, left + name_w + 2 * kWritingLineGap + who_w + kHeaderGap);
    a.content.text(std::move(number), x, baseline, size);
    a.content.text(plain(doc.student_number, true), x + number_w + kWritingLineGap, baseline, size);
    return a;
  }
  if (doc.student_number_cells > 0) {
    // The number as a comb at the right end of the row, the name's writing line in what is left.
    const double cells = s.comb_cell_width * doc.student_number_cells;
    const double comb_x = area.right - cells;
    const double top = line_y - s.comb_cell_height;
    for (int i = 0; i < doc.student_number_cells; ++i)
      a.content.box({{comb_x + s.comb_cell_width * i, top, s.comb_cell_width, s.comb_cell_height}, BoxKind::cell,
                     "student_number", {}, false, 0});
    const double number_x = comb_x - kWritingLineGap - number_w;
    a.content.text(std::move(name), left, baseline, size);
    a.content.kept().rules.push_back({{left + name_w + kWritingLineGap, line_y}, {number_x - kHeaderGap, line_y}, 0.6, Ink::text});
    a.content.text(std::move(number), number_x, baseline, size);
    return a;
  }
  const double split = left + (area.right - left) * kNameShare;
  a.content.text(std::move(name), left, baseline, size);
  a.content.kept().rules.push_back({{left + name_w + kWritingLineGap, line_y}, {split - kHeaderGap, line_y}, 0.6, Ink::text});
  a.content.text(std::move(number), split, baseline, size);
  a.content.kept().rules.push_back({{split + number_w + kWritingLineGap, line_y}, {area.right, line_y}, 0.6, Ink::text});
  return a;
}

// Course and title on the left, sheet id and "page i/n" on the right, a rule under them.
void add_header(LaidOutPage& page, const Document& doc, const LayoutStyle& s, const TextArea& area) {
  const double top = s.margin_top;
  const double big = s.header_title_size, small = s.header_small_size;
  const double first = top + big * kBaseline;
  const double second = first + small * s.line_height + 2;

  // The page code, when the document has scan furniture: a QR code at the header's right end
  // (its top quiet zone in the margin, its bottom one above the content), the header's texts
  // and rule left of it; and the four corner marks in the margins.
  double right = area.right;
  if (doc.page_code) {
    QrCode code = encode_qr(doc.page_code(page.number, page.count));
    const double side = s.qr_module * (code.size + 2 * kQrQuietZone);
    const double quiet = s.qr_module * kQrQuietZone;
    const PageRect rect{area.right - side + quiet, top - quiet, side, side};
    right = rect.x - 2;  // texts stop short of the quiet zone
    page.codes.insert(page.codes.begin(), PlacedQr{rect, std::move(code)});
    const double w = page.size.width_pt, h = page.size.height_pt, m = s.mark_inset, half = s.mark_size / 2;
    page.marks.clear();
    for (const auto& [cx, cy] : {std::pair{m, m}, std::pair{w - m, m}, std::pair{w - m, h - m}, std::pair{m, h - m}})
      page.marks.push_back({cx - half, cy - half, s.mark_size, s.mark_size});
  }

  Fragment f;
  auto id = plain(doc.sheet_id, true);
  auto count = plain(fmt::format("{} {}/{}", doc.words.page, page.number, page.count));
  const double right_w = std::max(text_width(id, big), text_width(count, small));
  f.text_right(std::move(id), right, first, big, Ink::text);
  f.text_right(std::move(count), right, second, small, Ink::muted);

  // A long title or course is set smaller rather than run into the right column.
  const double room = right - area.left - right_w - kHeaderGap;
  auto fitted = [&](std::vector<TextRun> runs, double size) {
    const double w = text_width(runs, size);
    return std::pair{std::move(runs), w > room && w > 0 ? size * room / w : size};
  };
  auto [title, title_size] = fitted(plain(doc.title, true), big);
  auto [course, course_size] = fitted(plain(doc.course), small);
  f.text(std::move(title), area.left, first, title_size);
  f.text(std::move(course), area.left, second, course_size, Ink::muted);
  const double rule_y = top + s.header_height;
  f.kept().rules.push_back({{area.left, rule_y}, {doc.page_code ? right + 2 : right, rule_y}, 0.6, Ink::muted});

  // The header goes first, so that it is also first in every list of the page.
  LaidOutPage head;
  f.move_into(head, 0);
  page.texts.insert(page.texts.begin(), head.texts.begin(), head.texts.end());
  page.rules.insert(page.rules.begin(), head.rules.begin(), head.rules.end());
  page.blocks.insert(page.blocks.begin(), PlacedBlock{{area.left, top, area.width, s.header_height}, -1, -1});
}

}  // namespace epure::render::layout_detail
