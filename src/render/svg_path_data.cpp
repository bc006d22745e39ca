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

// A command's letter and numbers, written backwards to end at `end` (the last number first);
// returns where they start. A separator only where a number would run into the previous one (a
// minus sign separates by itself).
template <std::size_t N>
char* command_before(char* end, char letter, const std::array<long long, N>& values) {
  char* p = end;
  for (std::size_t i = N; i-- > 0;) {
    p = scaled_before(p, values[i], kDecimals);
    if (i > 0 && values[i] >= 0) *--p = ' ';
  }
  *--p = letter;
  return p;
}

template <std::size_t N>
constexpr std::size_t kCommandRoom = 1 + N * (kScaledRoom + 1);

// Written backwards into a buffer and appended in one piece.
template <std::size_t N>
void write_command(std::string& d, char letter, const std::array<long long, N>& values) {
  char buf[kCommandRoom<N>];
  char* const end = std::end(buf);
  const char* p = command_before(end, letter, values);
  d.append(p, static_cast<std::size_t>(end - p));
}

// The shorter of a command's absolute and relative forms (absolute on a tie: the choice depends
// on integers only, so it is the same on every platform). Both are written, the shorter kept:
// cheaper than counting both lengths and then writing one.
template <std::size_t N>
void shorter(std::string& d, char absolute, const std::array<long long, N>& abs_values, char relative,
             const std::array<long long, N>& rel_values) {
  char abs_buf[kCommandRoom<N>], rel_buf[kCommandRoom<N>];
  char* const abs_end = std::end(abs_buf);
  char* const rel_end = std::end(rel_buf);
  const char* a = command_before(abs_end, absolute, abs_values);
  const char* r = command_before(rel_end, relative, rel_values);
  if (rel_end - r < abs_end - a)
    d.append(r, static_cast<std::size_t>(rel_end - r));
  else
    d.append(a, static_cast<std::size_t>(abs_end - a));
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
