#include "check/cases.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "exercises/rng.h"
#include "exercises/worksheet.h"
#include "geometry/vec.h"

namespace epure::check {

namespace {

using geo::Point2;
using geo::Vec2;

// Data as a sheet prints them: k / 10^decimals, the double nearest that decimal.
double decimal(Rng& rng, double lo, double hi, int decimals = 2) {
  const double scale = std::pow(10.0, decimals);
  const auto k = rng.integer(static_cast<std::int64_t>(std::llround(lo * scale)),
                             static_cast<std::int64_t>(std::llround(hi * scale)));
  return static_cast<double>(k) / scale;
}

Vec2 unit(Vec2 v) { return *geo::normalized(v); }
geo::Vec3 unit(geo::Vec3 v) { return *geo::normalized(v); }

// A direction on the two-decimal grid, not zero.
Vec2 direction(Rng& rng) {
  for (;;) {
    const Vec2 v{decimal(rng, -1, 1), decimal(rng, -1, 1)};
    if (std::abs(v.x) + std::abs(v.y) >= 0.1) return v;
  }
}

struct Builder {
  Fn fn;
  std::vector<Case> cases;
  void add(Category c, std::initializer_list<double> values) {
    Case k{fn, c, {}};
    std::size_t i = 0;
    for (double v : values) k.in[i++] = v;
    cases.push_back(k);
  }
};

// Scaled by 2^e, exactly: every coordinate and size (directions are left as they are).
Case scaled(Case k, int e, std::initializer_list<int> lengths) {
  for (int i : lengths) k.in[static_cast<std::size_t>(i)] = std::ldexp(k.in[static_cast<std::size_t>(i)], e);
  k.category = e > 0 ? Category::huge : Category::tiny;
  return k;
}

// ---- Exercise 1 ----------------------------------------------------------------------------
std::vector<Case> projection(Rng& rng) {
  Builder b{Fn::projection, {}};
  while (b.cases.size() < 120) {
    const Point2 A{decimal(rng, -10, 10), decimal(rng, -10, 10)}, B{decimal(rng, -10, 10), decimal(rng, -10, 10)};
    if (geo::norm(B - A) < 0.5) continue;
    b.add(Category::random, {A.x, A.y, B.x, B.y, decimal(rng, -10, 10), decimal(rng, -10, 10)});
  }
  // C on the line, at A, at B, and a short AB seen from far (t large)
  b.add(Category::random, {1, 1, 4, 5, 1, 1});
  b.add(Category::random, {1, 1, 4, 5, 4, 5});
  b.add(Category::random, {-2, 3, 2, 1, 6, -1});
  b.add(Category::random, {0, 0, 0.01, 0.02, 9.5, -7.25});
  for (int i = 0; i < 24; ++i) {
    const Case k = b.cases[static_cast<std::size_t>(i)];
    b.cases.push_back(scaled(k, i % 2 ? 60 : -60, {0, 1, 2, 3, 4, 5}));
  }
  return b.cases;
}

// ---- Exercise 2 ----------------------------------------------------------------------------
std::vector<Case> segments(Rng& rng) {
  Builder b{Fn::segments, {}};
  auto point = [&] { return Point2{decimal(rng, -10, 10), decimal(rng, -10, 10)}; };
  while (b.cases.size() < 150) {
    const Point2 A = point(), B = point(), C = point(), D = point();
    if (geo::norm(B - A) < 0.5 || geo::norm(D - C) < 0.5) continue;
    b.add(Category::random, {A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
  }
  // touching at an end, or at a point of the other segment (dyadic data: exact)
  for (int i = 0; i < 30; ++i) {
    const Point2 A{double(rng.integer(-8, 8)), double(rng.integer(-8, 8))};
    Vec2 AB{double(rng.integer(-6, 6)), double(rng.integer(-6, 6))};
    if (AB.x == 0 && AB.y == 0) AB = {3, 1};
    const Point2 B = A + AB;
    const double s = double(rng.integer(0, 4)) / 4;  // where C lands on [AB]: 0, 1/4, …, 1
    const Point2 C = A + s * AB;
    Vec2 CD{double(rng.integer(-6, 6)), double(rng.integer(-6, 6))};
    if (geo::cross(AB, CD) == 0) CD = perp(AB);
    const Point2 D = C + CD;
    if (i % 2) b.add(Category::touching_end, {A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
    else b.add(Category::touching_end, {C.x, C.y, D.x, D.y, A.x, A.y, B.x, B.y});
  }
  // near parallel: parallel as decimals, collinear as decimals (overlapping or not), and
  // crossings at tiny angles
  for (int i = 0; i < 64; ++i) {
    const Point2 A = point();
    const Vec2 d{decimal(rng, -2, 2, 1), decimal(rng, -2, 2, 1)};
    if (d.x == 0 && d.y == 0) continue;
    // the decimals' sums, as a sheet would print them: A + k·d computed on hundredths
    auto along = [&](Point2 from, double k) {
      return Point2{std::round((from.x + k * d.x) * 100) / 100, std::round((from.y + k * d.y) * 100) / 100};
    };
    const Point2 B = along(A, 3);
    switch (i % 4) {
      case 0: {  // parallel, distinct
        const Vec2 off{decimal(rng, -2, 2, 1), decimal(rng, -2, 2, 1)};
        const Point2 C = along({A.x + off.x, A.y + off.y}, 0.5), D = along({A.x + off.x, A.y + off.y}, 2.5);
        b.add(Category::near_parallel, {A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
        break;
      }
      case 1: {  // collinear, overlapping: the trap of an exact == 0 test
        const Point2 C = along(A, 1), D = along(A, 5);
        b.add(Category::near_parallel, {A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
        break;
      }
      case 2: {  // collinear, apart
        const Point2 C = along(A, 4), D = along(A, 6);
        b.add(Category::near_parallel, {A.x, A.y, B.x, B.y, C.x, C.y, D.x, D.y});
        break;
      }
      default: {  // crossing at an angle of 1e-3 to 1e-8 radians, inside both segments
        const double angle = std::pow(10.0, -3 - 5 * rng.uniform());
        const Vec2 u = unit(Vec2{d.x, d.y});
        const Vec2 v{u.x * std::cos(angle) - u.y * std::sin(angle), u.x * std::sin(angle) + u.y * std::cos(angle)};
        const Point2 P = point();
        const double a = 1 + 4 * rng.uniform(), c = 1 + 4 * rng.uniform();
        b.add(Category::near_parallel,
              {P.x - a * u.x, P.y - a * u.y, P.x + a * u.x, P.y + a * u.y, P.x - c * v.x, P.y - c * v.y, P.x + c * v.x,
               P.y + c * v.y});
        break;
      }
    }
  }
  // integer figures scaled by 2^±10: G2Xiszero's absolute threshold holds over that range
  for (int i = 0; i < 20; ++i) {
    Case k{Fn::segments, Category::random, {}};
    for (int j = 0; j < 8; ++j) k.in[static_cast<std::size_t>(j)] = double(rng.integer(-10, 10));
    if (k.in[0] == k.in[2] && k.in[1] == k.in[3]) k.in[2] += 1;
    if (k.in[4] == k.in[6] && k.in[5] == k.in[7]) k.in[6] += 1;
    b.cases.push_back(scaled(k, i % 2 ? 10 : -10, {0, 1, 2, 3, 4, 5, 6, 7}));
  }
  return b.cases;
}

// ---- Exercise 3: circles (and, in space, spheres: the same cases with z) --------------------
struct Disc {
  Point2 C;
  double r;
};

// A ray from A aimed near the circle: through a point within 1.5 r of C.
Vec2 aimed(Rng& rng, Point2 A, Point2 C, double r) {
  const Point2 target{C.x + r * (3 * rng.uniform() - 1.5), C.y + r * (3 * rng.uniform() - 1.5)};
  const Vec2 v = target - A;
  const Vec2 w{std::round(v.x * 100) / 100, std::round(v.y * 100) / 100};  // as a sheet prints it
  return unit(w.x == 0 && w.y == 0 ? Vec2{1, 0} : w);
}

void circle_cases(Builder& b, Rng& rng, bool canonical) {
  auto disc = [&] {
    if (canonical) return Disc{{0, 0}, 1};
    return Disc{{decimal(rng, -5, 5), decimal(rng, -5, 5)}, decimal(rng, 0.5, 5)};
  };
  auto add = [&](Category c, Point2 A, Vec2 u, Disc d) {
    if (canonical) b.add(c, {A.x, A.y, u.x, u.y});
    else b.add(c, {A.x, A.y, u.x, u.y, d.C.x, d.C.y, d.r});
  };
  const double reach = canonical ? 4 : 10;
  while (b.cases.size() < 150) {
    const Disc d = disc();
    const Point2 A{decimal(rng, -reach, reach), decimal(rng, -reach, reach)};
    // a quarter of the rays in any direction (most pass by or point away), the rest aimed
    const Vec2 u = rng.chance(0.25) ? unit(direction(rng)) : aimed(rng, A, d.C, d.r);
    add(Category::random, A, u, d);
  }
  for (int i = 0; i < 30; ++i) {  // inside, well inside
    const Disc d = disc();
    const Vec2 w = unit(direction(rng));
    const double k = 0.1 + 0.8 * rng.uniform();
    add(Category::inside, {d.C.x + k * d.r * w.x, d.C.y + k * d.r * w.y}, unit(direction(rng)), d);
  }
  for (int i = 0; i < 16; ++i) {  // just inside: 1e-6 to 1e-9 of the radius in
    const Disc d = disc();
    const Vec2 w = unit(direction(rng));
    const double k = 1 - std::pow(10.0, -6 - i % 4);
    add(Category::just_inside, {d.C.x + k * d.r * w.x, d.C.y + k * d.r * w.y}, unit(direction(rng)), d);
  }
  // On the circle, exactly: a radius of 5 (×2^k) and the point (3, 4)·r/5 around C (integers).
  const std::array<Vec2, 6> axis{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 0}, {0, 1}}};
  for (int i = 0; i < 24; ++i) {
    const Disc d = canonical ? Disc{{0, 0}, 1} : Disc{{double(rng.integer(-4, 4)), double(rng.integer(-4, 4))}, 5};
    const double s = d.r / 5;
    const int q = i % 4;
    const Vec2 at = q == 0 ? Vec2{3 * s, 4 * s} : q == 1 ? Vec2{-4 * s, 3 * s} : q == 2 ? Vec2{5 * s, 0} : Vec2{0, -5 * s};
    const Point2 A = d.C + at;
    // q = 2 and 3 also get the tangent at A (t_proj = 0, d^2 = r^2: a hit at t = 0)
    Vec2 u = axis[static_cast<std::size_t>((i / 4) % 6)];
    if ((q == 2 || q == 3) && i / 4 % 2 == 0) u = q == 2 ? Vec2{0, 1} : Vec2{-1, 0};
    if (canonical && (q == 0 || q == 1)) continue;  // (3, 4)/5 is not exact: the canonical circle takes the axes
    add(Category::on_boundary, A, u, d);
  }
  for (int i = 0; i < 20; ++i) {  // tangent: exact (integers) and within rounding (decimals)
    const Disc d = canonical ? Disc{{0, 0}, 1} : Disc{{double(rng.integer(-4, 4)), double(rng.integer(-4, 4))}, double(rng.integer(1, 4))};
    if (i % 2 == 0) {
      const double side = i % 4 == 0 ? 1 : -1;
      add(Category::tangent, {d.C.x - 7, d.C.y + side * d.r}, {1, 0}, d);
    } else {
      const Vec2 w = unit(direction(rng));   // the tangent point's direction from C
      const Point2 T = d.C + d.r * w;
      const Vec2 u{-w.y, w.x};
      add(Category::tangent, T - 6 * u, u, d);
    }
  }
  if (canonical) {
    for (int i = 0; i < 12; ++i) {  // from far away, aimed at the circle
      const double far = std::pow(10.0, 6 + i % 7);
      const Vec2 w = unit(direction(rng));
      const Point2 A{far * w.x, far * w.y};
      const Point2 target{0.9 * (2 * rng.uniform() - 1), 0.9 * (2 * rng.uniform() - 1)};
      add(Category::far_origin, A, unit(target - A), {{0, 0}, 1});
    }
  } else {
    const std::size_t n = b.cases.size();
    for (std::size_t i = 0; i < 24; ++i) {
      const Case k = b.cases[(i * 7) % n];
      b.cases.push_back(scaled(k, i % 2 ? 60 : -60, {0, 1, 4, 5, 6}));
    }
  }
}

// ---- Exercise 4: the canonical square ---------------------------------------------------------
void square_cases(Builder& b, Rng& rng) {
  auto add = [&](Category c, Point2 A, Vec2 u) { b.add(c, {A.x, A.y, u.x, u.y}); };
  while (b.cases.size() < 150) {
    const Point2 A{decimal(rng, -6, 6), decimal(rng, -6, 6)};
    const Vec2 u = rng.chance(0.25) ? unit(direction(rng)) : aimed(rng, A, {0, 0}, 1);
    add(Category::random, A, u);
  }
  for (int i = 0; i < 30; ++i)
    add(Category::inside, {decimal(rng, -0.95, 0.95), decimal(rng, -0.95, 0.95)}, unit(direction(rng)));
  for (int i = 0; i < 12; ++i) {
    const double in = 1 - std::pow(10.0, -6 - i % 4);
    add(Category::just_inside, {i % 2 ? in : decimal(rng, -0.9, 0.9), i % 2 ? decimal(rng, -0.9, 0.9) : -in},
        unit(direction(rng)));
  }
  // on a side, exactly: entering (a hit at t = 0), leaving (no hit), along the side (no entry)
  const std::array<Vec2, 4> axes{{{-1, 0}, {1, 0}, {0, 1}, {0, -1}}};
  for (int i = 0; i < 24; ++i) {
    const double y = double(rng.integer(-3, 3)) / 4;
    const Vec2 u = axes[static_cast<std::size_t>(i % 4)];
    const Point2 A = i % 8 < 4 ? Point2{1, y} : Point2{y, -1};
    add(Category::on_boundary, A, i % 8 < 4 ? u : Vec2{u.y, u.x});
  }
  // corners: along a side's line onto a corner (exact), and through a corner (within rounding)
  for (int i = 0; i < 16; ++i) {
    const double sx = i % 2 ? 1 : -1, sy = i % 4 < 2 ? 1 : -1;
    if (i < 8) add(Category::corner, {sx, 3 * sy}, {0, -sy});
    else add(Category::corner, {(2 + i % 3) * sx, (2 + i % 3) * sy}, unit(Vec2{-sx, -sy}));
  }
  for (int i = 0; i < 12; ++i) {  // from far away
    const double far = std::pow(10.0, 6 + i % 7);
    const Vec2 w = unit(direction(rng));
    const Point2 A{far * w.x, far * w.y};
    const Point2 target{0.9 * (2 * rng.uniform() - 1), 0.9 * (2 * rng.uniform() - 1)};
    add(Category::far_origin, A, unit(target - A));
  }
}

// ---- The open questions: an ellipse, a rectangle --------------------------------------------
void transformed_cases(Builder& b, Rng& rng, bool ellipse) {
  auto add = [&](Category c, Point2 A, Vec2 u, Point2 C, double s1, double s2, double angle) {
    b.add(c, {A.x, A.y, u.x, u.y, C.x, C.y, s1, s2, angle});
  };
  auto angle = [&] { return rng.chance(0.5) ? 15.0 * double(rng.integer(0, 23)) : decimal(rng, -180, 180, 1); };
  while (b.cases.size() < 120) {
    const Point2 C{decimal(rng, -5, 5), decimal(rng, -5, 5)};
    const double s1 = decimal(rng, 0.5, 4), s2 = decimal(rng, 0.5, 4);
    const Point2 A{decimal(rng, -10, 10), decimal(rng, -10, 10)};
    // directions as a sheet gives them: two decimals, any length
    Vec2 u = aimed(rng, A, C, std::max(s1, s2));
    u = {std::round(u.x * (1 + 3 * rng.uniform()) * 100) / 100, std::round(u.y * (1 + 3 * rng.uniform()) * 100) / 100};
    if (u.x == 0 && u.y == 0) u = {1, 0.5};
    add(Category::random, A, u, C, s1, s2, angle());
  }
  for (int i = 0; i < 24; ++i) {  // lengths far from 1
    const Point2 C{decimal(rng, -3, 3), decimal(rng, -3, 3)};
    const double s1 = decimal(rng, 0.5, 3), s2 = decimal(rng, 0.5, 3);
    const Point2 A{decimal(rng, -8, 8), decimal(rng, -8, 8)};
    const Vec2 w = aimed(rng, A, C, std::max(s1, s2));
    const double k = std::array<double, 6>{0.01, 0.1, 0.37, 2.5, 7, 100}[static_cast<std::size_t>(i % 6)];
    add(Category::non_unit, A, {k * w.x, k * w.y}, C, s1, s2, angle());
  }
  for (int i = 0; i < 20; ++i) {  // inside
    const Point2 C{decimal(rng, -3, 3), decimal(rng, -3, 3)};
    const double s1 = decimal(rng, 1, 3), s2 = decimal(rng, 1, 3);
    const double a = angle() * 3.141592653589793 / 180;
    const double x = 0.6 * s1 * (2 * rng.uniform() - 1), y = 0.6 * s2 * (2 * rng.uniform() - 1);
    const Point2 A{C.x + x * std::cos(a) - y * std::sin(a), C.y + x * std::sin(a) + y * std::cos(a)};
    add(Category::inside, A, direction(rng), C, s1, s2, angle());
  }
  for (int i = 0; i < 16; ++i) {  // on the figure, exactly (angle 0, integers)
    const Point2 C{double(rng.integer(-3, 3)), double(rng.integer(-3, 3))};
    const double s1 = double(rng.integer(1, 4)), s2 = double(rng.integer(1, 4));
    const Point2 A = i % 2 ? Point2{C.x + s1, C.y} : Point2{C.x, C.y - s2};
    const std::array<Vec2, 4> dirs{{{-1, 0}, {1, 0}, {0, 1}, {0, -2}}};
    add(Category::on_boundary, A, i % 2 ? dirs[static_cast<std::size_t>(i / 2 % 4)] : Vec2{dirs[static_cast<std::size_t>(i / 2 % 4)].y, dirs[static_cast<std::size_t>(i / 2 % 4)].x}, C, s1, s2, i % 4 < 2 ? 0 : 180);
  }
  for (int i = 0; i < 10; ++i) {  // tangent (ellipse) or along a side's line onto a corner (rectangle), exact
    const Point2 C{double(rng.integer(-3, 3)), double(rng.integer(-3, 3))};
    const double s1 = double(rng.integer(1, 4)), s2 = double(rng.integer(1, 4));
    const double side = i % 2 ? 1 : -1;
    if (ellipse) add(Category::tangent, {C.x - 9, C.y + side * s2}, {2, 0}, C, s1, s2, 0);
    else add(Category::corner, {C.x + side * s1, C.y + 6}, {0, -3}, C, s1, s2, 0);
  }
  const std::size_t n = b.cases.size();
  for (std::size_t i = 0; i < 20; ++i) {
    const Case k = b.cases[(i * 11) % n];
    b.cases.push_back(scaled(k, i % 2 ? 60 : -60, {0, 1, 4, 5, 6, 7}));
  }
}

// ---- In space -------------------------------------------------------------------------------
geo::Vec3 direction3(Rng& rng) {
  for (;;) {
    const geo::Vec3 v{decimal(rng, -1, 1), decimal(rng, -1, 1), decimal(rng, -1, 1)};
    if (std::abs(v.x) + std::abs(v.y) + std::abs(v.z) >= 0.1) return v;
  }
}

geo::Vec3 aimed3(Rng& rng, geo::Point3 A, geo::Point3 C, double r) {
  const geo::Point3 target{C.x + r * (3 * rng.uniform() - 1.5), C.y + r * (3 * rng.uniform() - 1.5),
                           C.z + r * (3 * rng.uniform() - 1.5)};
  const geo::Vec3 v = target - A;
  const geo::Vec3 w{std::round(v.x * 100) / 100, std::round(v.y * 100) / 100, std::round(v.z * 100) / 100};
  return unit(w.x == 0 && w.y == 0 && w.z == 0 ? geo::Vec3{1, 0, 0} : w);
}

void sphere_cases(Builder& b, Rng& rng) {
  auto add = [&](Category c, geo::Point3 A, geo::Vec3 u, geo::Point3 C, double r) {
    b.add(c, {A.x, A.y, A.z, u.x, u.y, u.z, C.x, C.y, C.z, r});
  };
  auto point = [&](double reach) { return geo::Point3{decimal(rng, -reach, reach), decimal(rng, -reach, reach), decimal(rng, -reach, reach)}; };
  while (b.cases.size() < 120) {
    const geo::Point3 C = point(4), A = point(9);
    const double r = decimal(rng, 0.5, 4);
    add(Category::random, A, rng.chance(0.25) ? unit(direction3(rng)) : aimed3(rng, A, C, r), C, r);
  }
  for (int i = 0; i < 20; ++i) {
    const geo::Point3 C = point(3);
    const double r = decimal(rng, 1, 4);
    const geo::Vec3 w = unit(direction3(rng));
    const double k = 0.1 + 0.8 * rng.uniform();
    add(Category::inside, C + (k * r) * w, unit(direction3(rng)), C, r);
  }
  for (int i = 0; i < 12; ++i) {  // on the sphere (2, 3, 6)·r/7, exactly; tangents along an axis
    const geo::Point3 C{double(rng.integer(-3, 3)), double(rng.integer(-3, 3)), double(rng.integer(-3, 3))};
    const double r = 7;
    const geo::Point3 A = C + geo::Vec3{2, 3, 6};
    const std::array<geo::Vec3, 4> dirs{{{0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {0, 1, 0}}};
    if (i < 8) add(Category::on_boundary, A, dirs[static_cast<std::size_t>(i % 4)], C, r);
    else add(Category::tangent, C + geo::Vec3{-9, 0, i % 2 ? r : -r}, {1, 0, 0}, C, r);
  }
  for (int i = 0; i < 4; ++i) {  // on the sphere, along its tangent plane: a hit at t = 0
    const geo::Point3 C{double(rng.integer(-3, 3)), double(rng.integer(-3, 3)), double(rng.integer(-3, 3))};
    const double r = double(rng.integer(1, 5));
    add(Category::on_boundary, C + geo::Vec3{i % 2 ? r : -r, 0, 0}, i < 2 ? geo::Vec3{0, 1, 0} : geo::Vec3{0, 0, -1}, C, r);
  }
  const std::size_t n = b.cases.size();
  for (std::size_t i = 0; i < 20; ++i) {
    const Case k = b.cases[(i * 7) % n];
    b.cases.push_back(scaled(k, i % 2 ? 60 : -60, {0, 1, 2, 6, 7, 8, 9}));
  }
}

void cube_cases(Builder& b, Rng& rng) {
  auto add = [&](Category c, geo::Point3 A, geo::Vec3 u) { b.add(c, {A.x, A.y, A.z, u.x, u.y, u.z}); };
  while (b.cases.size() < 120) {
    const geo::Point3 A{decimal(rng, -5, 5), decimal(rng, -5, 5), decimal(rng, -5, 5)};
    add(Category::random, A, rng.chance(0.25) ? unit(direction3(rng)) : aimed3(rng, A, {0, 0, 0}, 1));
  }
  for (int i = 0; i < 20; ++i)
    add(Category::inside, {decimal(rng, -0.9, 0.9), decimal(rng, -0.9, 0.9), decimal(rng, -0.9, 0.9)},
        unit(direction3(rng)));
  const std::array<geo::Vec3, 6> axes{{{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (int i = 0; i < 18; ++i) {  // on the face x = 1, exactly
    const geo::Point3 A{1, double(rng.integer(-3, 3)) / 4, double(rng.integer(-3, 3)) / 4};
    add(Category::on_boundary, A, axes[static_cast<std::size_t>(i % 6)]);
  }
  for (int i = 0; i < 12; ++i) {  // onto an edge along a face's plane (exact), through a vertex (rounding)
    const double s = i % 2 ? 1 : -1;
    if (i < 6) add(Category::corner, {s, 4 * s, 0.5}, {0, -s, 0});
    else add(Category::corner, {3 * s, 3 * s, 3 * s}, unit(geo::Vec3{-s, -s, -s}));
  }
  for (int i = 0; i < 10; ++i) {
    const double far = std::pow(10.0, 6 + i % 7);
    const geo::Vec3 w = unit(direction3(rng));
    const geo::Point3 A{far * w.x, far * w.y, far * w.z};
    const geo::Point3 target{0.9 * (2 * rng.uniform() - 1), 0.9 * (2 * rng.uniform() - 1), 0.9 * (2 * rng.uniform() - 1)};
    add(Category::far_origin, A, unit(target - A));
  }
}

// ---- a sheet's instances ---------------------------------------------------------------------
double num(const nlohmann::json& j) { return j.get<double>(); }

}  // namespace

std::vector<Case> standard_cases(Fn fn, std::uint64_t seed) {
  Rng rng(seed, 0x636865636bULL + static_cast<std::uint64_t>(fn));  // "check" + the function
  Builder b{fn, {}};
  switch (fn) {
    case Fn::projection: return projection(rng);
    case Fn::segments: return segments(rng);
    case Fn::circle: circle_cases(b, rng, false); break;
    case Fn::circle_canonical: circle_cases(b, rng, true); break;
    case Fn::square_canonical: square_cases(b, rng); break;
    case Fn::ellipse: transformed_cases(b, rng, true); break;
    case Fn::rectangle: transformed_cases(b, rng, false); break;
    case Fn::sphere: sphere_cases(b, rng); break;
    case Fn::cube_canonical: cube_cases(b, rng); break;
  }
  return b.cases;
}

std::vector<Case> sheet_cases(const WorksheetSpec& spec, const SheetId& id) {
  WorksheetSet set(spec, id.seed);
  const Sheet sheet = set.rebuild(id);
  std::vector<Case> out;
  auto pair = [](const nlohmann::json& j, double* to) {
    to[0] = num(j[0]);
    to[1] = num(j[1]);
  };
  auto triple = [](const nlohmann::json& j, double* to) {
    to[0] = num(j[0]);
    to[1] = num(j[1]);
    to[2] = num(j[2]);
  };
  for (const ExerciseInstance& ex : sheet.exercises) {
    // the function of the exercise's kind (functions.h: the circle's own first; the canonical
    // circle takes the same instance carried to the origin)
    std::optional<Fn> fn;
    for (const FunctionInfo& f : all_functions())
      if (f.kind == ex.kind) {
        fn = f.fn;
        break;
      }
    if (!fn) continue;  // the vectors: no function of the course's to run
    const nlohmann::json j = nlohmann::json::parse(ex.instance);
    Case k{*fn, Category::sheet, {}};
    switch (*fn) {
      case Fn::projection: pair(j["A"], &k.in[0]), pair(j["B"], &k.in[2]), pair(j["C"], &k.in[4]); break;
      case Fn::segments:
        pair(j["A"], &k.in[0]), pair(j["B"], &k.in[2]), pair(j["C"], &k.in[4]), pair(j["D"], &k.in[6]);
        break;
      case Fn::circle:
      case Fn::circle_canonical: {
        const Vec2 u = unit(Vec2{num(j["u"][0]), num(j["u"][1])});
        const double r = num(j["r"]);
        k.fn = Fn::circle;
        pair(j["A"], &k.in[0]), pair(j["C"], &k.in[4]);
        k.in[2] = u.x, k.in[3] = u.y, k.in[6] = r;
        out.push_back(k);
        // the same ray seen in the circle's own frame: the canonical circle's case
        Case c{Fn::circle_canonical, Category::sheet, {}};
        c.in[0] = (k.in[0] - k.in[4]) / r, c.in[1] = (k.in[1] - k.in[5]) / r, c.in[2] = u.x, c.in[3] = u.y;
        out.push_back(c);
        continue;
      }
      case Fn::square_canonical: {
        const Vec2 u = unit(Vec2{num(j["u"][0]), num(j["u"][1])});
        pair(j["A"], &k.in[0]);
        k.in[2] = u.x, k.in[3] = u.y;
        break;
      }
      case Fn::ellipse:
      case Fn::rectangle:
        pair(j["A"], &k.in[0]), pair(j["u"], &k.in[2]), pair(j["C"], &k.in[4]);
        pair(j[*fn == Fn::ellipse ? "radii" : "half"], &k.in[6]);
        k.in[8] = num(j["angle"]);
        break;
      case Fn::sphere: {
        const geo::Vec3 u = unit(geo::Vec3{num(j["u"][0]), num(j["u"][1]), num(j["u"][2])});
        triple(j["A"], &k.in[0]), triple(j["C"], &k.in[6]);
        k.in[3] = u.x, k.in[4] = u.y, k.in[5] = u.z, k.in[9] = num(j["r"]);
        break;
      }
      case Fn::cube_canonical: {
        const geo::Vec3 u = unit(geo::Vec3{num(j["u"][0]), num(j["u"][1]), num(j["u"][2])});
        triple(j["A"], &k.in[0]);
        k.in[3] = u.x, k.in[4] = u.y, k.in[5] = u.z;
        break;
      }
    }
    out.push_back(k);
  }
  return out;
}

}  // namespace epure::check
