#include "grading/report_csv.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <cmath>

#include "output/atomic_file.h"

namespace epure::grading {

struct CsvReport::Impl {
  output::AtomicFile file;
  const AnswerKey& key;
  CsvDialect dialect;
  ClassWords words;
  MarkScale scale;
  fmt::memory_buffer buf;
  std::vector<double> points;  // by question id index; NaN: not asked
  std::vector<char> asked;     // by question id index: 0 not asked, 1 marked, 2 to check

  Impl(const std::filesystem::path& path, const AnswerKey& k, CsvDialect d, const Texts& texts, MarkScale s)
      : file(path), key(k), dialect(d), words(k, texts), scale(s) {}

  void end_line() {
    if (dialect.crlf) buf.push_back('\r');
    buf.push_back('\n');
    if (buf.size() > (1 << 16)) flush();
  }
  void flush() {
    file.write(std::string_view(buf.data(), buf.size()));
    buf.clear();
  }
  void cell(std::string_view s, bool first = false) {
    if (!first) buf.push_back(dialect.delimiter);
    const char special[] = {dialect.delimiter, '"', '\n', '\r'};  // no string built per cell
    const bool quote = s.find_first_of(std::string_view(special, sizeof special)) != std::string_view::npos;
    if (!quote) {
      buf.append(s);
      return;
    }
    buf.push_back('"');
    for (char c : s) {
      if (c == '"') buf.push_back('"');
      buf.push_back(c);
    }
    buf.push_back('"');
  }
  // Room a cell of points takes at most: delimiter, sign, 19 digits, separator, 3 decimals.
  static constexpr std::size_t kPointsRoom = 32;

  // A cell of points, delimiter first, written at p (kPointsRoom bytes free); returns its end.
  // Most are 0 or 1, exactly as the key gives them (this compares the key's own values, not
  // computed ones): one digit. Thousandths are enough for the rest, without trailing zeros.
  char* put_number(char* p, double x) const {
    *p++ = dialect.delimiter;
    if (x == 0 || x == 1) {
      *p++ = x == 0 ? '0' : '1';
      return p;
    }
    long long m = static_cast<long long>(std::abs(x) * 1000 + 0.5);
    if (x < 0) *p++ = '-';
    char digits[24];
    int n = 0;
    for (long long whole = m / 1000; n == 0 || whole > 0; whole /= 10) digits[n++] = static_cast<char>('0' + whole % 10);
    while (n > 0) *p++ = digits[--n];
    long long frac = m % 1000;
    if (frac == 0) return p;
    *p++ = dialect.decimal_comma ? ',' : '.';
    for (long long d = 100; frac > 0; d /= 10) {
      *p++ = static_cast<char>('0' + frac / d);
      frac %= d;
    }
    return p;
  }
  // Room for `cells` cells at the end of the buffer, written through a pointer rather than a
  // push_back (and its capacity test) per character: a row has dozens of them.
  char* open_room(std::size_t cells) {
    const std::size_t at = buf.size();
    buf.resize(at + cells * kPointsRoom);
    return buf.data() + at;
  }
  void close_room(const char* end) { buf.resize(static_cast<std::size_t>(end - buf.data())); }
  void number(double x) { close_room(put_number(open_room(1), x)); }
};

CsvReport::CsvReport(const std::filesystem::path& path, const AnswerKey& key, CsvDialect dialect, const Texts& texts,
                     MarkScale scale)
    : impl_(std::make_unique<Impl>(path, key, dialect, texts, scale)) {
  auto& m = *impl_;
  if (dialect.bom) m.buf.append(std::string_view("\xef\xbb\xbf"));
  m.cell(texts.get("grading.report.sheet"), true);
  m.cell(texts.get("grading.report.student"));
  m.cell(texts.get("grading.report.score"));
  m.cell(texts.get("grading.report.max"));
  if (scale.out_of)  // "mark/20", "note/20"
    m.cell(texts.format("grading.report.mark", {{"out_of", fmt::format("{}", *scale.out_of)}}));
  m.cell(texts.get("grading.report.held"));
  for (const auto& id : key.question_ids()) m.cell(id);
  m.cell(texts.get("grading.report.line"));
  m.cell(texts.get("grading.report.flags"));
  m.end_line();
  m.points.assign(key.question_ids().size(), 0);
  m.asked.assign(key.question_ids().size(), 0);
}

CsvReport::~CsvReport() = default;

void CsvReport::submission(const Submission& s) {
  auto& m = *impl_;
  m.cell(s.sheet ? std::string_view(s.sheet->id) : s.sheet_text, true);
  m.cell(s.student);
  if (s.marked()) {
    m.number(s.score);
    m.number(s.max);
    // the mark out of N, rounded as mark_scale.h says
    if (m.scale.out_of) m.number(m.scale.mark(s.score, s.max));
    m.number(s.held);
    std::fill(m.asked.begin(), m.asked.end(), 0);
    // through local pointers: a store to asked (char) may alias anything, and would make the
    // compiler reload every vector's bounds at each question
    double* const points = m.points.data();
    char* const asked = m.asked.data();
    for (std::size_t e = 0; e < s.marks.size(); ++e) {
      const QuestionMark* const marks = s.marks[e].data();
      const int* const index = s.report_index[e].data();
      const std::size_t n = s.marks[e].size();
      for (std::size_t q = 0; q < n; ++q) {
        const auto i = static_cast<std::size_t>(index[q]);
        points[i] = marks[q].points;
        asked[i] = marks[q].verdict == Verdict::to_check ? 2 : 1;
      }
    }
    char* p = m.open_room(m.points.size());
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      if (m.asked[i] == 1) {
        p = m.put_number(p, m.points[i]);
      } else {
        *p++ = m.dialect.delimiter;
        if (m.asked[i] == 2) *p++ = '?';  // to check: not a number, so that a sum leaves it out
      }
    }
    m.close_room(p);
  } else {
    m.buf.push_back(m.dialect.delimiter);
    m.buf.push_back(m.dialect.delimiter);
    m.buf.push_back(m.dialect.delimiter);
    if (m.scale.out_of) m.buf.push_back(m.dialect.delimiter);
    for (std::size_t i = 0; i < m.points.size(); ++i) m.buf.push_back(m.dialect.delimiter);
  }
  m.buf.push_back(m.dialect.delimiter);
  fmt::format_to(fmt::appender(m.buf), "{}", s.line);
  std::string flags;
  for (const auto& f : s.flags) {
    const std::string name = m.words.flag(f.code);
    if (flags.find(name) != std::string::npos) continue;
    if (!flags.empty()) flags += "; ";
    flags += name;
  }
  m.cell(flags);
  m.end_line();
}

void CsvReport::finish(const ClassStatistics&, const Outcome&) {
  impl_->flush();
  impl_->file.commit();
}

}  // namespace epure::grading
