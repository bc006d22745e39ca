#include "render/svg_path_data.h"

#include <doctest/doctest.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

#include "exercises/rng.h"
#include "render/svg_writer.h"

using namespace epure::render;

namespace {

// An SVG path-data reader of its own (M, L, H, V, C, Z both ways), independent of the writer:
// the absolute points the data draw, in order (Z gives the subpath's start).
std::vector<P2> absolute_points(const std::string& d) {
  std::vector<P2> out;
  std::size_t i = 0;
  const auto number = [&] {
    while (i < d.size() && (d[i] == ' ' || d[i] == ',')) ++i;
    char* end = nullptr;
    const double v = std::strtod(d.c_str() + i, &end);
    REQUIRE(end != d.c_str() + i);
    i = static_cast<std::size_t>(end - d.c_str());
    return v;
  };
  P2 at{0, 0}, start{0, 0};
  while (i < d.size()) {
    const char c = d[i++];
    if (c == ' ') continue;
    const bool rel = std::islower(static_cast<unsigned char>(c)) != 0;
    const P2 base = rel ? at : P2{0, 0};
    switch (std::toupper(static_cast<unsigned char>(c))) {
      case 'M': {
        const double x = number(), y = number();
        at = start = {base.x + x, base.y + y};
        break;
      }
      case 'L': {
        const double x = number(), y = number();
        at = {base.x + x, base.y + y};
        break;
      }
      case 'H': at = {(rel ? at.x : 0) + number(), at.y}; break;
      case 'V': at = {at.x, (rel ? at.y : 0) + number()}; break;
      case 'C': {
        double v[6];
        for (double& x : v) x = number();
        out.push_back({base.x + v[0], base.y + v[1]});
        out.push_back({base.x + v[2], base.y + v[3]});
        at = {base.x + v[4], base.y + v[5]};
        break;
      }
      case 'Z': at = start; break;
      default: FAIL("unexpected path command " << c);
    }
    out.push_back(at);
  }
  return out;
}

// The points a path names, each as the absolute form writes it (to the hundredth), in the order
// absolute_points gives them.
std::vector<P2> written_points(const Path& path) {
  std::vector<P2> out;
  const auto hundredths = [](P2 p) {
    return P2{std::stod(format_number(p.x)), std::stod(format_number(p.y))};
  };
  P2 start{0, 0};
  for (const Path::Cmd& c : path.cmds()) {
    switch (c.op) {
      case Path::Op::move: start = hundredths(c.p[0]); out.push_back(start); break;
      case Path::Op::line: out.push_back(hundredths(c.p[0])); break;
      case Path::Op::cubic:
        for (const P2& p : c.p) out.push_back(hundredths(p));
        break;
      case Path::Op::close: out.push_back(start); break;
    }
  }
  return out;
}

std::string data(const Path& p) {
  std::string d;
  append_path_data(d, p);
  return d;
}

}  // namespace

TEST_CASE("path data: a rectangle, an axis-aligned step as H or V, the shorter of the two forms") {
  Path r;
  r.move_to({10, 20}).line_to({40, 20}).line_to({40, 60}).line_to({10, 60}).close();
  CHECK(data(r) == "M10 20H40V60H10Z");  // ties are written absolute
  Path far;
  far.move_to({512.35, 701.4}).line_to({513.4, 701.4}).line_to({513.4, 702.45}).line_to({512.35, 702.45}).close();
  CHECK(data(far) == "M512.35 701.4h1.05v1.05h-1.05Z");
  Path two;  // a second subpath moves from the first one's start, where Z left the pen
  two.move_to({100, 100}).line_to({101, 100}).close().move_to({102.5, 100.25}).line_to({103, 101});
  CHECK(data(two) == "M100 100h1Zm2.5 0.25L103 101");  // "l0.5 0.75" would be a byte longer
  Path neg;  // a minus sign separates numbers by itself
  neg.move_to({50, 50}).line_to({49, 48});
  CHECK(data(neg) == "M50 50l-1-2");
}

TEST_CASE("path data: relative steps add up to the rounded absolute points, with no drift") {
  Path p;
  p.move_to({0.004, 0.004});
  for (int i = 1; i <= 2000; ++i) p.line_to({0.333 * i + 0.004, 0.777 * i});
  const std::vector<P2> read = absolute_points(data(p)), want = written_points(p);
  REQUIRE(read.size() == want.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    CHECK(std::abs(read[i].x - want[i].x) < 1e-7);
    CHECK(std::abs(read[i].y - want[i].y) < 1e-7);
  }
}

TEST_CASE("path data: random paths of every command read back as their absolute form") {
  epure::Rng rng(34, 7);
  const auto coordinate = [&] { return -50 + 700 * rng.uniform(); };
  for (int n = 0; n < 300; ++n) {
    Path p;
    const int cmds = 1 + static_cast<int>(rng.uniform() * 12);
    p.move_to({coordinate(), coordinate()});
    P2 last{0, 0};
    for (int k = 0; k < cmds; ++k) {
      const double pick = rng.uniform();
      if (pick < 0.3) {
        last = {coordinate(), coordinate()};
        p.line_to(last);
      } else if (pick < 0.45) {
        p.line_to({coordinate(), last.y});  // horizontal when last is the current point
      } else if (pick < 0.7) {
        p.cubic_to({coordinate(), coordinate()}, {coordinate(), coordinate()}, last = {coordinate(), coordinate()});
      } else if (pick < 0.85) {
        p.close();
      } else {
        p.move_to(last = {coordinate(), coordinate()});
      }
    }
    const std::string d = data(p);
    const std::vector<P2> read = absolute_points(d), want = written_points(p);
    REQUIRE(read.size() == want.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
      INFO(d);
      CHECK(std::abs(read[i].x - want[i].x) < 1e-7);
      CHECK(std::abs(read[i].y - want[i].y) < 1e-7);
    }
  }
}

TEST_CASE("path data: a coordinate beyond the fast form writes the path absolute") {
  Path p;
  p.move_to({0, 0}).line_to({2e12, 1}).close();
  CHECK(data(p) == "M0 0 L2000000000000 1 Z");
}

TEST_CASE("path data: a horizontal step is the shorter of H and h by the written numbers, over digit-count edges") {
  // The writer counts a number's characters without writing it; the reference writes both forms
  // with format_number and compares their lengths (absolute on a tie). The values sit on the
  // edges where the count changes: 9.99 → 10, 0.1 → 0.05, 99.9 → 100, 999.99 → 1000, signs.
  epure::Rng rng(34, 9);
  const double edges[] = {0, 0.01, 0.05, 0.1, 0.5, 0.99, 1, 9.9, 9.99, 10, 10.01, 99.9, 99.99, 100, 100.5,
                          999.99, 1000, 1000.01, 9999.99, 10000, 123456.78};
  for (int n = 0; n < 20000; ++n) {
    const auto pick = [&] {
      const double e = edges[rng.integer(0, static_cast<std::int64_t>(std::size(edges)) - 1)];
      return rng.chance(0.5) ? -e : e;
    };
    const double x0 = pick(), x1 = pick(), y = 7;
    Path p;
    p.move_to({x0, y}).line_to({x1, y});
    const std::string absolute = format_number(x1);
    const std::string relative = format_number(std::round(x1 * 100) / 100 - std::round(x0 * 100) / 100);
    std::string want = "M";
    want += format_number(x0);
    want += " 7";
    want += relative.size() < absolute.size() ? 'h' : 'H';
    want += relative.size() < absolute.size() ? relative : absolute;
    CAPTURE(x0);
    CAPTURE(x1);
    if (std::round(x1 * 100) == std::round(x0 * 100)) continue;  // no step: H or h of nothing, either way
    REQUIRE(data(p) == want);
  }
}
