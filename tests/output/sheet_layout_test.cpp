// A student's sheet as a scan reads it (output/sheet_layout.h), from the pages layout_document
// returns (the ones the PDF is drawn from), on the course in both languages, A4 and Letter:
// - every page carries four corner marks in its margins and the QR code of its page code
//   (sheet id, page, page count, check);
// - every question of the sheet's key has its field: a number or a coordinate a comb (a sign
//   cell, the integer cells, the decimals the set asks), yes/no, a choice or sides boxes that
//   stand for what the answers spreadsheet types;
// - each answer as written fits its comb, and a question's comb has as many cells on every sheet
//   (so it does not tell one sheet's answer);
// - no cell overlaps another cell, a mark or the code; every cell lies on its page.
// The layout.json text checked against the PDF itself: tests/cli/layout_json.sh.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "exercises/page_code.h"
#include "exercises/spec.h"
#include "exercises/worksheet.h"
#include "output/sheet_layout.h"
#include "render/layout.h"
#include "render/qr_code.h"

using namespace epure;

namespace {

bool overlap(const scan::Rect& a, const scan::Rect& b) {
  constexpr double eps = 0.01;  // neighbouring cells share a side
  return a.x + a.width > b.x + eps && b.x + b.width > a.x + eps && a.y + a.height > b.y + eps && b.y + b.height > a.y + eps;
}

bool inside(const scan::Rect& r, double w, double h) { return r.x >= 0 && r.y >= 0 && r.x + r.width <= w && r.y + r.height <= h; }

}  // namespace

TEST_CASE("sheet_layout: marks and page codes on every page, a field for every question, combs that fit") {
  const WorksheetSpec spec = builtin_spec();
  std::uint64_t seed = 40;
  for (const char* lang : {"en", "fr"})
    for (const char* paper : {"A4", "letter"}) {
      SetOptions options;
      options.language = lang;
      options.page = paper;
      WorksheetSet set(spec, ++seed, options);
      set.measure_combs();  // as generate_set does: over the set's first 64 sheets
      std::map<std::string, std::size_t> cells_of;  // a comb's cells, the same on every sheet
      for (int i = 0; i < 8; ++i) {
        const Sheet sheet = set.next();
        const std::string id = sheet.id.str();
        CAPTURE(id);
        CAPTURE(paper);
        const render::Document doc = set.sheet_document(sheet);
        const auto pages = render::layout_document(doc);
        const scan::SheetLayout sl = output::sheet_layout(id, pages);
        REQUIRE(sl.pages.size() == pages.size());
        std::map<std::string, const scan::FieldLayout*> fields;
        for (std::size_t k = 0; k < pages.size(); ++k) {
          const auto& p = sl.pages[k];
          CHECK(p.page == static_cast<int>(k) + 1);
          // the page's code is its page code
          const render::QrCode expected = render::encode_qr(page_code_text({id, p.page, static_cast<int>(pages.size())}));
          REQUIRE(pages[k].codes.size() == 1);
          CHECK(pages[k].codes[0].code.modules == expected.modules);
          CHECK(std::abs(p.code.width - 25 * 1.3) < 1e-9);  // a version-2 code
          const scan::Rect code{p.code.x - 4 * 1.3, p.code.y - 4 * 1.3, p.code.width + 8 * 1.3, p.code.height + 8 * 1.3};
          CHECK(inside(code, p.width, p.height));
          std::vector<scan::Rect> marks;
          for (const auto& m : p.marks) {
            marks.push_back({m.x - p.mark_size / 2, m.y - p.mark_size / 2, p.mark_size, p.mark_size});
            CHECK(inside(marks.back(), p.width, p.height));
          }
          CHECK(p.marks[0].x < p.width / 2);
          CHECK(p.marks[0].y < p.height / 2);
          CHECK(p.marks[2].x > p.width / 2);
          CHECK(p.marks[2].y > p.height / 2);
          std::vector<scan::Rect> all;
          for (const auto& f : p.fields) {
            CAPTURE(f.question);
            CHECK(fields.emplace(f.question, &f).second);  // one field a question
            for (const auto& c : f.cells) {
              CHECK(inside(c, p.width, p.height));
              CHECK(!overlap(c, code));
              for (const auto& m : marks) CHECK(!overlap(c, m));
              for (const auto& o : all) CHECK(!overlap(c, o));
              all.push_back(c);
            }
          }
        }
        // the student number's comb, on the first page
        REQUIRE(fields.count("student_number"));
        CHECK(fields["student_number"]->cells.size() == 8);
        // every question of the key has its field, and each answer fits
        for (const auto& e : sheet.exercises)
          for (const auto& q : e.questions) {
            const std::string qid = fmt::format("{}.{}", e.number, q.field);
            CAPTURE(qid);
            REQUIRE(fields.count(qid));
            const scan::FieldLayout& f = *fields[qid];
            if (const auto* v = std::get_if<double>(&q.expected)) {
              REQUIRE(f.type == scan::FieldType::comb);
              CHECK(f.sign);
              CHECK(f.decimals == spec.decimals);
              const int integer_cells = static_cast<int>(f.cells.size()) - 1 - f.decimals;
              const std::string written = fmt::format("{:.{}f}", std::fabs(*v), spec.decimals);
              CHECK(static_cast<int>(written.find('.')) <= integer_cells);
              auto [it, fresh] = cells_of.emplace(qid, f.cells.size());
              CHECK(it->second == f.cells.size());
            } else {
              REQUIRE(f.type == scan::FieldType::tick);
              CHECK(f.values.size() == f.cells.size());
              if (const auto* b = std::get_if<bool>(&q.expected)) {
                CHECK(f.values == std::vector<std::string>{"true", "false"});
                (void)b;
              } else if (const auto* word = std::get_if<std::string>(&q.expected)) {
                CHECK(std::find(f.values.begin(), f.values.end(), *word) != f.values.end());
                CHECK(!f.multiple);
              } else {
                CHECK(f.multiple);  // sides: any number of boxes
                CHECK(f.values.back() == "none");
              }
            }
          }
      }
    }
}

TEST_CASE("sheet_layout: the student number's comb has the spec's cells, clear of the code and the marks") {
  for (const int digits : {4, 12})
    for (const char* paper : {"A4", "letter"}) {
      WorksheetSpec spec = builtin_spec();
      spec.student_number_digits = digits;
      SetOptions options;
      options.language = "fr";
      options.page = paper;
      WorksheetSet set(spec, 7, options);
      const Sheet sheet = set.next();
      const auto pages = render::layout_document(set.sheet_document(sheet));
      const scan::SheetLayout sl = output::sheet_layout(sheet.id.str(), pages);
      CAPTURE(digits);
      CAPTURE(paper);
      const scan::PageLayout& first = sl.pages.front();
      const scan::FieldLayout* number = nullptr;
      for (const auto& f : first.fields)
        if (f.question == "student_number") number = &f;
      REQUIRE(number != nullptr);
      CHECK(number->cells.size() == static_cast<std::size_t>(digits));
      const scan::Rect code{first.code.x - 4 * 1.3, first.code.y - 4 * 1.3, first.code.width + 8 * 1.3, first.code.height + 8 * 1.3};
      for (std::size_t i = 0; i < number->cells.size(); ++i) {
        const scan::Rect& c = number->cells[i];
        CHECK(inside(c, first.width, first.height));
        CHECK(!overlap(c, code));
        for (const auto& m : first.marks)
          CHECK(!overlap(c, {m.x - first.mark_size / 2, m.y - first.mark_size / 2, first.mark_size, first.mark_size}));
        for (std::size_t j = 0; j < i; ++j) CHECK(!overlap(c, number->cells[j]));
      }
      // and the other fields of the page stay clear of it
      for (const auto& f : first.fields)
        if (f.question != "student_number")
          for (const auto& c : f.cells)
            for (const auto& n : number->cells) CHECK(!overlap(c, n));
    }
}
