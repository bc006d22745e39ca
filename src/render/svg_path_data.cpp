#include "render/svg_path_data.h"

#include <array>
#include <cstddef>
#include <iterator>

#include "render/svg_writer.h"

namespace epure::render {
namespace {

constexpr int kDecimals = 2;  // a hundredth of a point: far below what a printer or a screen shows

// A point as integer hundredths, or none when a coordinate is beyond the fast form (never in a
// drawing; such a path is written absolute, number by number).
struct Scaled {
  long long x = 0, y = 0;
};

bool scale(P2 p, Scaled& s) { return round_scaled(p.x, kDecimals, s.x) && round_scaled(p.y, kDecimals, s.y); }

// The length of append_scaled's text for `n`, without writing it: the integer part's digits,
// then ".d" or ".dd" for the decimals that are not trailing zeros.
int scaled_length(long long n) {
  static_assert(kDecimals == 2);
  if (n == 0) return 1;
  unsigned long long m = n < 0 ? 0ULL - static_cast<unsigned long long>(n) : static_cast<unsigned long long>(n);
  const unsigned long long decimals = m % 100;
  int length = (n < 0 ? 1 : 0) + (decimals == 0 ? 0 : decimals % 10 == 0 ? 2 : 3);
  m /= 100;
  for (; m >= 1000; m /= 1000) length += 3;
  return length + (m >= 100 ? 3 : m >= 10 ? 2 : 1);
}

// A command's numbers after its letter: a separator only where a number would run into the
// previous one (a minus sign separates by itself).
template <std::size_t N>
int numbers_length(const std::array<long long, N>& values) {
  int length = 0;
  for (std::size_t i = 0; i < N; ++i) length += scaled_length(values[i]) + (i > 0 && values[i] >= 0 ? 1 : 0);
  return length;
}

// Written backwards into a buffer, the last number first, and appended in one piece.
template <std::size_t N>
void write_command(std::string& d, char letter, const std::array<long long, N>& values) {
  char buf[1 + N * (kScaledRoom + 1)];
  char* const end = std::end(buf);
  char* p = end;
  for (std::size_t i = N; i-- > 0;) {
    p = scaled_before(p, values[i], kDecimals);
    if (i > 0 && values[i] >= 0) *--p = ' ';
  }
  *--p = letter;
  d.append(p, static_cast<std::size_t>(end - p));
}

// The shorter of a command's absolute and relative forms (absolute on a tie: the choice depends
// on integers only, so it is the same on every platform).
template <std::size_t N>
void shorter(std::string& d, char absolute, const std::array<long long, N>& abs_values, char relative,
             const std::array<long long, N>& rel_values) {
  if (numbers_length(rel_values) < numbers_length(abs_values))
    write_command(d, relative, rel_values);
  else
    write_command(d, absolute, abs_values);
}

void append_absolute(std::string& d, const Path& path) {
  const auto point = [&](P2 p) {
    append_number(d, p.x, kDecimals);
    d += ' ';
    append_number(d, p.y, kDecimals);
  };
  for (const Path::Cmd& c : path.cmds()) {
    if (!d.empty()) d += ' ';
    switch (c.op) {
      case Path::Op::move: d += 'M'; point(c.p[0]); break;
      case Path::Op::line: d += 'L'; point(c.p[0]); break;
      case Path::Op::cubic:
        d += 'C';
        point(c.p[0]);
        d += ' ';
        point(c.p[1]);
        d += ' ';
        point(c.p[2]);
        break;
      case Path::Op::close: d += 'Z'; break;
    }
  }
}

}  // namespace

void append_path_data(std::string& d, const Path& path) {
  // Written as the coordinates are rounded; a path with one beyond the fast form (never in a
  // drawing) is taken back and written absolute. No copy of the path's points is made: the SVG
  // writer runs for every path of every page.
  const std::size_t mark = d.size();
  Scaled at{}, start{};  // the current point, and the current subpath's first (where Z returns)
  bool have_point = false;
  for (std::size_t i = 0; i < path.cmds().size(); ++i) {
    const Path::Cmd& c = path.cmds()[i];
    std::array<Scaled, 3> s{};
    const int points = c.op == Path::Op::cubic ? 3 : c.op == Path::Op::close ? 0 : 1;
    for (int k = 0; k < points; ++k) {
      if (!scale(c.p[k], s[static_cast<std::size_t>(k)])) {
        d.resize(mark);
        append_absolute(d, path);
        return;
      }
    }
    switch (c.op) {
      case Path::Op::move:
        // The path's first move is absolute in SVG whatever its letter: written M.
        if (!have_point)
          write_command<2>(d, 'M', {s[0].x, s[0].y});
        else
          shorter<2>(d, 'M', {s[0].x, s[0].y}, 'm', {s[0].x - at.x, s[0].y - at.y});
        at = start = s[0];
        have_point = true;
        break;
      case Path::Op::line:
        if (s[0].y == at.y && have_point)
          shorter<1>(d, 'H', {s[0].x}, 'h', {s[0].x - at.x});
        else if (s[0].x == at.x && have_point)
          shorter<1>(d, 'V', {s[0].y}, 'v', {s[0].y - at.y});
        else if (have_point)
          shorter<2>(d, 'L', {s[0].x, s[0].y}, 'l', {s[0].x - at.x, s[0].y - at.y});
        else
          write_command<2>(d, 'L', {s[0].x, s[0].y});
        at = s[0];
        break;
      case Path::Op::cubic:
        if (!have_point) {
          write_command<6>(d, 'C', {s[0].x, s[0].y, s[1].x, s[1].y, s[2].x, s[2].y});
          at = s[2];
          break;
        }
        shorter<6>(d, 'C', {s[0].x, s[0].y, s[1].x, s[1].y, s[2].x, s[2].y}, 'c',
                   {s[0].x - at.x, s[0].y - at.y, s[1].x - at.x, s[1].y - at.y, s[2].x - at.x, s[2].y - at.y});
        at = s[2];
        break;
      case Path::Op::close:
        d += 'Z';
        at = start;
        break;
    }
  }
}

}  // namespace epure::render
