#include "render/layout.h"
#include "render/laid_out.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <thread>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

using namespace epure::render;
using epure::render::testing::block_of;
using epure::render::testing::joined;
using epure::render::testing::kPt;

namespace {

bool page_has_text(const LaidOutPage& page, const std::string& text) {
  return std::any_of(page.texts.begin(), page.texts.end(),
                     [&](const PlacedText& t) { return joined(t) == text; });
}

Scene square_scene(double w = 8, double h = 5) {
  Scene scene;
  scene.title = "Projection of C on (AB)";
  Panel panel;
  panel.view = {-1, -1, w - 1, h - 1};
  panel.add(Grid{1, true});
  panel.add(Segment{{0, 0}, {5, 2}, Role::data, false});
  panel.add(PointMark{{2, 3}, Role::data, Label{"C", {2, 3}, Side::above, Role::data}});
  scene.panels.push_back(std::move(panel));
  return scene;
}

const std::string kText =
    "Les points A, B et C sont donnés. Calculer le paramètre t_{ab} de la projection orthogonale "
    "P de C sur la droite (AB), à l'aide du produit scalaire \\vec{AB}·\\vec{AC}, puis en déduire "
    "les coordonnées de P et la distance CP. Arrondir chaque résultat intermédiaire à deux "
    "décimales.";

Section exercise(int n, bool with_figure = true, int paragraphs = 1) {
  Section s;
  s.add(Heading{fmt::format("Exercise {} — projection", n), 1});
  for (int i = 0; i < paragraphs; ++i) s.add(Paragraph{kText, false});
  if (with_figure) s.add(Figure{square_scene(), 0.6});
  s.add(AnswerField{fmt::format("{}.t", n), "t =", AnswerField::Kind::number, {}});
  s.add(AnswerField{fmt::format("{}.P", n), "P =", AnswerField::Kind::point, {}});
  s.add(AnswerField{fmt::format("{}.position", n), "Position of P:", AnswerField::Kind::choice,
                    {"before", "between", "after"}});
  return s;
}

Document sample(int sections, int paragraphs = 1) {
  Document doc;
  doc.title = "Ray tracer utilities — worksheet";
  doc.course = "Computer graphics, M1";
  doc.sheet_id = "K7QF-3M2X";
  doc.language = "en";
  doc.header_note = "Give every answer with two decimals.";
  doc.student_fields = true;
  for (int i = 1; i <= sections; ++i) doc.sections.push_back(exercise(i, true, paragraphs));
  return doc;
}


// Every page of `pages` shown as text, down to the last coordinate: two layouts are the same
// exactly when these strings are.
std::string dump(const std::vector<LaidOutPage>& pages) {
  std::string out;
  for (const auto& p : pages) {
    out += fmt::format("page {}/{} {}x{}\n", p.number, p.count, p.size.width_pt, p.size.height_pt);
    for (const auto& b : p.boxes)
      out += fmt::format("box {} {} {} {} {} {} {}\n", static_cast<int>(b.kind), b.rect.x, b.rect.y,
                         b.rect.width, b.rect.height, b.question_id, b.value);
    for (const auto& r : p.rules)
      out += fmt::format("rule {} {} {} {} {}\n", r.a.x, r.a.y, r.b.x, r.b.y, r.width);
    for (const auto& f : p.figures)
      out += fmt::format("figure {} {} {} {}\n", f.rect.x, f.rect.y, f.rect.width, f.rect.height);
    for (const auto& t : p.texts)
      out += fmt::format("text {} {} {} {} {}\n", t.baseline.x, t.baseline.y, t.size,
                         static_cast<int>(t.ink), joined(t));
  }
  return out;
}

void check_inside(const LaidOutPage& page, const LayoutStyle& style) {
  const double left = style.margin_left, right = page.size.width_pt - style.margin_right;
  const double top = style.margin_top, bottom = page.size.height_pt - style.margin_bottom;
  auto inside = [&](double x0, double y0, double x1, double y1) {
    CHECK(x0 >= left - kPt);
    CHECK(x1 <= right + kPt);
    CHECK(y0 >= top - kPt);
    CHECK(y1 <= bottom + kPt);
  };
  for (const auto& b : page.boxes) inside(b.rect.x, b.rect.y, b.rect.right(), b.rect.bottom());
  for (const auto& f : page.figures) inside(f.rect.x, f.rect.y, f.rect.right(), f.rect.bottom());
  for (const auto& r : page.rules)
    inside(std::min(r.a.x, r.b.x), std::min(r.a.y, r.b.y), std::max(r.a.x, r.b.x), std::max(r.a.y, r.b.y));
  for (const auto& t : page.texts) {
    CAPTURE(joined(t));
    // The line's ink, from the top of its tallest glyph to the bottom of a descender.
    inside(t.baseline.x, t.baseline.y - 0.93 * t.size, t.baseline.x + text_width(t.runs, t.size),
           t.baseline.y + 0.24 * t.size);
  }
  for (const auto& b : page.blocks) inside(b.rect.x, b.rect.y, b.rect.right(), b.rect.bottom());
}

}  // namespace

TEST_CASE("layout: a header on every page, the name fields on the first only") {
  const Document doc = sample(6);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  for (const auto& page : pages) {
    CAPTURE(page.number);
    CHECK(page.count == static_cast<int>(pages.size()));
    CHECK(page_has_text(page, doc.title));
    CHECK(page_has_text(page, doc.course));
    CHECK(page_has_text(page, doc.sheet_id));
    CHECK(page_has_text(page, fmt::format("page {}/{}", page.number, pages.size())));
    CHECK(page_has_text(page, "Name:") == (page.number == 1));
    CHECK(page_has_text(page, "Student number:") == (page.number == 1));
  }
  CHECK(page_has_text(pages[0], doc.header_note));

  SUBCASE("no scan furniture unless the document asks for it") {
    for (const auto& page : pages) {
      CHECK(page.codes.empty());
      CHECK(page.marks.empty());
    }
  }

  SUBCASE("the scan furniture: on every page four corner marks and the page's code, in the header's right end") {
    Document scanned = doc;
    scanned.page_code = [](int page, int count) { return fmt::format("K7QF-3M2X/{}/{}", page, count); };
    scanned.student_number_cells = 8;
    const auto sp = layout_document(scanned);
    const LayoutStyle style;
    for (const auto& page : sp) {
      CAPTURE(page.number);
      REQUIRE(page.codes.size() == 1);
      CHECK(page.codes[0].code.modules == encode_qr(fmt::format("K7QF-3M2X/{}/{}", page.number, page.count)).modules);
      const PlacedQr& qr = page.codes[0];
      CHECK(qr.rect.width == doctest::Approx(style.qr_module * (qr.code.size + 2 * kQrQuietZone)));
      // its modules end on the right margin and start at the top margin; its quiet zone ends
      // above the content
      CHECK(qr.rect.right() - style.qr_module * kQrQuietZone == doctest::Approx(scanned.page.width_pt - style.margin_right));
      CHECK(qr.rect.y + style.qr_module * kQrQuietZone == doctest::Approx(style.margin_top));
      CHECK(qr.rect.bottom() <= style.margin_top + style.header_height + style.header_gap);
      // no text, rule or box in it
      for (const PlacedText& t : page.texts)
        CHECK((t.baseline.x + text_width(t.runs, t.size) <= qr.rect.x || t.baseline.y - t.size > qr.rect.bottom()));
      for (const PlacedRule& r : page.rules)
        if (r.a.y >= qr.rect.y && r.a.y <= qr.rect.bottom()) CHECK(std::max(r.a.x, r.b.x) <= qr.rect.x + 1e-9);
      for (const PlacedBox& b : page.boxes) CHECK(b.rect.y > qr.rect.bottom());
      REQUIRE(page.marks.size() == 4);
      for (const PageRect& m : page.marks) {
        CHECK(m.width == doctest::Approx(style.mark_size));
        // in the margins, at the corners
        const double cx = m.x + m.width / 2, cy = m.y + m.height / 2;
        CHECK((cx == doctest::Approx(style.mark_inset) || cx == doctest::Approx(scanned.page.width_pt - style.mark_inset)));
        CHECK((cy == doctest::Approx(style.mark_inset) || cy == doctest::Approx(scanned.page.height_pt - style.mark_inset)));
        CHECK((m.right() < style.margin_left || m.x > scanned.page.width_pt - style.margin_right));
        CHECK((m.bottom() < style.margin_top || m.y > scanned.page.height_pt - style.margin_bottom));
      }
    }
    // the student number as a comb of 8 cells on the first page, right of its label
    int cells = 0;
    for (const PlacedBox& b : sp[0].boxes)
      if (b.kind == BoxKind::cell && b.question_id == "student_number") ++cells;
    CHECK(cells == 8);
    for (std::size_t i = 1; i < sp.size(); ++i)
      for (const PlacedBox& b : sp[i].boxes) CHECK(b.question_id != "student_number");
    // a roster's student: printed, no comb
    scanned.student_name = "Zoé Lefèvre";
    scanned.student_number = "20260001";
    const auto named = layout_document(scanned);
    CHECK(page_has_text(named[0], "Zoé Lefèvre"));
    CHECK(page_has_text(named[0], "20260001"));
    for (const PlacedBox& b : named[0].boxes) CHECK(b.kind != BoxKind::cell);
  }

  SUBCASE("a key has no name fields, and its words come from the document") {
    Document key = doc;
    key.student_fields = false;
    key.words.page = "feuille";
    const auto key_pages = layout_document(key);
    CHECK(key_pages[0].codes.empty());
    CHECK(key_pages[0].marks.empty());
    CHECK_FALSE(page_has_text(key_pages[0], "Name:"));
    CHECK(page_has_text(key_pages[0], fmt::format("feuille 1/{}", key_pages.size())));
  }
}

TEST_CASE("layout: everything lies inside the margins, blocks never overlap") {
  const LayoutStyle style;
  for (PageSize size : {PageSize::a4(), PageSize::letter()}) {
    for (int paragraphs : {1, 3, 7}) {
      Document doc = sample(5, paragraphs);
      doc.page = size;
      CAPTURE(size.height_pt);
      CAPTURE(paragraphs);
      for (const auto& page : layout_document(doc, style)) {
        CAPTURE(page.number);
        check_inside(page, style);
        for (std::size_t i = 0; i < page.blocks.size(); ++i) {
          for (std::size_t j = i + 1; j < page.blocks.size(); ++j) {
            // Side by side (a figure and the fields beside it) or one below the other.
            const PageRect& a = page.blocks[i].rect;
            const PageRect& b = page.blocks[j].rect;
            CAPTURE(i);
            CAPTURE(j);
            CHECK((a.right() <= b.x + kPt || b.right() <= a.x + kPt || a.bottom() <= b.y + kPt ||
                   b.bottom() <= a.y + kPt));
          }
        }
      }
    }
  }
}

TEST_CASE("layout: no text overlaps another text, a box or a figure") {
  struct Ink2 {
    double x0, y0, x1, y1;
    std::string what;
  };
  auto overlap = [](const Ink2& a, const Ink2& b) {
    return a.x0 < b.x1 - kPt && b.x0 < a.x1 - kPt && a.y0 < b.y1 - kPt && b.y0 < a.y1 - kPt;
  };
  for (int paragraphs : {1, 4}) {
    Document doc = sample(4, paragraphs);
    if (paragraphs > 1) {
      // A title too long for the header is set smaller, clear of the sheet id.
      doc.title = "Ray tracer utilities: projections, segments, rays against circles, squares, "
                  "ellipses and rectangles — worksheet";
      doc.course = "Computer graphics and image synthesis, first year of the master's degree, spring";
    }
    Section fields;
    fields.add(AnswerField{"9.faces", "Faces hit by the ray, in the order met:", AnswerField::Kind::faces,
                           {"x = −1", "x = 1", "y = −1", "y = 1", "z = −1", "z = 1"}});
    fields.add(AnswerField{"9.hit", "d^{2} < r^{2} ?", AnswerField::Kind::boolean, {}});
    fields.add(AnswerField{"9.Q", "\\vec{N}", AnswerField::Kind::point3, {}});
    fields.add(AnswerLine{"9.t_ab", "t_{ab}", "≈ 0.43 (exact: 3/7), within 0.01 or 1 %, the larger"});
    doc.sections.push_back(fields);
    CAPTURE(paragraphs);
    for (const auto& page : layout_document(doc)) {
      CAPTURE(page.number);
      std::vector<Ink2> texts, others;
      for (const auto& t : page.texts) {
        const TextExtent e = text_extent(t.runs, t.size);
        texts.push_back({t.baseline.x, t.baseline.y - e.ascent, t.baseline.x + e.width,
                         t.baseline.y + e.descent, joined(t)});
      }
      for (const auto& b : page.boxes)
        if (b.kind != BoxKind::shade)
          others.push_back({b.rect.x, b.rect.y, b.rect.right(), b.rect.bottom(), "box " + b.question_id});
      for (const auto& f : page.figures)
        others.push_back({f.rect.x, f.rect.y, f.rect.right(), f.rect.bottom(), "figure"});
      for (const auto& q : page.codes)
        others.push_back({q.rect.x, q.rect.y, q.rect.right(), q.rect.bottom(), "QR code"});
      for (std::size_t i = 0; i < texts.size(); ++i) {
        for (std::size_t j = i + 1; j < texts.size(); ++j) {
          CAPTURE(texts[i].what);
          CAPTURE(texts[j].what);
          CHECK_FALSE(overlap(texts[i], texts[j]));
        }
        for (const auto& o : others) {
          CAPTURE(texts[i].what);
          CAPTURE(o.what);
          CHECK_FALSE(overlap(texts[i], o));
        }
      }
    }
  }
}

TEST_CASE("layout: page breaks") {
  SUBCASE("1. a heading never ends a page, a figure stays with its paragraph") {
    for (int paragraphs = 1; paragraphs <= 12; ++paragraphs) {
      CAPTURE(paragraphs);
      const Document doc = sample(4, paragraphs);
      const auto pages = layout_document(doc);
      for (const auto& page : pages) {
        const auto& last = page.blocks.back();
        if (page.number < page.count && last.section >= 0) {
          CHECK_FALSE(std::holds_alternative<Heading>(block_of(doc, last)));
        }
        for (const auto& b : page.blocks) {
          if (b.section < 0 || !std::holds_alternative<Figure>(block_of(doc, b))) continue;
          REQUIRE(b.block > 0);
          // The paragraph just before the figure ends on this page, right above it; or the
          // figure opens its page and that paragraph is whole on the page before.
          const bool with_paragraph =
              std::any_of(page.blocks.begin(), page.blocks.end(), [&](const PlacedBlock& o) {
                return o.section == b.section && o.block == b.block - 1;
              });
          bool after_whole_paragraph = false;
          if (!with_paragraph && page.number > 1 && page.blocks.size() > 1 && page.blocks[1].block == b.block) {
            const auto& before = pages[static_cast<std::size_t>(page.number - 2)].blocks;
            int parts = 0;
            for (const auto& p : pages)
              for (const auto& o : p.blocks) parts += o.section == b.section && o.block == b.block - 1;
            after_whole_paragraph = parts == 1 && before.back().section == b.section &&
                                    before.back().block == b.block - 1;
          }
          CHECK((with_paragraph || after_whole_paragraph));
        }
      }
    }
  }

  SUBCASE("2. sections share pages; a section's opening is split only after its statement") {
    // The sample's sections are a statement, a figure and the fields beside it: their opening.
    Document doc = sample(7);
    doc.breaks = Document::Breaks::between_blocks;
    const auto pages = layout_document(doc);
    std::size_t shared = 0;
    for (const auto& page : pages) {
      std::set<int> here;
      for (const auto& b : page.blocks)
        if (b.section >= 0) here.insert(b.section);
      shared += here.size() > 1 ? 1 : 0;
    }
    CHECK(shared > 0);
    CHECK(pages.size() < doc.sections.size());
    std::set<int> seen;
    for (const auto& page : layout_document(doc)) {
      std::set<int> here;
      for (const auto& b : page.blocks)
        if (b.section >= 0) here.insert(b.section);
      for (int s : here) {
        CAPTURE(s);
        // Continued from an earlier page only with its figure (and the fields beside it)
        // opening this page.
        if (seen.count(s) == 0) continue;
        CHECK(page.blocks[1].section == s);
        CHECK(std::holds_alternative<Figure>(block_of(doc, page.blocks[1])));
      }
      seen.insert(here.begin(), here.end());
    }
    CHECK(seen.size() == doc.sections.size());
  }

  SUBCASE("3. a section taller than a page flows, with no line of a paragraph alone") {
    const LayoutStyle style;
    const Document doc = sample(2, 14);
    const auto pages = layout_document(doc, style);
    REQUIRE(pages.size() >= 3);
    const double line = style.body_size * style.line_height;
    // A paragraph's lines on each page it spans (a statement set around its figure is in two
    // parts on one page).
    std::map<std::pair<int, int>, std::map<int, double>> lines;
    for (const auto& page : pages)
      for (const auto& b : page.blocks)
        if (b.section >= 0 && std::holds_alternative<Paragraph>(block_of(doc, b)))
          lines[{b.section, b.block}][page.number] += b.rect.height;
    int across = 0;
    for (const auto& [block, on_pages] : lines) {
      if (on_pages.size() < 2) continue;
      ++across;
      for (const auto& [page, height] : on_pages) {
        const auto page_number = page;  // CAPTURE's lambda cannot take a structured binding (clang 14)
        CAPTURE(page_number);
        CHECK(height >= 2 * line - kPt);
      }
    }
    CHECK(across == 0);  // the sample's sentences never end a line: its paragraphs stay whole
  }

  SUBCASE("3b. a paragraph breaks across pages only where a sentence ends, outside parentheses") {
    // Short sentences, some of them in parentheses that run over several lines.
    std::string text;
    for (int i = 0; i < 160; ++i) {
      if (i % 7 == 3) text += "(Une remarque entre parenthèses. Elle continue encore ici. Et se termine là.) ";
      text += fmt::format("Phrase numéro {} du texte, assez longue pour remplir une ligne. ", i);
    }
    Document doc = sample(0);
    doc.breaks = Document::Breaks::between_blocks;
    Section s;
    s.add(Heading{"Texte long", 1});
    s.add(Paragraph{text, false});
    doc.sections.push_back(s);
    const auto pages = layout_document(doc);
    REQUIRE(pages.size() >= 2);
    std::string before;
    for (const auto& page : pages) {
      std::vector<const PlacedText*> lines;
      for (const auto& t : page.texts)
        if (t.ink == Ink::text && t.baseline.y > LayoutStyle{}.margin_top + LayoutStyle{}.header_height) lines.push_back(&t);
      if (lines.empty()) continue;
      for (const auto* t : lines) before += joined(*t) + " ";
      if (page.number == page.count) break;
      std::string last = joined(*lines.back());
      CAPTURE(page.number);
      CAPTURE(last);
      while (!last.empty() && last.back() == ')') last.pop_back();  // ".)": the aside ends too
      CHECK(last.back() == '.');
      int depth = 0;
      for (char c : before) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      CHECK(depth == 0);
    }
  }

  SUBCASE("4. a figure taller than a page is scaled to fit") {
    Document doc = sample(1);
    std::get<Figure>(doc.sections[0].blocks[2]) = Figure{square_scene(2, 40), 1.0};
    const auto pages = layout_document(doc);
    int figures = 0;
    for (const auto& page : pages) {
      check_inside(page, LayoutStyle{});
      figures += static_cast<int>(page.figures.size());
    }
    CHECK(figures == 1);
  }

  SUBCASE("5. a table or a run of fields that a page holds is never split") {
    for (int paragraphs = 1; paragraphs <= 12; ++paragraphs) {
      CAPTURE(paragraphs);
      Document doc = sample(3, paragraphs);
      for (auto& section : doc.sections) {
        for (int k = 0; k < 8; ++k)
          section.add(AnswerLine{fmt::format("x.{}", k), "t_{ab}", "≈ 0.43 (exact: 3/7)"});
      }
      const auto pages = layout_document(doc);
      for (std::size_t s = 0; s < doc.sections.size(); ++s) {
        std::set<int> table_pages, field_pages;
        for (const auto& page : pages) {
          for (const auto& b : page.blocks) {
            if (b.section != static_cast<int>(s)) continue;
            if (std::holds_alternative<AnswerLine>(block_of(doc, b))) table_pages.insert(page.number);
            if (std::holds_alternative<AnswerField>(block_of(doc, b))) field_pages.insert(page.number);
          }
        }
        CAPTURE(s);
        CHECK(table_pages.size() == 1);
        CHECK(field_pages.size() == 1);
      }
    }
  }

  SUBCASE("6. a section starts where the one before ends, unless little of that page is left") {
    // Heading, two paragraphs and the figure (blocks 0 to 3), then fields in numbers that end a
    // section at every height of a page.
    const LayoutStyle style;
    for (int fields = 1; fields <= 40; ++fields) {
      CAPTURE(fields);
      Document doc = sample(3, 2);
      doc.breaks = Document::Breaks::between_blocks;
      for (auto& section : doc.sections)
        for (int k = 0; k < fields; ++k)
          section.add(AnswerField{fmt::format("x.{}", k), "t =", AnswerField::Kind::number, {}});
      const auto pages = layout_document(doc, style);
      const double top = style.margin_top + style.header_height + style.header_gap;
      const double text_height = doc.page.height_pt - style.margin_bottom - top;
      for (std::size_t s = 1; s < doc.sections.size(); ++s) {
        CAPTURE(s);
        int heading_page = 0, previous_end = 0;
        for (const auto& page : pages)
          for (const auto& b : page.blocks) {
            if (b.section == static_cast<int>(s) && b.block == 0) heading_page = page.number;
            if (b.section == static_cast<int>(s) - 1) previous_end = page.number;
          }
        double previous_bottom = 0;
        for (const auto& b : pages[static_cast<std::size_t>(previous_end - 1)].blocks)
          if (b.section == static_cast<int>(s) - 1) previous_bottom = std::max(previous_bottom, b.rect.bottom());
        REQUIRE(heading_page >= previous_end);
        // A fifth of a page (LayoutStyle-independent: layout.cpp's kMaxOpeningWaste), at most,
        // is left blank before a section's opening goes to the next page.
        if (heading_page > previous_end) CHECK(previous_bottom >= top + 0.8 * text_height - kPt);
      }
    }
  }

  SUBCASE("7. an empty document is one page with its header") {
    Document doc = sample(0);
    const auto pages = layout_document(doc);
    REQUIRE(pages.size() == 1);
    CHECK(page_has_text(pages[0], "page 1/1"));
  }
}

TEST_CASE("layout: answer fields are sized to what they hold") {
  const LayoutStyle style;
  Document doc = sample(0);
  Section s;
  using K = AnswerField::Kind;
  s.add(AnswerField{"1.t", "t =", K::number, {}});
  s.add(AnswerField{"1.P", "P =", K::point, {}});
  s.add(AnswerField{"1.Q", "Q =", K::point3, {}});
  s.add(AnswerField{"1.position", "P is", K::choice, {"before", "between", "after"}});
  s.add(AnswerField{"1.faces", "Faces hit:", K::faces,
                    {"x = −1", "x = 1", "y = −1", "y = 1", "z = −1", "z = 1"}});
  s.add(AnswerField{"1.hit", "Does the ray hit?", K::boolean, {}});
  doc.sections.push_back(s);
  const auto pages = layout_document(doc, style);
  REQUIRE(pages.size() == 1);
  const auto& page = pages[0];

  auto boxes_of = [&](const std::string& id) {
    std::vector<PlacedBox> out;
    for (const auto& b : page.boxes)
      if (b.question_id == id) out.push_back(b);
    return out;
  };
  auto values = [](const std::vector<PlacedBox>& boxes) {
    std::vector<std::string> v;
    for (const auto& b : boxes) v.push_back(b.value);
    return v;
  };

  const auto number = boxes_of("1.t");
  REQUIRE(number.size() == 1);
  CHECK(number[0].kind == BoxKind::answer);
  CHECK(number[0].rect.width == doctest::Approx(style.number_box_width).epsilon(1e-12));
  CHECK(number[0].rect.height == doctest::Approx(style.field_box_height).epsilon(1e-12));

  const auto point = boxes_of("1.P");
  CHECK(values(point) == std::vector<std::string>{"x", "y"});
  CHECK(page_has_text(page, "("));
  CHECK(page_has_text(page, ";"));
  CHECK(page_has_text(page, ")"));
  const auto point3 = boxes_of("1.Q");
  CHECK(values(point3) == std::vector<std::string>{"x", "y", "z"});
  for (const auto& b : point3) CHECK(b.rect.width == doctest::Approx(style.point3_box_width).epsilon(1e-12));

  const auto choice = boxes_of("1.position");
  CHECK(values(choice) == std::vector<std::string>{"before", "between", "after"});
  for (const auto& b : choice) {
    CHECK(b.kind == BoxKind::tick);
    CHECK(b.rect.width == doctest::Approx(style.tick_size).epsilon(1e-12));
  }
  CHECK(page_has_text(page, "between"));
  const auto faces = boxes_of("1.faces");
  REQUIRE(faces.size() == 6);
  // Six faces on rows of equal length, in aligned columns.
  std::set<double> rows, columns;
  for (const auto& b : faces) {
    rows.insert(b.rect.y);
    columns.insert(b.rect.x);
  }
  CHECK(rows.size() * columns.size() == 6);
  CHECK(values(boxes_of("1.hit")) == std::vector<std::string>{"true", "false"});
  CHECK(page_has_text(page, "yes"));
  CHECK(page_has_text(page, "no"));

  // The boxes of consecutive fields start on one column, after the widest prompt.
  CHECK(point[0].rect.x > number[0].rect.x);  // after the "("
  CHECK(choice[0].rect.x == doctest::Approx(number[0].rect.x).epsilon(1e-12));
  // Question ids are printed, small, at the right edge.
  for (const char* id : {"1.t", "1.P", "1.Q", "1.position", "1.faces", "1.hit"}) {
    CAPTURE(id);
    CHECK(page_has_text(page, id));
  }
  check_inside(page, style);
}

TEST_CASE("layout: a question asked as a question is on a few wide lines, beside or above its ticks; \"none\" has a row of its own") {
  const LayoutStyle style;
  Document doc = sample(0);
  Section s;
  using K = AnswerField::Kind;
  // Point fields keep the prompt column narrow, as on a ray's sheet.
  s.add(AnswerField{"1.I", "I =", K::point, {}});
  const std::string question =
      "Is A, the origin of the ray drawn on the figure with its direction u, inside the ellipse whose centre C and "
      "semi-axes a and b are given above?";
  s.add(AnswerField{"1.inside", question, K::boolean, {}});
  AnswerField faces{"1.faces", "Sides:", K::faces, {"+x", "+y", "−x", "−y", "none"}};
  faces.last_choice_apart = true;
  s.add(faces);
  doc.sections.push_back(s);
  const auto pages = layout_document(doc, style);
  REQUIRE(pages.size() == 1);
  const auto& page = pages[0];
  std::vector<PlacedBox> inside, sides;
  for (const auto& b : page.boxes) {
    if (b.question_id == "1.inside") inside.push_back(b);
    if (b.question_id == "1.faces") sides.push_back(b);
  }
  REQUIRE(inside.size() == 2);
  REQUIRE(sides.size() == 5);

  SUBCASE("1. the long prompt is on fewer lines than its column would give, its ticks on one row") {
    std::vector<const PlacedText*> lines;
    for (const auto& t : page.texts) {
      const std::string j = joined(t);
      if (!j.empty() && question.find(j) != std::string::npos && j.size() > 3) lines.push_back(&t);
    }
    REQUIRE(!lines.empty());
    CHECK(lines.size() <= 2);
    const double row = page.size.width_pt - style.margin_left - style.margin_right;
    for (const auto* l : lines) {
      CHECK(text_width(l->runs, l->size) > 0.5 * row);  // not a thin column of words
      for (const auto& b : inside)  // above its ticks, or left of them
        CHECK((l->baseline.y < b.rect.y || l->baseline.x + text_width(l->runs, l->size) < b.rect.x));
    }
    CHECK(inside[0].rect.y == doctest::Approx(inside[1].rect.y).epsilon(1e-12));  // yes and no on one row
  }
  SUBCASE("2. the sides in a grid, \"none\" alone on the row below, at the grid's first column") {
    const auto& none = sides.back();
    CHECK(none.value == "none");
    for (std::size_t i = 0; i + 1 < sides.size(); ++i) CHECK(sides[i].rect.y < none.rect.y);
    CHECK(none.rect.x == doctest::Approx(sides[0].rect.x).epsilon(1e-12));
  }
  check_inside(page, style);
}

TEST_CASE("layout: a key's answer lines are a two-column table") {
  Document doc = sample(0);
  doc.student_fields = false;
  Section s;
  s.add(AnswerLine{"2.t_ab", "t_{ab}", "≈ 0.43 (exact: 3/7)"});
  s.add(AnswerLine{"2.I", "I", "(2.14 ; 1.29)"});
  s.add(AnswerLine{"2.intersects", "The segments intersect", "yes"});
  doc.sections.push_back(s);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() == 1);
  double prompt_x = -1, answer_x = -1;
  int answers = 0;
  for (const auto& t : pages[0].texts) {
    if (t.ink == Ink::answer) {
      ++answers;
      if (answer_x < 0) answer_x = t.baseline.x;
      CHECK(t.baseline.x == doctest::Approx(answer_x).epsilon(1e-12));
    }
    if (joined(t) == "The segments intersect") prompt_x = t.baseline.x;
  }
  CHECK(answers == 3);
  CHECK(answer_x > prompt_x);
  // The id is plain text: "2.t_ab" is printed as it is, not as a subscript.
  CHECK(page_has_text(pages[0], "2.t_ab"));
}

TEST_CASE("layout: deterministic") {
  const Document doc = sample(5, 2);
  const auto a = dump(layout_document(doc));
  const auto b = dump(layout_document(doc));
  CHECK(a == b);
  CHECK(a.size() > 1000);
}

TEST_CASE("layout: a figure's fields and a key's answers beside it, when they fit") {
  const LayoutStyle style;
  const double left = style.margin_left, right = PageSize::a4().width_pt - style.margin_right;
  const double width = right - left;

  SUBCASE("a sheet's fields: in a column right of the figure, top-aligned with it, no overlap") {
    const Document doc = sample(1);
    const auto pages = layout_document(doc);
    const LaidOutPage& page = pages[0];
    REQUIRE(page.figures.size() == 1);
    const PageRect fig = page.figures[0].rect;
    CHECK(fig.x == doctest::Approx(left));                      // on the left, not centred
    CHECK(fig.width >= style.figure_min_share * width - kPt);   // never narrower than that
    int boxes = 0;
    for (const PlacedBox& b : page.boxes) {
      if (b.kind == BoxKind::shade) continue;
      ++boxes;
      CAPTURE(b.question_id);
      CHECK(b.rect.x >= fig.right() + kPt);                     // right of the figure
      CHECK(b.rect.y >= fig.y - kPt);                           // from its top down
      CHECK(b.rect.right() <= right + kPt);
    }
    CHECK(boxes == 1 + 2 + 3);  // t, P's two coordinates, the three positions
    // Each field is still a block of its own, beside the figure's.
    int field_blocks = 0;
    for (const PlacedBlock& b : page.blocks)
      if (b.section == 0 && std::holds_alternative<AnswerField>(block_of(doc, b))) {
        ++field_blocks;
        CHECK(b.rect.x >= fig.right() - kPt);
      }
    CHECK(field_blocks == 3);
  }

  SUBCASE("a key's answers: the table beside the figure") {
    Document key = sample(1);
    key.student_fields = false;
    auto& blocks = key.sections[0].blocks;
    blocks.erase(blocks.begin() + 3, blocks.end());  // heading, paragraph, figure
    blocks.emplace_back(AnswerLine{"1.t", "t =", "2/5 = 0.4"});
    blocks.emplace_back(AnswerLine{"1.P", "P =", "(4, 4)"});
    const auto pages = layout_document(key);
    REQUIRE(pages[0].figures.size() == 1);
    const PageRect fig = pages[0].figures[0].rect;
    bool answer_seen = false;
    for (const PlacedText& t : pages[0].texts) {
      if (t.ink != Ink::answer) continue;
      answer_seen = true;
      CHECK(t.baseline.x > fig.right());
      CHECK(t.baseline.y < fig.bottom());
    }
    CHECK(answer_seen);
  }

  SUBCASE("a key's long answers beside the figure: under their prompt, never wrapped") {
    Document key = sample(1);
    key.student_fields = false;
    auto& blocks = key.sections[0].blocks;
    blocks.erase(blocks.begin() + 3, blocks.end());
    const std::string point = "(−5√2/8 ≈ −0.88, −3√2/4 ≈ −1.06)";
    blocks.emplace_back(AnswerLine{"6.Ac", "A_{c} =", point});
    blocks.emplace_back(AnswerLine{"6.N", "\\vec{N} =", "(−0.21, −0.26)"});
    const auto pages = layout_document(key);
    REQUIRE(pages[0].figures.size() == 1);
    const PageRect fig = pages[0].figures[0].rect;
    int answers = 0;
    double prompt_y = 0, answer_y = 0;
    for (const PlacedText& t : pages[0].texts) {
      if (joined(t) == "A =" || joined(t) == "Ac =") prompt_y = t.baseline.y;
      if (t.ink != Ink::answer) continue;
      ++answers;
      CHECK(t.baseline.x > fig.right());  // still beside the figure
      if (joined(t) == point) answer_y = t.baseline.y;
    }
    CHECK(answers == 2);  // one line each: the point whole
    CHECK(answer_y > 0);
    if (prompt_y > 0) CHECK(answer_y > prompt_y);  // on the line under its prompt
  }

  SUBCASE("a figure of two panels keeps its width: its answers go under it") {
    Document key = sample(1);
    key.student_fields = false;
    auto& blocks = key.sections[0].blocks;
    blocks.erase(blocks.begin() + 2, blocks.end());  // heading, paragraph
    Scene two = square_scene();
    two.panels.push_back(two.panels[0]);
    two.links = {"T^{−1}"};
    blocks.emplace_back(Figure{two, 0.9});
    blocks.emplace_back(AnswerLine{"6.t", "t =", "3.56"});
    const auto pages = layout_document(key);
    REQUIRE(pages[0].figures.size() == 1);
    const PageRect fig = pages[0].figures[0].rect;
    CHECK(fig.width == doctest::Approx(0.9 * width));
    for (const PlacedText& t : pages[0].texts)
      if (t.ink == Ink::answer) CHECK(t.baseline.y > fig.bottom());
  }

  SUBCASE("fields too many for the figure's height go below it; the statement beside it, or it is centred") {
    Document doc = sample(1);
    for (int k = 0; k < 30; ++k)
      doc.sections[0].add(AnswerField{fmt::format("1.x{}", k), "x =", AnswerField::Kind::number, {}});
    const auto pages = layout_document(doc);
    const PageRect fig = pages[0].figures[0].rect;
    // The statement is shorter in the column beside the figure than above it: it goes there.
    const auto statement = std::find_if(pages[0].blocks.begin(), pages[0].blocks.end(),
                                        [](const PlacedBlock& b) { return b.section == 0 && b.block == 1; });
    REQUIRE(statement != pages[0].blocks.end());
    CHECK(statement->rect.x >= fig.right() - kPt);
    CHECK(fig.x == doctest::Approx(left));
    // Without a statement before it, the figure is centred as before.
    Document bare = doc;
    bare.sections[0].blocks.erase(bare.sections[0].blocks.begin() + 1);
    const PageRect centred = layout_document(bare)[0].figures[0].rect;
    CHECK(centred.x + centred.width / 2 == doctest::Approx(left + width / 2));
    for (const auto& page : pages)
      for (const PlacedBox& b : page.boxes)
        if (b.kind == BoxKind::answer && page.number == 1) CHECK(b.rect.y >= fig.bottom() - kPt);
  }

  SUBCASE("a field too wide for any column (a 3D point with a long prompt in a narrow page) goes below") {
    Document doc = sample(1);
    doc.page = {300, 841.89};
    auto& blocks = doc.sections[0].blocks;
    blocks.erase(blocks.begin() + 3, blocks.end());
    blocks.emplace_back(AnswerField{"1.Q", "Q =", AnswerField::Kind::point3, {}});
    const auto pages = layout_document(doc);
    const PageRect fig = pages[0].figures[0].rect;
    for (const PlacedBox& b : pages[0].boxes)
      if (b.kind == BoxKind::answer) CHECK(b.rect.y >= fig.bottom() - kPt);
  }
}

TEST_CASE("layout: a statement beside its figure when that makes the exercise shorter") {
  const LayoutStyle style;
  auto with = [](Scene scene, double fraction) {
    Document doc = sample(1);
    std::get<Figure>(doc.sections[0].blocks[2]) = Figure{std::move(scene), fraction};
    return doc;
  };
  auto rect_of = [](const LaidOutPage& page, int section, int block) {
    for (const auto& b : page.blocks)
      if (b.section == section && b.block == block) return b.rect;
    FAIL("block not on the page");
    return PageRect{};
  };

  SUBCASE("1. a tall figure: the statement and the fields in the column on its right") {
    const Document doc = with(square_scene(4, 9), 0.45);
    const auto pages = layout_document(doc);
    REQUIRE(pages.size() == 1);
    const PageRect fig = pages[0].figures.at(0).rect;
    const PageRect statement = rect_of(pages[0], 0, 1);
    CHECK(statement.x >= fig.right() - kPt);
    CHECK(statement.y >= fig.y - kPt);
    for (const PlacedBox& b : pages[0].boxes)
      if (b.kind != BoxKind::shade) CHECK(b.rect.y >= statement.bottom() - kPt);  // fields under it
    check_inside(pages[0], style);
  }

  SUBCASE("2. a wide, low figure: the statement stays above it") {
    const Document doc = with(square_scene(9, 3), 0.9);
    const auto pages = layout_document(doc);
    const PageRect fig = pages[0].figures.at(0).rect;
    CHECK(rect_of(pages[0], 0, 1).bottom() <= fig.y + kPt);
  }

  SUBCASE("2b. a statement too long for the column flows around the figure: its first lines across, the rest beside") {
    Document doc = sample(1);
    std::get<Paragraph>(doc.sections[0].blocks[1]).text = kText + " " + kText + " " + kText;
    std::get<Figure>(doc.sections[0].blocks[2]) = Figure{square_scene(5, 7), 0.55};
    const auto pages = layout_document(doc);
    REQUIRE(pages.size() == 1);
    const PageRect fig = pages[0].figures.at(0).rect;
    int across = 0, beside_figure = 0;
    for (const auto& b : pages[0].blocks) {
      if (b.section != 0 || b.block != 1) continue;
      if (b.rect.x >= fig.right() - kPt) {
        ++beside_figure;
        CHECK(b.rect.y >= fig.y - kPt);
      } else {
        ++across;
        CHECK(b.rect.bottom() <= fig.y + kPt);
      }
    }
    CHECK(across == 1);
    CHECK(beside_figure == 1);
    // Every word of the statement is printed once.
    std::string printed;
    for (const auto& t : pages[0].texts) printed += joined(t) + " ";
    CHECK(printed.find("décimales. Les points") != std::string::npos);
    check_inside(pages[0], style);
  }

  SUBCASE("3. beside its figure when a page holds it; above it when it would leave a page much space") {
    // The first exercise fills most of a page; the second (a key's steps: three paragraphs, a
    // tall figure with the last of them beside it) would not fit in what is left.
    Document doc = sample(2);
    doc.breaks = Document::Breaks::between_blocks;  // a key's: its sections may break
    doc.sections[0] = exercise(1, true, 6);
    doc.sections[1] = exercise(2, true, 3);
    std::get<Figure>(doc.sections[1].blocks[4]) = Figure{square_scene(4, 9), 0.45};
    const auto pages = layout_document(doc);
    REQUIRE(pages.size() == 2);
    // The second exercise opens on the first page (its heading and first steps), its figure on
    // the next with the last step above it and the fields beside it: the first page is not left
    // a third empty, and the figure is not parted from the step it follows.
    bool heading_on_first = false;
    for (const auto& b : pages[0].blocks) heading_on_first = heading_on_first || (b.section == 1 && b.block == 0);
    CHECK(heading_on_first);
    REQUIRE(pages[1].figures.size() == 1);
    const PageRect fig = pages[1].figures[0].rect;
    bool last_step_above = false, fields_beside = false;
    for (const auto& b : pages[1].blocks) {
      if (b.section != 1) continue;
      if (b.block == 3) last_step_above = b.rect.bottom() <= fig.y + kPt;
      if (b.block == 5) fields_beside = b.rect.x >= fig.right() - kPt && b.rect.y >= fig.y - kPt;
      CHECK(b.block >= 3);  // no step parted across the page
    }
    CHECK(last_step_above);
    CHECK(fields_beside);
    for (const auto& page : pages) check_inside(page, style);
  }
}

namespace {

// A section whose figure's data are four times taller than wide, so that the height cap, not
// the width, sets its size; and one with an ordinary figure.
Section tall_exercise(int n) {
  Section s;
  s.add(Heading{fmt::format("Exercise {} — projection", n), 1});
  s.add(Paragraph{kText, false});
  s.add(Figure{square_scene(4, 16), 0.6});
  s.add(AnswerField{fmt::format("{}.t", n), "t =", AnswerField::Kind::number, {}});
  return s;
}


}  // namespace

// The figures of a layout by section, in order: (section, width, height).
std::vector<std::tuple<int, double, double>> figures_by_section(const std::vector<LaidOutPage>& pages) {
  std::vector<std::tuple<int, double, double>> out;
  for (const auto& p : pages) {
    std::size_t k = 0;
    for (const auto& b : p.blocks) {
      if (b.section < 0 || k >= p.figures.size()) continue;
      const PageRect& f = p.figures[k].rect;
      if (std::abs(b.rect.x - f.x) < kPt && std::abs(b.rect.y - f.y) < kPt) {
        out.emplace_back(b.section, f.width, f.height);
        ++k;
      }
    }
  }
  return out;
}

TEST_CASE("layout: a document over its page budget sets some figures smaller, down to a floor") {
  const LayoutStyle style;
  // Documents of an ordinary exercise and two tall ones, repeated, until one whose budget (its
  // pages at full size, less one) smaller figures meet.
  Document doc = sample(0);
  std::vector<LaidOutPage> full, fitted;
  bool found = false;
  for (int n = 1; n <= 12 && !found; ++n) {
    doc.sections.push_back(n % 3 != 1 ? tall_exercise(n) : exercise(n));
    doc.page_budget = 0;
    full = layout_document(doc, style);
    doc.page_budget = static_cast<int>(full.size()) - 1;
    fitted = layout_document(doc, style);
    found = fitted.size() <= full.size() - 1;
  }
  REQUIRE(found);
  CAPTURE(doc.sections.size());
  for (const auto& page : fitted) check_inside(page, style);
  const auto before = figures_by_section(full), after = figures_by_section(fitted);
  REQUIRE(before.size() == doc.sections.size());
  REQUIRE(after.size() == before.size());

  SUBCASE("each figure at its full size, or smaller by no more than the floor; some at full size") {
    int smaller = 0, kept = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
      CAPTURE(i);
      const auto [s0, w0, h0] = before[i];
      const auto [s1, w1, h1] = after[i];
      CHECK(s0 == s1);
      if (w1 < w0 - kPt) {
        ++smaller;
        CHECK(w1 >= style.figure_min_scale * w0 - kPt);
        CHECK(h1 < h0);
      } else {
        ++kept;
        CHECK(std::abs(h1 - h0) < kPt);
      }
    }
    CHECK(smaller > 0);
    CHECK(kept > 0);  // only the sections that need it are set smaller
  }
  SUBCASE("within its budget, the document is laid out as without one") {
    Document unbudgeted = doc;
    unbudgeted.page_budget = 0;
    Document roomy = doc;
    roomy.page_budget = static_cast<int>(full.size());
    CHECK(dump(layout_document(roomy, style)) == dump(full));
    CHECK(dump(layout_document(unbudgeted, style)) == dump(full));
  }
  SUBCASE("past what the floor can do, as few pages as smaller figures reach: the layout for that many") {
    Document tight = doc;
    tight.page_budget = 1;
    const auto squeezed = layout_document(tight, style);
    CHECK(squeezed.size() > 1);
    CHECK(squeezed.size() <= fitted.size());  // at least the page the fitted budget saved
    Document reachable = doc;
    reachable.page_budget = static_cast<int>(squeezed.size());
    CHECK(dump(layout_document(reachable, style)) == dump(squeezed));
  }
}

TEST_CASE("layout: a text measured in an earlier document of the thread gives the pages a fresh measure gives") {
  // A thread keeps the texts it measured by their content (text_measure.cpp) and finds them by
  // their length and ends: two statements alike but for the words inside must be told apart.
  const auto repeat = [](const std::string& word, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += word;
    return s;
  };
  const std::string head = "Les points A, B et C sont donnés, et ", tail = " : calculer t_{ab} puis P.";
  std::string narrow = head, wide = head;
  narrow += repeat("iii ", 40);
  narrow += tail;
  wide += repeat("WWW ", 40);
  wide += tail;
  REQUIRE(narrow.size() == wide.size());
  const auto document = [&](const std::string& text) {
    Document doc = sample(2);
    for (auto& section : doc.sections)
      for (auto& block : section.blocks)
        if (auto* p = std::get_if<Paragraph>(&block)) p->text = text;
    return doc;
  };
  const Document first = document(narrow), second = document(wide);
  std::string fresh;
  std::thread([&] { fresh = dump(layout_document(second)); }).join();  // a thread that measured nothing yet
  const std::string after_first = dump(layout_document(first));
  CHECK(dump(layout_document(second)) == fresh);
  CHECK(after_first != fresh);  // the two texts do break differently: the test can tell
}

TEST_CASE("layout: a row measured in an earlier document of the thread gives the pages a fresh measure gives") {
  // A thread keeps the shapes of answer rows by their content (row_shapes.h): fields alike but
  // for their cells, and the same fields laid out with another style, must be told apart. The
  // narrow combs fit beside their figures, the wide ones go under them: a wide row taken for a
  // narrow one would have the page budget counted short, and no figure set smaller.
  const auto document = [](int integer_cells) {
    Document doc = sample(5);
    for (auto& section : doc.sections)
      for (auto& block : section.blocks)
        if (auto* f = std::get_if<AnswerField>(&block); f && f->kind != AnswerField::Kind::choice) {
          f->integer_cells = integer_cells;
          f->decimals = 2;
        }
    return doc;
  };
  Document narrow = document(1), wide = document(6);
  narrow.page_budget = wide.page_budget = static_cast<int>(layout_document(narrow).size());
  LayoutStyle other;
  other.comb_cell_width = 30;  // the narrow combs then go under their figures too
  std::string fresh, fresh_other;
  std::thread([&] {  // a thread that measured nothing yet
    fresh = dump(layout_document(wide));
    fresh_other = dump(layout_document(narrow, other));
  }).join();
  const std::string after_narrow = dump(layout_document(narrow));
  CHECK(dump(layout_document(wide)) == fresh);
  CHECK(dump(layout_document(narrow, other)) == fresh_other);
  CHECK(dump(layout_document(narrow)) == after_narrow);
  // The test can tell: the wide rows need the figures smaller to keep to the budget (a mutation
  // that shares rows across cell counts, or across styles, fails the checks above).
  Document unbounded = wide;
  unbounded.page_budget = 0;
  CHECK(dump(layout_document(unbounded)) != fresh);
}

TEST_CASE("layout: a row measured in a document of another language gives the pages a fresh measure gives") {
  // A thread's rows are dropped when a document prints other yes/no words or another decimal
  // separator (row_shapes.h): "oui" and "non" are wider than "yes" and "no", so a row of ticks
  // that fits the column beside a figure in English may not in French, and the column is then
  // set wider or under the figure. ',' and '.' are as wide as each other in the layout's font (a
  // French comb measures as an English one), but a separator is any string: one as wide as a
  // word reaches past its comb's last cell. The column's width is scanned through the figure's,
  // so that somewhere a row fits with one document's words or separator and not with the other's.
  const auto document = [](double figure_width, const std::string& separator, const std::string& yes,
                           const std::string& no) {
    Document doc = sample(3);
    for (auto& section : doc.sections) {
      std::vector<Block> blocks;
      for (auto& block : section.blocks) {
        if (auto* f = std::get_if<Figure>(&block)) f->width_fraction = figure_width;
        if (auto* f = std::get_if<AnswerField>(&block)) {
          if (f->kind != AnswerField::Kind::number) continue;
          f->integer_cells = 2;  // "t = □□□,□": the separator before a single decimal cell
          f->decimals = 1;
        }
        blocks.push_back(block);
      }
      section.blocks = std::move(blocks);
      section.add(AnswerField{"b", "Inside?", AnswerField::Kind::boolean, {}});
    }
    doc.decimal_separator = separator;
    doc.words.yes = yes;
    doc.words.no = no;
    return doc;
  };
  // Where the figures stand and how large: whether the rows went beside them, and at what width.
  const auto figures = [](const std::vector<LaidOutPage>& pages) {
    std::string out = fmt::format("{} pages\n", pages.size());
    for (const auto& p : pages)
      for (const auto& f : p.figures) out += fmt::format("figure {} {} {} {}\n", f.rect.x, f.rect.y, f.rect.width, f.rect.height);
    return out;
  };
  // Pages laid out by a thread that measured nothing yet.
  const auto fresh = [](const Document& doc) {
    std::vector<LaidOutPage> pages;
    std::thread([&] { pages = layout_document(doc); }).join();
    return pages;
  };
  std::string differ;  // the documents laid out after another unlike their fresh measure
  int told_words = 0, told_separator = 0;
  for (int permille = 200; permille <= 950; permille += 2) {
    const double w = permille / 1000.0;
    const Document english = document(w, ".", "yes", "no"), french = document(w, ",", "oui", "non");
    // Each unlike the one before it in one thing only: the thread's rows must be dropped for each.
    const Document french_words = document(w, ".", "oui", "non");
    const Document wide_separator = document(w, "une virgule", "oui", "non");
    const std::vector<std::tuple<std::string, const Document*, const Document*>> pairs = {
        {"French after English", &english, &french},
        {"French words after English", &english, &french_words},
        {"a wide separator after French", &french, &wide_separator}};
    for (const auto& [name, earlier, later] : pairs) {
      const Document& first = *earlier;
      const Document& second = *later;
      std::string after;
      std::thread([&] {
        (void)layout_document(first);
        after = dump(layout_document(second));
      }).join();
      if (after != dump(fresh(second))) differ += fmt::format("{} at {}; ", name, w);
    }
    told_words += figures(fresh(english)) != figures(fresh(french_words));
    told_separator += figures(fresh(french)) != figures(fresh(wide_separator));
  }
  CHECK(differ == "");
  // The test can tell: at some widths the words, and the separator, set the figures otherwise
  // (a mutation that keeps the rows across either fails the check above).
  CHECK(told_words > 0);
  CHECK(told_separator > 0);
}
