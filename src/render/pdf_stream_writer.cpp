#include "render/pdf_stream_writer.h"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <utility>

#include "render/utf8.h"

#include <fmt/format.h>

namespace epure::render {
namespace {

// An object number's field: wide enough for any object number a PDF can have (PDF's offsets
// take ten digits too); the number is right-aligned, so the object starts at its first digit.
constexpr std::size_t kField = 10;
const std::string kBlankField(kField, ' ');
// A dictionary object's end as cairo writes it (a page's, the catalog's); a page's /Annots entry
// goes before it.
constexpr std::string_view kDictionaryEnd = ">>\nendobj\n";
// The last object's end and the cross-reference table's start, as cairo writes them (binary
// stream data that happened to hold these twelve bytes would be caught by the startxref check).
constexpr std::string_view kTableStart = "endobj\nxref\n";
// The start of cairo's catalog; /Outlines and /PageLabels go right after it.
constexpr std::string_view kCatalog = "<< /Type /Catalog\n";
// More than a catalog can be: what follows kCatalog is its last lines, then the table.
constexpr std::size_t kLargestCatalog = 64 * 1024;
// A cross-reference entry's offset has ten digits.
constexpr std::uint64_t kLargestOffset = 9'999'999'999;

[[noreturn]] void fail(std::string_view why) {
  throw std::runtime_error(fmt::format("cannot add the PDF's links, bookmarks and labels: {}", why));
}

// A PDF number with at most two decimals and no trailing zeros ("595.28", "60", "-3.5").
std::string number(double v) {
  std::string s = fmt::format("{:.2f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

// A PDF literal string: the delimiters and the backslash escaped, bytes outside printable
// ASCII as octal escapes (a URI is 7-bit ASCII anyway).
std::string literal(std::string_view text) {
  std::string s = "(";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '(' || c == ')' || c == '\\') {
      s += '\\';
      s += c;
    } else if (u < 0x20 || u > 0x7e) {
      s += fmt::format("\\{:03o}", u);
    } else {
      s += c;
    }
  }
  return s + ")";
}

// A PDF text string (a bookmark's title, a page label): a literal string when it is printable
// ASCII, else UTF-16BE with its byte order mark, in hexadecimal, as PDF asks of other text.
std::string text_string(std::string_view utf8_text) {
  const bool ascii = std::all_of(utf8_text.begin(), utf8_text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u <= 0x7e;
  });
  if (ascii) return literal(utf8_text);
  std::string s = "<FEFF";
  for (std::size_t i = 0; i < utf8_text.size();) {
    const utf8::Decoded d = utf8::decode(utf8_text, i);
    i += d.length;
    if (d.cp < 0x10000) {
      s += fmt::format("{:04X}", static_cast<std::uint32_t>(d.cp));
    } else {
      const std::uint32_t v = static_cast<std::uint32_t>(d.cp) - 0x10000;
      s += fmt::format("{:04X}{:04X}", 0xD800 + (v >> 10), 0xDC00 + (v & 0x3FF));
    }
  }
  return s + ">";
}

// A borderless /Link whose action opens the URI; its number field left blank.
std::string annotation(const PageLink& link, double height_pt) {
  const PageRect& r = link.rect;
  return fmt::format(
      "{} 0 obj\n<< /Type /Annot\n   /Subtype /Link\n   /Rect [ {} {} {} {} ]\n   /Border [ 0 0 0 ]\n"
      "   /A << /S /URI /URI {} >>\n>>\nendobj\n",
      kBlankField, number(r.x), number(height_pt - r.bottom()), number(r.right()), number(height_pt - r.y),
      literal(link.uri));
}

std::string field(std::int64_t n) {
  std::string digits = std::to_string(n);
  if (digits.size() > kField) fail(fmt::format("object number {} is too large", n));
  return std::string(kField - digits.size(), ' ') + digits;
}

std::optional<std::int64_t> integer(std::string_view s) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v < 0) return std::nullopt;
  return v;
}

}  // namespace

PdfSink string_sink(std::string& bytes) {
  return {[&bytes](std::string_view b) { bytes.append(b); },
          [&bytes](std::uint64_t offset, std::string_view b) {
            if (offset + b.size() > bytes.size()) throw std::logic_error("overwrite past the end");
            bytes.replace(offset, b.size(), b);
          }};
}

PdfStreamWriter::PdfStreamWriter(PdfSink sink) : sink_(std::move(sink)) {}

void PdfStreamWriter::emit(std::string_view bytes) {
  sink_.write(bytes);
  out_ += bytes.size();
}

void PdfStreamWriter::write(std::string_view bytes) {
  in_ += bytes.size();
  if (holding_) {
    page_bytes_.append(bytes);
  } else if (trailer_ != Trailer::off) {
    trailer_bytes(bytes);
  } else {
    emit(bytes);
  }
}

void PdfStreamWriter::add_run(PageRun run) {
  if (trailer_ != Trailer::off) throw std::logic_error("PdfStreamWriter: add_run after the pages");
  if (run.pages < 1) throw std::logic_error("PdfStreamWriter: a run of no pages");
  const int first = run_pages_ + 1;
  run_pages_ += run.pages;
  if (!run.label.empty()) any_label_ = true;
  if (run.outline && !run.label.empty()) ++bookmarks_;
  else run.outline = false;
  runs_.push_back({std::move(run), first, 0});
}

void PdfStreamWriter::begin_page(int number, double height_pt, std::span<const PageLink> links) {
  if (holding_ || trailer_ != Trailer::off) throw std::logic_error("PdfStreamWriter: begin_page out of order");
  // the newest runs are the ones still being written: a bookmarked run opening on this page is
  // among the last few
  pages_written_ = std::max(pages_written_, number);
  wants_object_ = false;
  for (auto r = runs_.rbegin(); r != runs_.rend() && r->first_page >= number; ++r)
    if (r->first_page == number && r->names.outline) wants_object_ = true;
  if (links.empty() && !wants_object_) return;
  if (!links.empty() && !sink_.overwrite)
    throw std::logic_error("PdfStreamWriter: links need a sink that can overwrite");
  holding_ = true;
  page_number_ = number;
  page_height_ = height_pt;
  page_links_.assign(links.begin(), links.end());
  page_bytes_.clear();
}

void PdfStreamWriter::end_page() {
  if (!holding_) return;
  holding_ = false;
  // cairo's page object, the last thing it wrote for the page
  const std::string header = fmt::format(" 0 obj\n<< /Type /Page % {}\n", page_number_);
  const std::size_t at = page_bytes_.rfind(header);
  const std::size_t size = page_bytes_.size();
  if (at == std::string::npos || size < kDictionaryEnd.size() + 1 ||
      std::string_view(page_bytes_).substr(size - kDictionaryEnd.size()) != kDictionaryEnd ||
      page_bytes_[size - kDictionaryEnd.size() - 1] != '\n' || page_bytes_.find("endobj", at) != size - 7)
    fail(fmt::format("page {}: cairo's page object is not the last thing it wrote for the page", page_number_));

  if (wants_object_) {
    std::size_t digits = at;
    while (digits > 0 && page_bytes_[digits - 1] >= '0' && page_bytes_[digits - 1] <= '9') --digits;
    const auto object = integer(std::string_view(page_bytes_).substr(digits, at - digits));
    if (!object || *object < 1 || (digits > 0 && page_bytes_[digits - 1] != '\n'))
      fail(fmt::format("page {}: no object number before cairo's page object", page_number_));
    for (auto r = runs_.rbegin(); r != runs_.rend() && r->first_page >= page_number_; ++r)
      if (r->first_page == page_number_ && r->names.outline) r->page_object = *object;
  }
  if (page_links_.empty()) {
    emit(page_bytes_);
    page_bytes_.clear();
    return;
  }
  emit(std::string_view(page_bytes_).substr(0, size - kDictionaryEnd.size()));
  std::string annots = "   /Annots [";
  const std::uint64_t annots_at = out_ + annots.size() + 1;
  for (std::size_t k = 0; k < page_links_.size(); ++k) annots.append(" ").append(kBlankField).append(" 0 R");
  annots += " ]\n";
  emit(annots);
  emit(kDictionaryEnd);
  const auto first = static_cast<std::uint32_t>(annotations_.size());
  for (const PageLink& link : page_links_) {
    annotations_.push_back(out_);
    emit(annotation(link, page_height_));
  }
  pages_.push_back({in_, out_ - in_, annots_at, first, static_cast<std::uint32_t>(page_links_.size())});
  page_links_.clear();
}

bool PdfStreamWriter::adds_catalog_entries() const { return any_label_ || bookmarks_ > 0; }

void PdfStreamWriter::begin_trailer() {
  if (holding_) throw std::logic_error("PdfStreamWriter: begin_trailer inside a page");
  for (const Run& run : runs_)
    if (run.names.outline && run.page_object == 0)
      fail(fmt::format("the bookmark '{}' opens page {}, which cairo did not write", run.names.label, run.first_page));
  if (!annotations_.empty() || adds_catalog_entries()) trailer_ = Trailer::seeking;
}

std::size_t PdfStreamWriter::find_or_pass(std::string_view mark) {
  const std::size_t at = pending_.find(mark);
  if (at != std::string::npos) return at;
  // all but a possible start of the mark, which the next bytes may complete
  const std::size_t keep = std::min(pending_.size(), mark.size() - 1);
  emit(std::string_view(pending_).substr(0, pending_.size() - keep));
  pending_.erase(0, pending_.size() - keep);
  return std::string::npos;
}

void PdfStreamWriter::trailer_bytes(std::string_view bytes) {
  pending_.append(bytes);
  if (trailer_ == Trailer::seeking && adds_catalog_entries()) {
    // up to the catalog's first line, which is where its new entries go
    const std::size_t at = find_or_pass(kCatalog);
    if (at == std::string::npos) return;
    emit(std::string_view(pending_).substr(0, at + kCatalog.size()));
    pending_.erase(0, at + kCatalog.size());
    trailer_ = Trailer::catalog;
  }
  if (trailer_ == Trailer::catalog) {
    // the rest of the catalog, held until the table says how many objects cairo wrote
    const std::size_t at = pending_.find(kTableStart);
    if (at == std::string::npos) {
      if (pending_.size() > kLargestCatalog) fail("cairo's catalog is not followed by its cross-reference table");
      return;
    }
    const std::size_t table = at + std::string_view("endobj\n").size();
    catalog_rest_ = pending_.substr(0, table);
    if (catalog_rest_.find("endobj") != at || catalog_rest_.find(" obj\n") != std::string::npos ||
        catalog_rest_.size() < kDictionaryEnd.size() || catalog_rest_.compare(catalog_rest_.size() - kDictionaryEnd.size(), kDictionaryEnd.size(), kDictionaryEnd) != 0)
      fail("cairo's catalog is not its last object");
    if (catalog_rest_.find("/Outlines") != std::string::npos || catalog_rest_.find("/PageLabels") != std::string::npos)
      fail("cairo's catalog has an outline or page labels of its own");
    table_cairo_ = in_ - (pending_.size() - table);
    pending_.erase(0, table);
    trailer_ = Trailer::table;
  }
  if (trailer_ == Trailer::seeking) {
    const std::size_t at = find_or_pass(kTableStart);
    if (at == std::string::npos) return;
    const std::size_t table = at + std::string_view("endobj\n").size();
    emit(std::string_view(pending_).substr(0, table));
    table_cairo_ = in_ - (pending_.size() - table);
    table_out_ = out_;
    pending_.erase(0, table);
    trailer_ = Trailer::table;
  }
  std::size_t from = 0;
  for (std::size_t nl = pending_.find('\n'); nl != std::string::npos; nl = pending_.find('\n', from)) {
    trailer_line(std::string_view(pending_).substr(from, nl - from));
    from = nl + 1;
  }
  pending_.erase(0, from);
}

void PdfStreamWriter::trailer_line(std::string_view line) {
  const auto added = static_cast<std::int64_t>(annotations_.size() + document_objects());
  switch (expect_) {
    case Expect::header:
      if (line != "xref") fail("cairo's cross-reference table not found");
      if (!adds_catalog_entries()) emit("xref\n");  // else after the catalog and the new objects
      expect_ = Expect::subsection;
      return;
    case Expect::subsection: {
      const auto n = line.substr(0, 2) == "0 " ? integer(line.substr(2)) : std::nullopt;
      if (!n || *n < 1) fail(fmt::format("unexpected cross-reference subsection '{}'", line));
      objects_ = *n;
      if (adds_catalog_entries()) {
        write_catalog_and_objects();
        table_out_ = out_;
        emit("xref\n");
      }
      emit(fmt::format("0 {}\n", objects_ + added));
      expect_ = Expect::entries;
      return;
    }
    case Expect::entries: {
      // "oooooooooo ggggg n " (20 bytes with the end of line)
      const auto offset = integer(line.substr(0, kField));
      if (line.size() != 19 || !offset || line[10] != ' ' || line[16] != ' ' || line[18] != ' ' ||
          (line[17] != 'n' && line[17] != 'f'))
        fail(fmt::format("unexpected cross-reference entry '{}'", line));
      if (line[17] == 'n') {
        // moved by what was inserted before it: the pages linked before the object starts
        const auto after = std::upper_bound(pages_.begin(), pages_.end(), static_cast<std::uint64_t>(*offset),
                                            [](std::uint64_t o, const LinkedPage& p) { return o < p.cairo_end; });
        const std::uint64_t moved = *offset + (after == pages_.begin() ? 0 : std::prev(after)->shift);
        if (moved > kLargestOffset) fail("the file is larger than a cross-reference table can address");
        emit(fmt::format("{:010}{}\n", moved, line.substr(kField)));
      } else {
        emit(line);
        emit("\n");
      }
      if (++entries_ < objects_) return;
      for (std::size_t j = 0; j < annotations_.size(); ++j) {
        const std::int64_t n = objects_ + static_cast<std::int64_t>(j);
        const std::uint64_t at = annotations_[j] + kField - std::to_string(n).size();
        emit(fmt::format("{:010} 00000 n \n", at));
      }
      for (const std::uint64_t at : document_offsets_) emit(fmt::format("{:010} 00000 n \n", at));
      document_offsets_ = {};
      expect_ = Expect::trailer;
      return;
    }
    case Expect::trailer: {
      if (line == "startxref") {
        if (!size_written_) fail("no /Size in cairo's trailer");
        emit("startxref\n");
        expect_ = Expect::startxref;
        return;
      }
      const std::size_t at = line.find("/Size ");
      if (at == std::string_view::npos) {
        emit(line);
        emit("\n");
        return;
      }
      std::size_t end = at + 6;
      while (end < line.size() && line[end] >= '0' && line[end] <= '9') ++end;
      if (integer(line.substr(at + 6, end - at - 6)) != objects_) fail(fmt::format("unexpected trailer '{}'", line));
      emit(fmt::format("{}/Size {}{}\n", line.substr(0, at), objects_ + added, line.substr(end)));
      size_written_ = true;
      return;
    }
    case Expect::startxref:
      if (integer(line) != static_cast<std::int64_t>(table_cairo_))
        fail(fmt::format("cairo's startxref {} is not where its table was found ({})", line, table_cairo_));
      emit(fmt::format("{}\n", table_out_));
      expect_ = Expect::eof;
      return;
    case Expect::eof:
      if (line != "%%EOF") fail(fmt::format("unexpected end of file '{}'", line));
      emit("%%EOF\n");
      expect_ = Expect::done;
      return;
    case Expect::done:
      fail("bytes after %%EOF");
  }
}

std::size_t PdfStreamWriter::document_objects() const {
  return (bookmarks_ > 0 ? 1 + static_cast<std::size_t>(bookmarks_) : 0) + (any_label_ ? 1 : 0);
}

void PdfStreamWriter::write_catalog_and_objects() {
  // numbered after cairo's objects and the annotations: the outline's root, its bookmarks in
  // order, then the page labels
  const std::int64_t first = objects_ + static_cast<std::int64_t>(annotations_.size());
  const std::int64_t root = first;
  const std::int64_t labels = first + (bookmarks_ > 0 ? 1 + bookmarks_ : 0);
  std::string entries;
  if (bookmarks_ > 0) entries += fmt::format("   /Outlines {} 0 R\n", root);
  if (any_label_) entries += fmt::format("   /PageLabels {} 0 R\n", labels);
  emit(entries);
  emit(catalog_rest_);
  catalog_rest_ = {};

  const auto object = [&](std::int64_t number, std::string_view body) {
    if (out_ > kLargestOffset) fail("the file is larger than a cross-reference table can address");
    document_offsets_.push_back(out_);
    emit(fmt::format("{} 0 obj\n{}endobj\n", number, body));
  };
  if (bookmarks_ > 0) {
    object(root, fmt::format("<< /Type /Outlines\n   /First {} 0 R\n   /Last {} 0 R\n   /Count {}\n>>\n", root + 1,
                             root + bookmarks_, bookmarks_));
    std::int64_t k = 0;
    for (const Run& run : runs_) {
      if (!run.names.outline) continue;
      ++k;
      const std::string& title = run.names.title.empty() ? run.names.label : run.names.title;
      std::string body = fmt::format("<< /Title {}\n   /Parent {} 0 R\n", text_string(title), root);
      if (k > 1) body += fmt::format("   /Prev {} 0 R\n", root + k - 1);
      if (k < bookmarks_) body += fmt::format("   /Next {} 0 R\n", root + k + 1);
      body += fmt::format("   /Dest [{} 0 R /XYZ null null 0]\n>>\n", run.page_object);
      object(root + k, body);
    }
  }
  if (any_label_) {
    // one entry a page named, and one where unnamed pages start (a decimal page number from
    // there on, PDF's default), as PDF's number tree takes them: by the index of a range's first
    // page. Written as it goes: a class set has tens of thousands.
    if (out_ > kLargestOffset) fail("the file is larger than a cross-reference table can address");
    document_offsets_.push_back(out_);
    std::string body = fmt::format("{} 0 obj\n<< /Nums [\n", labels);
    const auto unnamed_from = [&](int index) { body += fmt::format("   {} << /S /D /St {} >>\n", index, index + 1); };
    for (const Run& run : runs_) {
      const int index = run.first_page - 1;
      if (run.names.label.empty()) {
        unnamed_from(index);
        continue;
      }
      for (int p = 0; p < run.names.pages; ++p) {
        const std::string name =
            run.names.numbered ? fmt::format("{} {}/{}", run.names.label, p + 1, run.names.pages) : run.names.label;
        body += fmt::format("   {} << /P {} >>\n", index + p, text_string(name));
      }
      if (body.size() > 64 * 1024) {
        emit(body);
        body.clear();
      }
    }
    if (run_pages_ < pages_written_) unnamed_from(run_pages_);
    body += "  ]\n>>\nendobj\n";
    emit(body);
  }
}

void PdfStreamWriter::finish() {
  if (holding_) throw std::logic_error("PdfStreamWriter: finish inside a page");
  if (trailer_ == Trailer::off) return;
  if (expect_ != Expect::done || !pending_.empty()) fail("cairo's trailer ended early");
  // the numbers, now that cairo's count is known: the /Annots arrays, then each object's own
  for (const LinkedPage& page : pages_) {
    std::string refs;
    for (std::uint32_t k = 0; k < page.count; ++k)
      refs.append(k == 0 ? "" : " ").append(field(objects_ + page.first + k)).append(" 0 R");
    sink_.overwrite(page.annots_at, refs);
  }
  for (std::size_t j = 0; j < annotations_.size(); ++j)
    sink_.overwrite(annotations_[j], field(objects_ + static_cast<std::int64_t>(j)));
}

}  // namespace epure::render
