#include "render/pdf_link_writer.h"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace epure::render {
namespace {

// An object number's field: wide enough for any object number a PDF can have (PDF's offsets
// take ten digits too); the number is right-aligned, so the object starts at its first digit.
constexpr std::size_t kField = 10;
const std::string kBlankField(kField, ' ');
// A page object's end as cairo writes it; the /Annots entry goes before it.
constexpr std::string_view kPageEnd = ">>\nendobj\n";
// The last object's end and the cross-reference table's start, as cairo writes them (binary
// stream data that happened to hold these twelve bytes would be caught by the startxref check).
constexpr std::string_view kTableStart = "endobj\nxref\n";
// A cross-reference entry's offset has ten digits.
constexpr std::uint64_t kLargestOffset = 9'999'999'999;

[[noreturn]] void fail(std::string_view why) {
  throw std::runtime_error(fmt::format("cannot add the PDF's links: {}", why));
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

PdfLinkWriter::PdfLinkWriter(PdfSink sink) : sink_(std::move(sink)) {}

void PdfLinkWriter::emit(std::string_view bytes) {
  sink_.write(bytes);
  out_ += bytes.size();
}

void PdfLinkWriter::write(std::string_view bytes) {
  in_ += bytes.size();
  if (holding_) {
    page_bytes_.append(bytes);
  } else if (trailer_ != Trailer::off) {
    trailer_bytes(bytes);
  } else {
    emit(bytes);
  }
}

void PdfLinkWriter::begin_page(int number, double height_pt, std::span<const PageLink> links) {
  if (holding_ || trailer_ != Trailer::off) throw std::logic_error("PdfLinkWriter: begin_page out of order");
  if (links.empty()) return;
  if (!sink_.overwrite) throw std::logic_error("PdfLinkWriter: links need a sink that can overwrite");
  holding_ = true;
  page_number_ = number;
  page_height_ = height_pt;
  page_links_.assign(links.begin(), links.end());
  page_bytes_.clear();
}

void PdfLinkWriter::end_page() {
  if (!holding_) return;
  holding_ = false;
  // cairo's page object, the last thing it wrote for the page
  const std::string header = fmt::format(" 0 obj\n<< /Type /Page % {}\n", page_number_);
  const std::size_t at = page_bytes_.rfind(header);
  const std::size_t size = page_bytes_.size();
  if (at == std::string::npos || size < kPageEnd.size() + 1 ||
      std::string_view(page_bytes_).substr(size - kPageEnd.size()) != kPageEnd ||
      page_bytes_[size - kPageEnd.size() - 1] != '\n' || page_bytes_.find("endobj", at) != size - 7)
    fail(fmt::format("page {}: cairo's page object is not the last thing it wrote for the page", page_number_));

  emit(std::string_view(page_bytes_).substr(0, size - kPageEnd.size()));
  std::string annots = "   /Annots [";
  const std::uint64_t annots_at = out_ + annots.size() + 1;
  for (std::size_t k = 0; k < page_links_.size(); ++k) annots.append(" ").append(kBlankField).append(" 0 R");
  annots += " ]\n";
  emit(annots);
  emit(kPageEnd);
  const auto first = static_cast<std::uint32_t>(annotations_.size());
  for (const PageLink& link : page_links_) {
    annotations_.push_back(out_);
    emit(annotation(link, page_height_));
  }
  pages_.push_back({in_, out_ - in_, annots_at, first, static_cast<std::uint32_t>(page_links_.size())});
  page_links_.clear();
}

void PdfLinkWriter::begin_trailer() {
  if (holding_) throw std::logic_error("PdfLinkWriter: begin_trailer inside a page");
  if (!annotations_.empty()) trailer_ = Trailer::seeking;
}

void PdfLinkWriter::trailer_bytes(std::string_view bytes) {
  pending_.append(bytes);
  if (trailer_ == Trailer::seeking) {
    const std::size_t at = pending_.find(kTableStart);
    if (at == std::string::npos) {
      // all but a possible start of kTableStart
      const std::size_t keep = std::min(pending_.size(), kTableStart.size() - 1);
      emit(std::string_view(pending_).substr(0, pending_.size() - keep));
      pending_.erase(0, pending_.size() - keep);
      return;
    }
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

void PdfLinkWriter::trailer_line(std::string_view line) {
  const auto added = static_cast<std::int64_t>(annotations_.size());
  switch (expect_) {
    case Expect::header:
      if (line != "xref") fail("cairo's cross-reference table not found");
      emit("xref\n");
      expect_ = Expect::subsection;
      return;
    case Expect::subsection: {
      const auto n = line.substr(0, 2) == "0 " ? integer(line.substr(2)) : std::nullopt;
      if (!n || *n < 1) fail(fmt::format("unexpected cross-reference subsection '{}'", line));
      objects_ = *n;
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
      for (std::int64_t j = 0; j < added; ++j) {
        const std::int64_t n = objects_ + j;
        const std::uint64_t at = annotations_[static_cast<std::size_t>(j)] + kField - std::to_string(n).size();
        emit(fmt::format("{:010} 00000 n \n", at));
      }
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

void PdfLinkWriter::finish() {
  if (holding_) throw std::logic_error("PdfLinkWriter: finish inside a page");
  if (annotations_.empty()) return;
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
