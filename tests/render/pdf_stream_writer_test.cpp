#include "render/pdf_stream_writer.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "render/pdf_document.h"
#include "sample_document.h"

using namespace epure::render;

namespace {

using testing::sample_document;

PdfMetadata metadata() {
  PdfMetadata m;
  m.title = "Rayon et cercle — corrigé";
  m.creator = "epure test";
  m.date = 1700000000;
  return m;
}

std::int64_t integer(std::string_view s) {
  std::int64_t v = -1;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

// The PDF read back the way a viewer finds its objects: startxref, the table, then each object
// where its entry says (not by searching the text). Returns each object's text, by number.
std::map<std::int64_t, std::string> objects(const std::string& pdf) {
  const std::size_t s = pdf.rfind("startxref\n");
  REQUIRE(s != std::string::npos);
  const auto table = static_cast<std::size_t>(integer(std::string_view(pdf).substr(s + 10)));
  REQUIRE(pdf.compare(table, 7, "xref\n0 ") == 0);
  const std::int64_t count = integer(std::string_view(pdf).substr(table + 7));
  const std::size_t entries = pdf.find('\n', table + 7) + 1;
  const std::size_t trailer = entries + static_cast<std::size_t>(count) * 20;
  REQUIRE(pdf.compare(trailer, 8, "trailer\n") == 0);
  CHECK(pdf.find(fmt::format("/Size {}\n", count), trailer) != std::string::npos);
  std::map<std::int64_t, std::string> found;
  for (std::int64_t i = 0; i < count; ++i) {
    const std::string_view entry = std::string_view(pdf).substr(entries + static_cast<std::size_t>(i) * 20, 20);
    REQUIRE(entry.substr(18) == " \n");
    if (entry[17] != 'n') continue;
    const auto at = static_cast<std::size_t>(integer(entry.substr(0, 10)));
    CAPTURE(i);
    const std::string header = fmt::format("{} 0 obj\n", i);
    REQUIRE(pdf.compare(at, header.size(), header) == 0);
    const std::size_t end = pdf.find("endobj\n", at);
    REQUIRE(end != std::string::npos);
    found[i] = pdf.substr(at + header.size(), end - at - header.size());
  }
  return found;
}

// The numbers in an /Annots [ a 0 R b 0 R … ] array.
std::vector<std::int64_t> annots(const std::string& page) {
  std::vector<std::int64_t> refs;
  const std::size_t at = page.find("/Annots [");
  if (at == std::string::npos) return refs;
  const std::size_t end = page.find(']', at);
  std::string_view list = std::string_view(page).substr(at + 9, end - at - 9);
  while (true) {
    const std::size_t digit = list.find_first_of("0123456789");
    if (digit == std::string_view::npos) break;
    list.remove_prefix(digit);
    refs.push_back(integer(list));
    const std::size_t r = list.find(" 0 R");
    REQUIRE(r != std::string_view::npos);
    list.remove_prefix(r + 4);
  }
  return refs;
}

}  // namespace

TEST_CASE("pdf links: annotations written into cairo's stream, every object where the table says") {
  const Document doc = sample_document(3);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  const double height = pages[0].size.height_pt;
  const std::vector<PageLink> first{{0, {50, 60, 200, 14}, "explore.html#K7QF-3M2X.1"},
                                    {0, {50, 300, 200, 14}, "explore.html#K7QF-3M2X.2"},
                                    {1, {50.25, 80.5, 199.5, 14}, "explore.html#K7QF-3M2X.3"}};
  const std::vector<PageLink> second{{1, {10, 20, 30, 40}, "../explore.html#K7QF-3M2Y.1"}};

  std::string pdf;
  PdfDocument doc_pdf(string_sink(pdf), metadata());
  doc_pdf.add(pages, "K7QF-3M2X", true, {}, first);
  doc_pdf.add_blank(PageSize::a4(), "K7QF-3M2X");
  doc_pdf.add(pages, "K7QF-3M2Y", true, {}, second);
  doc_pdf.finish();
  CHECK(doc_pdf.links() == 4);

  const auto all = objects(pdf);
  // the pages in order, by cairo's "% <number>" comment
  std::vector<std::string> page_objects;
  for (int number = 1;; ++number) {
    const std::string mark = fmt::format("<< /Type /Page % {}\n", number);
    std::string text;
    for (const auto& [n, body] : all)
      if (body.rfind(mark, 0) == 0) text = body;
    if (text.empty()) break;
    page_objects.push_back(text);
  }
  REQUIRE(page_objects.size() == 2 * pages.size() + 1);

  // which page holds which link: the first document's pages 1 and 2, the second's page 2
  const auto uris_on = [&](std::size_t page) {
    std::vector<std::string> uris;
    for (std::int64_t ref : annots(page_objects[page])) {
      REQUIRE(all.count(ref) == 1);
      const std::string& a = all.at(ref);
      CHECK(a.find("/Type /Annot") != std::string::npos);
      CHECK(a.find("/Subtype /Link") != std::string::npos);
      CHECK(a.find("/Border [ 0 0 0 ]") != std::string::npos);
      const std::size_t u = a.find("/URI (");
      REQUIRE(u != std::string::npos);
      uris.push_back(a.substr(u + 6, a.find(')', u) - u - 6));
    }
    return uris;
  };
  CHECK(uris_on(0) == std::vector<std::string>{"explore.html#K7QF-3M2X.1", "explore.html#K7QF-3M2X.2"});
  CHECK(uris_on(1) == std::vector<std::string>{"explore.html#K7QF-3M2X.3"});
  for (std::size_t p = 2; p < page_objects.size(); ++p)
    if (p != pages.size() + 2) CHECK(uris_on(p).empty());
  CHECK(uris_on(pages.size() + 2) == std::vector<std::string>{"../explore.html#K7QF-3M2Y.1"});

  // the layout's rectangle (from the top left) in PDF's user space (from the bottom left), two
  // decimals at most
  CHECK(pdf.find(fmt::format("/Rect [ 50 {:.2f} 250 {:.2f} ]", height - 74, height - 60)) != std::string::npos);
  CHECK(pdf.find(fmt::format("/Rect [ 50.25 {:.2f} 249.75 {:.2f} ]", height - 94.5, height - 80.5)) !=
        std::string::npos);

  // the same pages and links, the same bytes
  std::string again;
  PdfDocument twice(string_sink(again), metadata());
  twice.add(pages, "K7QF-3M2X", true, {}, first);
  twice.add_blank(PageSize::a4(), "K7QF-3M2X");
  twice.add(pages, "K7QF-3M2Y", true, {}, second);
  twice.finish();
  CHECK(again == pdf);
}

TEST_CASE("pdf links: without links, the same bytes whether the sink can overwrite or not") {
  const Document doc = sample_document(2);
  const auto pages = layout_document(doc);
  std::string through, plain;
  {
    PdfDocument pdf(string_sink(through), metadata());
    pdf.add(pages, "K7QF-3M2X", true);
    pdf.finish();
    CHECK(pdf.links() == 0);
  }
  {
    // without the ability to overwrite: nothing is held or rewritten
    PdfDocument pdf(PdfSink{[&](std::string_view b) { plain.append(b); }, {}}, metadata());
    pdf.add(pages, "K7QF-3M2X", true);
    pdf.finish();
  }
  CHECK(through == plain);
  CHECK(through.find("/Annots") == std::string::npos);
  objects(through);
}

TEST_CASE("pdf links: the URI as a PDF string, escaped") {
  const Document doc = sample_document(1);
  const auto pages = layout_document(doc);
  const std::vector<PageLink> links{{0, {0, 0, 10, 10}, "a(b)\\c d\xc3\xa9"}};
  const std::string pdf = pages_to_pdf(pages, doc.sheet_id, metadata(), {}, links);
  CHECK(pdf.find("/URI (a\\(b\\)\\\\c d\\303\\251)") != std::string::npos);
  objects(pdf);
}

TEST_CASE("pdf links: what cannot be written whole is an error, not a file without its links") {
  const Document doc = sample_document(1);
  const auto pages = layout_document(doc);
  const std::vector<PageLink> links{{0, {0, 0, 10, 10}, "x"}};

  SUBCASE("1. a link past the document's pages") {
    const std::vector<PageLink> far{{static_cast<int>(pages.size()), {0, 0, 10, 10}, "x"}};
    CHECK_THROWS_AS(pages_to_pdf(pages, doc.sheet_id, metadata(), {}, far), std::runtime_error);
  }
  SUBCASE("2. a sink that cannot overwrite") {
    PdfDocument pdf(PdfSink{[](std::string_view) {}, {}}, metadata());
    CHECK_THROWS_AS(pdf.add(pages, doc.sheet_id, false, {}, links), std::logic_error);
  }
  SUBCASE("3. a page that is not cairo's") {
    std::string out;
    PdfStreamWriter writer(string_sink(out));
    writer.begin_page(1, 842, links);
    writer.write("1 0 obj\n<< /Type /Pages >>\nendobj\n");
    CHECK_THROWS_WITH_AS(writer.end_page(), doctest::Contains("cannot add the PDF's links"), std::runtime_error);
  }
  SUBCASE("4. a page object that is not the last thing written") {
    std::string out;
    PdfStreamWriter writer(string_sink(out));
    writer.begin_page(1, 842, links);
    writer.write("3 0 obj\n<< /Type /Page % 1\n   /Parent 1 0 R\n>>\nendobj\n4 0 obj\n   12\nendobj\n");
    CHECK_THROWS_AS(writer.end_page(), std::runtime_error);
  }
  // a page that cairo wrote as described, then trailers that are not as cairo writes them
  const std::string page = "%PDF-1.5\n1 0 obj\n<< /Type /Page % 1\n   /Parent 2 0 R\n>>\nendobj\n";
  const auto with_trailer = [&](const std::string& tail) {
    std::string out;
    PdfStreamWriter writer(string_sink(out));
    writer.begin_page(1, 842, links);
    writer.write(page);
    writer.end_page();
    writer.begin_trailer();
    writer.write(tail);
    writer.finish();
    return out;
  };
  const std::string objects_2 = "2 0 obj\n<< /Type /Pages /Kids [ 1 0 R ] /Count 1 >>\nendobj\n";
  const auto table = [&](std::size_t at) {
    return fmt::format("xref\n0 3\n0000000000 65535 f \n0000000009 00000 n \n{:010} 00000 n \n", at);
  };
  const std::size_t at2 = page.size();
  const std::size_t xref = at2 + objects_2.size();
  SUBCASE("5. cairo's trailer, rewritten: the new object counted and found") {
    const std::string out = with_trailer(objects_2 + table(at2) + "trailer\n<< /Size 3\n   /Root 9 0 R\n>>\nstartxref\n" +
                                         std::to_string(xref) + "\n%%EOF\n");
    const auto all = objects(out);
    CHECK(all.size() == 3);
    CHECK(annots(all.at(1)) == std::vector<std::int64_t>{3});
    CHECK(all.at(3).find("/Subtype /Link") != std::string::npos);
  }
  SUBCASE("6. startxref not where the table is") {
    CHECK_THROWS_AS(with_trailer(objects_2 + table(at2) + "trailer\n<< /Size 3 >>\nstartxref\n12\n%%EOF\n"),
                    std::runtime_error);
  }
  SUBCASE("7. /Size not the table's count") {
    CHECK_THROWS_AS(with_trailer(objects_2 + table(at2) + "trailer\n<< /Size 4 >>\nstartxref\n" +
                                 std::to_string(xref) + "\n%%EOF\n"),
                    std::runtime_error);
  }
  SUBCASE("8. no table at all") {
    CHECK_THROWS_AS(with_trailer(objects_2), std::runtime_error);
  }
  SUBCASE("9. a table in two subsections") {
    CHECK_THROWS_AS(with_trailer(objects_2 + "xref\n1 2\n0000000009 00000 n \n"), std::runtime_error);
  }
  SUBCASE("10. a bookmark on a page cairo never wrote") {
    std::string out;
    PdfStreamWriter writer(string_sink(out));
    writer.add_run({"K7QF-3M2X", 1, true, true});
    CHECK_THROWS_WITH_AS(writer.begin_trailer(), doctest::Contains("did not write"), std::runtime_error);
  }
  SUBCASE("11. a catalog that is not cairo's last object") {
    std::string out;
    PdfStreamWriter writer(string_sink(out));
    writer.add_run({"K7QF-3M2X", 1, true, false});
    writer.begin_page(1, 842, {});
    writer.write(page);
    writer.end_page();
    writer.begin_trailer();
    CHECK_THROWS_AS(writer.write("2 0 obj\n<< /Type /Catalog\n   /Pages 3 0 R\n>>\nendobj\n4 0 obj\n<< >>\nendobj\nxref\n"),
                    std::runtime_error);
  }
}

TEST_CASE("pdf stream: with neither links nor names, cairo's bytes pass through untouched") {
  const std::string cairo = "%PDF-1.5\n1 0 obj\n<< /Type /Page % 1\n   /Parent 2 0 R\n>>\nendobj\n"
                            "2 0 obj\n<< /Type /Catalog\n   /Pages 3 0 R\n>>\nendobj\nxref\n0 1\n";
  std::string out;
  PdfStreamWriter writer(PdfSink{[&](std::string_view b) { out.append(b); }, {}});
  writer.add_run({"", 1, true, true});  // an unnamed page: no label, no bookmark
  writer.begin_page(1, 842, {});
  writer.write(cairo.substr(0, 60));
  writer.end_page();
  writer.begin_trailer();
  writer.write(cairo.substr(60));
  writer.finish();
  CHECK(out == cairo);
}

TEST_CASE("pdf stream: bookmarks and page labels, in the catalog and where the table says") {
  const Document doc = sample_document(3);
  const auto pages = layout_document(doc);
  REQUIRE(pages.size() >= 2);
  const int n = static_cast<int>(pages.size());
  const std::vector<PageLink> link{{1, {50, 80, 200, 14}, "explore.html#K7QF-3M2X.2"}};

  std::string pdf;
  PdfDocument out(string_sink(pdf), metadata());
  out.add(pages, "K7QF-3M2X", true, {}, link);
  out.add_blank(PageSize::a4(), "K7QF-3M2X");
  out.add(pages, "Élève 2 — π", true);  // not ASCII: UTF-16BE
  out.add(pages, "K7QF-3M2Z", false);   // named pages, no bookmark
  out.finish();
  const auto all = objects(pdf);

  // the pages' object numbers, in order
  std::vector<std::int64_t> page_objects;
  for (int number = 1;; ++number) {
    const std::string mark = fmt::format("<< /Type /Page % {}\n", number);
    std::int64_t found = -1;
    for (const auto& [k, body] : all)
      if (body.rfind(mark, 0) == 0) found = k;
    if (found < 0) break;
    page_objects.push_back(found);
  }
  REQUIRE(page_objects.size() == static_cast<std::size_t>(3 * n + 1));

  // the catalog points at the outline and the labels; cairo's own catalog entries are kept
  std::string catalog;
  for (const auto& [k, body] : all)
    if (body.rfind("<< /Type /Catalog\n", 0) == 0) catalog = body;
  REQUIRE(!catalog.empty());
  CHECK(catalog.find("/Pages ") != std::string::npos);
  const auto ref_after = [](const std::string& text, std::string_view key) {
    const std::size_t at = text.find(key);
    REQUIRE(at != std::string::npos);
    return integer(std::string_view(text).substr(at + key.size() + 1));
  };
  const std::string& outline = all.at(ref_after(catalog, "/Outlines"));
  CHECK(outline.find("/Type /Outlines") != std::string::npos);
  CHECK(ref_after(outline, "/Count") == 2);

  // two bookmarks, in order, each opening its document's first page
  const std::string& first = all.at(ref_after(outline, "/First"));
  const std::string& last = all.at(ref_after(outline, "/Last"));
  CHECK(ref_after(first, "/Next") == ref_after(outline, "/Last"));
  CHECK(ref_after(last, "/Prev") == ref_after(outline, "/First"));
  CHECK(first.find("/Prev") == std::string::npos);
  CHECK(last.find("/Next") == std::string::npos);
  CHECK(first.find("/Title (K7QF-3M2X)") != std::string::npos);
  // "Élève 2 — π": É (00C9), è (00E8), the dash (2014), π (03C0)
  CHECK(last.find("/Title <FEFF00C9006C00E8007600650020003200202014002003C0>") != std::string::npos);
  CHECK(first.find(fmt::format("/Dest [{} 0 R /XYZ null null 0]", page_objects[0])) != std::string::npos);
  CHECK(last.find(fmt::format("/Dest [{} 0 R /XYZ null null 0]", page_objects[static_cast<std::size_t>(n + 1)])) !=
        std::string::npos);

  // a label per page: "<name> k/n", the blank page its document's name
  const std::string& labels = all.at(ref_after(catalog, "/PageLabels"));
  CHECK(labels.find(fmt::format("   0 << /P (K7QF-3M2X 1/{}) >>\n", n)) != std::string::npos);
  CHECK(labels.find(fmt::format("   {} << /P (K7QF-3M2X {}/{}) >>\n", n - 1, n, n)) != std::string::npos);
  CHECK(labels.find(fmt::format("   {} << /P (K7QF-3M2X) >>\n", n)) != std::string::npos);
  CHECK(labels.find(fmt::format("   {} << /P <FEFF00C9006C00E8007600650020003200202014002003C000200031002F", n + 1)) !=
        std::string::npos);
  CHECK(labels.find(fmt::format("   {} << /P (K7QF-3M2Z {}/{}) >>\n", 3 * n, n, n)) != std::string::npos);
  CHECK(testing::count(labels, " << /P ") == 3 * n + 1);

  // the link still where it was, numbered before the outline's objects
  CHECK(annots(all.at(page_objects[1])).size() == 1);
}
