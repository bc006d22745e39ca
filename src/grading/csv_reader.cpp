#include "grading/csv_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace epure::grading {

namespace {

constexpr std::size_t kBlock = 1 << 20;

enum class State { field_start, unquoted, in_quotes, quote_seen };

}  // namespace

CsvReader::CsvReader(const std::filesystem::path& path, std::optional<char> delimiter) {
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_) throw std::runtime_error(fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
  buf_.resize(kBlock);
  try {
    start(delimiter);
  } catch (const std::runtime_error& e) {
    std::fclose(file_);
    file_ = nullptr;
    throw std::runtime_error(fmt::format("{}: {}", path.string(), e.what()));
  }
}

CsvReader CsvReader::from_text(std::string text, std::optional<char> delimiter) {
  CsvReader r;
  r.buf_.assign(text.begin(), text.end());
  r.end_ = r.buf_.size();
  r.eof_ = true;
  r.start(delimiter);
  return r;
}

CsvReader::~CsvReader() {
  if (file_) std::fclose(file_);
}

CsvReader::CsvReader(CsvReader&& o) noexcept
    : file_(o.file_), buf_(std::move(o.buf_)), begin_(o.begin_), end_(o.end_), eof_(o.eof_),
      newline_(o.newline_), delimiter_(o.delimiter_), bom_(o.bom_), crlf_(o.crlf_), line_(o.line_),
      blank_lines_(o.blank_lines_) {
  o.file_ = nullptr;
}

bool CsvReader::fill() {
  if (eof_ || !file_) {
    eof_ = true;
    return false;
  }
  if (begin_ > 0) {
    std::memmove(buf_.data(), buf_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buf_.size()) {  // one record longer than the buffer
    if (end_ > kMaxRecordBytes) too_long(line_);  // line_: where the record being read starts
    buf_.resize(buf_.size() * 2);
  }
  const std::size_t got = std::fread(buf_.data() + end_, 1, buf_.size() - end_, file_);
  end_ += got;
  if (got == 0) eof_ = true;
  return got > 0;
}

void CsvReader::start(std::optional<char> delimiter) {
  // enough of the file to see its encoding, its line ends and its header
  while (!eof_ && end_ < 4096) fill();
  const auto* u = reinterpret_cast<const unsigned char*>(buf_.data());
  if (end_ >= 2 && ((u[0] == 0xff && u[1] == 0xfe) || (u[0] == 0xfe && u[1] == 0xff)))
    throw std::runtime_error("the file is UTF-16 (a spreadsheet's \"Unicode text\"): export it as CSV UTF-8");
  if (end_ >= 3 && u[0] == 0xef && u[1] == 0xbb && u[2] == 0xbf) {
    bom_ = true;
    begin_ = 3;
  }
  const std::string_view head(buf_.data() + begin_, end_ - begin_);
  const auto lf = head.find('\n'), cr = head.find('\r');
  if (lf == std::string_view::npos && cr != std::string_view::npos) newline_ = '\r';  // classic Mac
  if (delimiter) {
    delimiter_ = *delimiter;
    return;
  }
  // the delimiter the header line uses most, outside quotes (question ids contain none)
  const std::string_view first = head.substr(0, head.find(newline_));
  int counts[3] = {0, 0, 0};
  bool quoted = false;
  for (char c : first) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == ',') ++counts[0];
    if (c == ';') ++counts[1];
    if (c == '\t') ++counts[2];
  }
  delimiter_ = ',';
  if (counts[1] > counts[0] && counts[1] >= counts[2]) delimiter_ = ';';
  if (counts[2] > counts[0] && counts[2] > counts[1]) delimiter_ = '\t';
}

bool CsvReader::find_record(std::size_t& end, std::size_t& next, bool& quoted, bool& unclosed) {
  quoted = false;
  unclosed = false;
  if (begin_ == end_ && eof_) return false;  // nothing left (and an empty text has no buffer at all)
  std::size_t pos = begin_;
  State st = State::field_start;
  // The next line end at or after pos, and how far none was found, both relative to begin_
  // (fill() moves the buffer): a line with many stray quotes in unquoted cells comes back to
  // the fast path once per quote, and must not search for its end again each time (that was
  // quadratic in the line's length, minutes on a few megabytes without a line break).
  constexpr std::size_t kUnknown = static_cast<std::size_t>(-1);
  std::size_t nl_rel = kUnknown, clean_rel = 0;
  for (;;) {
    if (st == State::field_start || st == State::unquoted) {
      // fast path: no quote before the line's end means the record ends there
      const char* base = buf_.data();
      if (nl_rel == kUnknown || begin_ + nl_rel < pos) {
        const std::size_t from = std::max(pos, begin_ + clean_rel);
        const auto* nl = static_cast<const char*>(std::memchr(base + from, newline_, end_ - from));
        nl_rel = nl ? static_cast<std::size_t>(nl - base) - begin_ : kUnknown;
        if (!nl) clean_rel = end_ - begin_;
      }
      const bool found = nl_rel != kUnknown;
      const std::size_t limit = found ? begin_ + nl_rel : end_;
      if (!std::memchr(base + pos, '"', limit - pos)) {
        if (found) {
          end = limit;
          next = limit + 1;
          return true;
        }
        if (eof_) {
          if (begin_ == end_) return false;
          end = next = end_;
          return true;
        }
        const std::size_t scanned = limit - begin_;
        fill();
        pos = begin_ + scanned;
        continue;
      }
    }
    quoted = true;
    while (pos < end_) {
      const char c = buf_[pos];
      switch (st) {
        case State::field_start:
        case State::unquoted:
          if (c == '"' && st == State::field_start) st = State::in_quotes;
          else if (c == delimiter_) st = State::field_start;
          else if (c == newline_) {
            end = pos;
            next = pos + 1;
            return true;
          } else st = State::unquoted;
          break;
        case State::in_quotes:
          if (c == '"') st = State::quote_seen;
          break;
        case State::quote_seen:
          if (c == '"') st = State::in_quotes;
          else if (c == delimiter_) st = State::field_start;
          else if (c == newline_) {
            end = pos;
            next = pos + 1;
            return true;
          } else st = State::unquoted;
          break;
      }
      ++pos;
      if (st == State::unquoted) break;  // back to the fast path
    }
    if (pos >= end_) {
      if (eof_) {
        if (begin_ == end_) return false;
        unclosed = st == State::in_quotes;
        end = next = end_;
        return true;
      }
      const std::size_t scanned = pos - begin_;
      fill();
      pos = begin_ + scanned;
    }
  }
}

void CsvReader::too_long(int line) const {
  throw std::runtime_error(fmt::format("line {}: a record longer than {} MiB (an unclosed quote?): not an answers file",
                                       line, kMaxRecordBytes >> 20));
}

void CsvReader::split(std::size_t b, std::size_t e, bool quoted, CsvRecord& r) {
  // one cell past the limit is enough to refuse the record (next() does)
  const std::size_t limit_ = std::min(this->limit_, kMaxCells + 1);
  char* buf = buf_.data();
  r.cells.clear();
  if (!quoted) {
    // Cells are a few bytes long: a call to memchr for each costs more than it saves. Eight
    // bytes at a time instead: a mask of the delimiters among them (exact, no false positive:
    // each byte's test is kept apart from its neighbours'), then one cell per set bit.
    static_assert(std::endian::native == std::endian::little, "the delimiter mask reads bytes in memory order");
    const char d = delimiter_;
    constexpr std::uint64_t kLow7 = 0x7f7f7f7f7f7f7f7full;
    const std::uint64_t pattern = 0x0101010101010101ull * static_cast<unsigned char>(d);
    std::size_t p = b;
    std::size_t i = b;
    for (; i + 8 <= e; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, buf + i, 8);
      const std::uint64_t x = word ^ pattern;  // a zero byte where the delimiter is
      std::uint64_t zeros = ~(((x & kLow7) + kLow7) | x | kLow7);
      while (zeros) {
        // little-endian (asserted above): the lowest set bit is the first byte in the text
        const std::size_t at = i + static_cast<std::size_t>(std::countr_zero(zeros)) / 8;
        r.cells.emplace_back(buf + p, at - p);
        p = at + 1;
        if (r.cells.size() >= limit_) return;
        zeros &= zeros - 1;
      }
    }
    for (; i < e; ++i) {
      if (buf[i] != d) continue;
      r.cells.emplace_back(buf + p, i - p);
      p = i + 1;
      if (r.cells.size() >= limit_) return;
    }
    r.cells.emplace_back(buf + p, e - p);
    return;
  }
  std::size_t p = b;
  for (;;) {
    std::size_t cell_end;
    if (p < e && buf[p] == '"') {
      // quoted: unescaped in place ("" → "), the text shrinks behind the read position
      std::size_t w = p, q = p + 1;
      bool closed = false;
      while (q < e) {
        if (buf[q] == '"') {
          if (q + 1 < e && buf[q + 1] == '"') {
            buf[w++] = '"';
            q += 2;
            continue;
          }
          closed = true;
          ++q;
          break;
        }
        buf[w++] = buf[q++];
      }
      if (!closed) r.problem = "unclosed_quote";
      if (q < e && buf[q] != delimiter_) {
        r.problem = "text_after_quote";
        while (q < e && buf[q] != delimiter_) buf[w++] = buf[q++];
      }
      r.cells.emplace_back(buf + p, w - p);
      cell_end = q;
    } else {
      const auto* d = static_cast<const char*>(std::memchr(buf + p, delimiter_, e - p));
      cell_end = d ? static_cast<std::size_t>(d - buf) : e;
      r.cells.emplace_back(buf + p, cell_end - p);
    }
    if (cell_end >= e || r.cells.size() >= limit_) return;
    p = cell_end + 1;
  }
}

bool CsvReader::next(CsvRecord& r) {
  for (;;) {
    std::size_t end = 0, next = 0;
    bool quoted = false, unclosed = false;
    if (!find_record(end, next, quoted, unclosed)) return false;
    r.line = line_;
    // an unclosed quote runs to the end of the file: its last line end is the file's, not the
    // record's
    while (unclosed && end > begin_ && (buf_[end - 1] == newline_ || buf_[end - 1] == '\r')) --end;
    int breaks = 0;
    if (quoted)
      for (std::size_t i = begin_; i < end; ++i) breaks += buf_[i] == newline_;
    r.last_line = line_ + breaks;
    line_ = r.last_line + (next > end ? 1 : 0);
    std::size_t stop = end;
    if (newline_ == '\n' && stop > begin_ && buf_[stop - 1] == '\r') {
      --stop;
      crlf_ = true;
    }
    r.problem = unclosed ? std::string_view("unclosed_quote") : std::string_view();
    const std::size_t b = begin_;
    if (stop - b > kMaxRecordBytes) too_long(r.line);
    begin_ = next;
    if (stop == b) {
      ++blank_lines_;
      continue;
    }
    split(b, stop, quoted, r);
    if (r.cells.size() > kMaxCells)
      throw std::runtime_error(fmt::format("line {}: more than {} cells in a record: not an answers file", r.line, kMaxCells));
    if (unclosed) r.problem = "unclosed_quote";
    return true;
  }
}

}  // namespace epure::grading
