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
  // The sheet id's QR code at the right end of the row (its quiet zone is its margin), the
  // writing lines in what is left.
  double fields_right = area.right;
  if (!doc.sheet_id.empty()) {
    QrCode code = encode_qr(doc.sheet_id);
    const double side = s.qr_module * (code.size + 2 * kQrQuietZone);
    const double quiet = s.qr_module * kQrQuietZone;
    a.height = std::max(a.height, side - quiet);  // the top quiet zone may reach into header_gap
    a.content.codes.push_back({{area.right - side + quiet, -quiet, side, side}, std::move(code)});
    fields_right = area.right - side + quiet - kHeaderGap;
  }
  const double size = s.body_size;
  const double baseline = s.name_row_height - kWritingLineGap - kWritingLineDrop;
  const double line_y = baseline + kWritingLineDrop;
  auto name = plain(doc.words.name);
  auto number = plain(doc.words.student_number);
  const double name_w = text_width(name, size);
  const double number_w = text_width(number, size);
  const double left = area.left;
  const double split = left + (fields_right - left) * kNameShare;
  a.content.text(std::move(name), left, baseline, size);
  a.content.rules.push_back({{left + name_w + kWritingLineGap, line_y}, {split - kHeaderGap, line_y}, 0.6, Ink::text});
  a.content.text(std::move(number), split, baseline, size);
  a.content.rules.push_back({{split + number_w + kWritingLineGap, line_y}, {fields_right, line_y}, 0.6, Ink::text});
  return a;
}

// Course and title on the left, sheet id and "page i/n" on the right, a rule under them.
void add_header(LaidOutPage& page, const Document& doc, const LayoutStyle& s, const TextArea& area) {
  const double top = s.margin_top;
  const double big = s.header_title_size, small = s.header_small_size;
  const double first = top + big * kBaseline;
  const double second = first + small * s.line_height + 2;

  Fragment f;
  auto id = plain(doc.sheet_id, true);
  auto count = plain(fmt::format("{} {}/{}", doc.words.page, page.number, page.count));
  const double right_w = std::max(text_width(id, big), text_width(count, small));
  f.text_right(std::move(id), area.right, first, big, Ink::text);
  f.text_right(std::move(count), area.right, second, small, Ink::muted);

  // A long title or course is set smaller rather than run into the right column.
  const double room = area.width - right_w - kHeaderGap;
  auto fitted = [&](std::vector<TextRun> runs, double size) {
    const double w = text_width(runs, size);
    return std::pair{std::move(runs), w > room && w > 0 ? size * room / w : size};
  };
  auto [title, title_size] = fitted(plain(doc.title, true), big);
  auto [course, course_size] = fitted(plain(doc.course), small);
  f.text(std::move(title), area.left, first, title_size);
  f.text(std::move(course), area.left, second, course_size, Ink::muted);
  const double rule_y = top + s.header_height;
  f.rules.push_back({{area.left, rule_y}, {area.right, rule_y}, 0.6, Ink::muted});

  // The header goes first, so that it is also first in every list of the page.
  LaidOutPage head;
  f.move_into(head, 0);
  page.texts.insert(page.texts.begin(), head.texts.begin(), head.texts.end());
  page.rules.insert(page.rules.begin(), head.rules.begin(), head.rules.end());
  page.blocks.insert(page.blocks.begin(), PlacedBlock{{area.left, top, area.width, s.header_height}, -1, -1});
}

}  // namespace epure::render::layout_detail
