// A turned ellipse or rectangle decided on the decimals written (geometry/turned_written.h),
// against figures worked by hand that are on a boundary as decimals and not as their doubles.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "geometry/degenerate.h"
#include "geometry/quadratic.h"
#include "geometry/turned_written.h"

using namespace epure::geo;

namespace {

// The decimal a JSON text writes (its double correctly rounded by strtod). The texts are
// literals: they outlive the numbers.
Decimal d(const char* text) { return read_decimal(text, std::strtod(text, nullptr)); }
DPoint2 p(const char* x, const char* y) { return {d(x), d(y)}; }

struct Line {
  WrittenTurned w;
  Ray2 ray;
};
Line line(DPoint2 A, DPoint2 u, DPoint2 C, const char* sx, const char* sy, const char* angle) {
  return {{A, u, C, d(sx), d(sy), d(angle)}, {hi_point(A), hi_vec(u)}};
}
RayEllipse ellipse(const Line& l) {
  return intersect_written(l.w, l.w.u, l.ray, Ellipse{hi_point(l.w.C), l.w.sx.hi, l.w.sy.hi, l.w.angle_deg.hi});
}
RayRectangle rectangle(const Line& l) {
  return intersect_written(l.w, l.w.u, l.ray, Rectangle{hi_point(l.w.C), l.w.sx.hi, l.w.sy.hi, l.w.angle_deg.hi});
}

}  // namespace

TEST_CASE("turned figures: a quarter turn is read on the decimal written") {
  CHECK(quarter_turns(d("0")) == 0);
  CHECK(quarter_turns(d("90")) == 1);
  CHECK(quarter_turns(d("450.0")) == 1);
  CHECK(quarter_turns(d("-90")) == 3);
  CHECK(quarter_turns(d("-180")) == 2);
  CHECK(quarter_turns(d("7.2e2")) == 0);
  CHECK_FALSE(quarter_turns(d("90.00000000000000000001")));  // its double is 90, the decimal is not
  CHECK_FALSE(quarter_turns(d("45")));
  CHECK_FALSE(quarter_turns(d("1e300")));
}

TEST_CASE("turned ellipse at a quarter turn: tangent and on it as written") {
  // radii (0.3, 0.7) turned by 90°: its top in the world is C + (−0.7, 0)... its own x-axis is the
  // world's y: the vertex (0.3, 0) of its frame is C + (0, 0.3). The line y = C_y + 0.3 is tangent
  // there; 0.1 + 0.3 = 0.4 as decimals, not as doubles.
  const auto tangent = ellipse(line(p("-5", "0.4"), p("1", "0"), p("0.2", "0.1"), "0.3", "0.7", "90"));
  REQUIRE(tangent.hit);
  CHECK_FALSE(tangent.inside);
  CHECK(tangent.hit->t == doctest::Approx(5.2).epsilon(1e-15));
  CHECK(tangent.hit->N.y == doctest::Approx(1).epsilon(1e-15));
  // a hair above: a miss; a hair below: a chord
  CHECK_FALSE(ellipse(line(p("-5", "0.40000000000000000001"), p("1", "0"), p("0.2", "0.1"), "0.3", "0.7", "90")).hit);
  CHECK(ellipse(line(p("-5", "0.39999999999999999999"), p("1", "0"), p("0.2", "0.1"), "0.3", "0.7", "450")).hit);
  // A on the ellipse at that vertex: outside; heading in it hits at t = 0, heading out it is behind
  const auto in = ellipse(line(p("0.2", "0.4"), p("0.1", "-1"), p("0.2", "0.1"), "0.3", "0.7", "-270"));
  CHECK_FALSE(in.inside);
  REQUIRE(in.hit);
  CHECK(in.hit->t == 0);
  CHECK_FALSE(ellipse(line(p("0.2", "0.4"), p("0.1", "1"), p("0.2", "0.1"), "0.3", "0.7", "90")).hit);
  // a hair inside: inside, and it leaves at t > 0
  const auto hair = ellipse(line(p("0.2", "0.39999999999999999999"), p("0.1", "1"), p("0.2", "0.1"), "0.3", "0.7", "90"));
  CHECK(hair.inside);
  REQUIRE(hair.hit);
  CHECK(hair.hit->t >= 0);
}

TEST_CASE("turned ellipse with equal radii: a circle at any angle") {
  // radius 0.5 about (0.1, 0.2): the line y = 0.7 is tangent at (0.1, 0.7), whatever the angle
  const auto tangent = ellipse(line(p("-3", "0.7"), p("2", "0"), p("0.1", "0.2"), "0.5", "0.5", "37.3"));
  REQUIRE(tangent.hit);
  CHECK(tangent.hit->t == doctest::Approx(1.55).epsilon(1e-15));
  CHECK_FALSE(ellipse(line(p("-3", "0.70000000000000000001"), p("2", "0"), p("0.1", "0.2"), "0.5", "0.5", "37.3")).hit);
  // A on the circle (0.4, 0.6): 0.3² + 0.4² = 0.5²
  const auto on = ellipse(line(p("0.4", "0.6"), p("-1", "0"), p("0.1", "0.2"), "0.5", "0.5", "123"));
  CHECK_FALSE(on.inside);
  REQUIRE(on.hit);
  CHECK(on.hit->t == 0);
}

TEST_CASE("turned rectangle at a quarter turn: corners and sides as written") {
  // half-sizes (0.3, 0.1) turned by 90° about (0.7, 0.2): in the world it spans x in [0.6, 0.8],
  // y in [−0.1, 0.5]. The ray from (0.5, 0.4) along (1, 1) grazes its corner (0.6, 0.5) at
  // t = 0.1, through the figure's +y side (its own frame: X = (0.2, 0.2), U = (1, −1)), whose
  // normal is the world's −x.
  const auto corner = rectangle(line(p("0.5", "0.4"), p("1", "1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  REQUIRE(corner.hit);
  CHECK(corner.hit->t == doctest::Approx(0.1).epsilon(1e-14));
  REQUIRE(corner.canonical.face);
  CHECK(corner.canonical.face->axis == 1);
  CHECK(corner.hit->N.x == doctest::Approx(-1));
  // a hair above the corner (its double is on it): no hit
  CHECK_FALSE(rectangle(line(p("0.5", "0.40000000000000000001"), p("1", "1"), p("0.7", "0.2"), "0.3", "0.1", "90")).hit);
  // A on the side y = 0.5 (0.2 + 0.3), heading in: t = 0; a hair above: outside, t > 0
  const auto on = rectangle(line(p("0.7", "0.5"), p("0", "-1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  CHECK_FALSE(on.inside);
  REQUIRE(on.hit);
  CHECK(on.hit->t == 0);
  const auto above = rectangle(line(p("0.7", "0.50000000000000000001"), p("0", "-1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  REQUIRE(above.hit);
  CHECK(above.hit->t > 0);
  const auto below = rectangle(line(p("0.7", "0.49999999999999999999"), p("0", "-1"), p("0.7", "0.2"), "0.3", "0.1", "90"));
  CHECK(below.inside);
}

TEST_CASE("turned ellipse at multiples of 30° and 45°: exact in Q(√3) and Q(√2)") {
  // radii (7, 28) turned by 30°: x'²(3b² + a²)/4 = a²b² at x' = 8 along the world's x-axis, so
  // A = C + (8, 0) is on it (1 + 3·16 = 49 = 7²)
  const auto in = ellipse(line(p("8", "0"), p("-1", "0.3"), p("0", "0"), "7", "28", "30"));
  CHECK_FALSE(in.inside);
  REQUIRE(in.hit);
  CHECK(in.hit->t == 0);
  CHECK_FALSE(ellipse(line(p("8", "0"), p("1", "0.3"), p("0", "0"), "7", "28", "390")).hit);  // heading out
  CHECK(ellipse(line(p("7.99999999999999999999", "0"), p("1", "0.3"), p("0", "0"), "7", "28", "-330")).inside);
  CHECK_FALSE(ellipse(line(p("8.00000000000000000001", "0"), p("1", "0.3"), p("0", "0"), "7", "28", "30")).hit);
  // 60°: the same with the radii swapped
  CHECK_FALSE(ellipse(line(p("8", "0"), p("-1", "0.3"), p("0", "0"), "28", "7", "60")).inside);
  // 45°: b²(x + y)²/2 + a²(y − x)²/2 = a²b², which (x, y) = (1, 6), a = 5, b = 25 satisfy
  // (625·49/2 + 25·25/2 = 15,625); heading in along −(1, 1), it hits at t = 0
  const auto diagonal = ellipse(line(p("1", "6"), p("-0.1", "-0.1"), p("0", "0"), "5", "25", "45"));
  CHECK_FALSE(diagonal.inside);
  REQUIRE(diagonal.hit);
  CHECK(diagonal.hit->t == 0);
}

TEST_CASE("quadratic numbers: exact signs of p + q√K") {
  using exact::Quadratic;
  const auto q2 = [](double p, double q) { return Quadratic<2>{exact::exact_value(p), exact::exact_value(q)}; };
  CHECK(q2(1.4142135623730951, -1).sign() == 1);  // the double above √2
  CHECK(q2(-1.4142135623730951, 1).sign() == -1);
  CHECK(q2(1.4142135623730950, -1).sign() == -1);  // the one below
  CHECK(q2(0, 0).sign() == 0);
  const auto half = q2(0, 0.5);
  CHECK((half * half - q2(0.5, 0)).sign() == 0);  // (½√2)² = ½ exactly
  CHECK((half * half).value() == 0.5);
}

TEST_CASE("turned figures at other angles: decided where the filter is certain, refused within rounding") {
  // Ellipse radii (5, 3) and rectangle half-sizes (5, 3), centre (1.25, −0.5), turned by angles
  // whose cos and sin are no exact number of ours (17°, 17.5°, 123.4°; 15° and 36°, where cos 2θ
  // is a quadratic irrational). Points worked in 60-digit arithmetic (mpmath) and written with 30
  // digits: on the ellipse at φ = 0.7 (within 1e-29), 1e-9 outside and inside along the normal,
  // a tangent line through it, and a point on the rectangle's side x' = 5 (and 1e-9 beyond).
  struct Pt {
    const char* x;
    const char* y;
  };
  struct Case {
    const char* angle;
    Pt on, out, in, inward, tangent_start, tangent_start_out, tangent, side, side_out, side_inward;
  };
  const Case cases[] = {
    {"17", {"4.34205803601596720921933301789", "2.46629638524389655059974391491"}, {"4.34205803633267570557157696621", "2.46629638619241946984750815508"}, {"4.34205803569925871286708906956", "2.46629638429537363135197967474"}, {"-0.31670850", "-0.94852292"},
     {"6.23910387451149568955388008510", "1.83287939253940865394420739458"}, {"6.23910387482820418590612403343", "1.83287939348793157319197163475"}, {"-0.948522919247764240167273533606", "0.316708496352243948327768260163"},
     {"5.73915207509244067859578538771", "1.91816327957671912182599429350"}, {"5.73915207604874543455882086905", "1.91816327986909082654873102160"}, {"-1.0147791", "-0.10111075"}},
    {"17.5", {"4.31605480921602202968643490957", "2.49316639198111240952803217732"}, {"4.31605480952444114782374995789", "2.49316639293236297986552264720"}, {"4.31605480890760291154911986126", "2.49316639102986183919054170744"}, {"-0.30841912", "-0.95125057"},
     {"6.21855594989100296944813331568", "1.87632815570648231289506830487"}, {"6.21855595019942208758544836400", "1.87632815665773288323255877475"}, {"-0.951250570337490469880849203053", "0.308419118137315048316481936227"},
     {"5.71787895423686148409668818707", "1.95724594826959252925658274426"}, {"5.71787895519057843484491510821", "1.95724594857029832876085586588"}, {"-1.0138581", "-0.10996241"}},
    {"15", {"4.44369668872049827936189764473", "2.35657812840077108705613293909"}, {"4.44369668907011681794787493100", "2.35657812933766322464562381986"}, {"4.44369668837087974077592035846", "2.35657812746387894946664205832"}, {"-0.34961854", "-0.93689214"},
     {"6.31748096389948004090350688605", "1.65734105122881651451459217861"}, {"6.31748096424909857948948417232", "1.65734105216570865210408305938"}, {"-0.936892137589490880770804620660", "0.349618538585977286270770380237"},
     {"5.82081008634282067139981716102", "1.76002105180167209849423738785"}, {"5.82081008730874649768888544777", "1.76002105206049114359675815020"}, {"-1.0176896", "-0.065633880"}},
    {"36", {"3.20786667016744793882193453490", "3.31136396124135029216754013961"}, {"3.20786667015809284889330040656", "3.31136396224130653235629318358"}, {"3.20786667017680302875056866324", "3.31136396024139405197878709565"}, {"0.0093550899", "-0.99995624"},
     {"5.20777915054495402675221004409", "3.33007414109861854885042832319"}, {"5.20777915053559893682357591575", "3.33007414209857478903918136715"}, {"-0.999956240188753043965137754598", "-0.00935508992863412834144409178804"},
     {"4.70729971958226399134276113128", "3.24794325583731306994582319038"}, {"4.70729972039128098571770855538", "3.24794325642509832223829631955"}, {"-0.92657404", "-0.42598185"}},
    {"123.4", {"-2.46862574552359957531055864477", "1.62874604120148177952087929811"}, {"-2.46862574652295080517107876624", "1.62874604123749732305788393267"}, {"-2.46862574452424834545003852329", "1.62874604116546623598387466354"}, {"0.99935123", "-0.036015544"},
     {"-2.39659465844959030617925299357", "3.62744850092252202247667600495"}, {"-2.39659465944894153603977311505", "3.62744850095853756601368063952"}, {"-0.0360155435370046345656528255990", "-0.999351229860520121477898353423"},
     {"-2.33725156368838435521858158119", "3.12375857623203719436565988170"}, {"-2.33725156423886509530357714202", "3.12375857706688505762906643274"}, {"0.38351117", "-0.94494401"}},
  };
  const auto q = [](Pt v) { return p(v.x, v.y); };
  for (const Case& c : cases) {
    CAPTURE(c.angle);
    const DPoint2 C = p("1.25", "-0.5");
    auto el = [&](Pt A, Pt u) { return ellipse(line(q(A), q(u), C, "5", "3", c.angle)); };
    auto rect = [&](Pt A, Pt u) { return rectangle(line(q(A), q(u), C, "5", "3", c.angle)); };
    // 1e-9 from the boundary: far beyond the filter's bound, decided as the figure lies
    const auto out = el(c.out, c.inward);
    CHECK_FALSE(out.inside);
    REQUIRE(out.hit);
    CHECK(out.hit->t > 0);
    CHECK(el(c.in, c.inward).inside);
    CHECK_FALSE(el(c.tangent_start_out, c.tangent).hit);  // beside the ellipse by 1e-9
    const auto beyond = rect(c.side_out, c.side_inward);
    CHECK_FALSE(beyond.inside);
    REQUIRE(beyond.hit);
    CHECK(beyond.hit->t > 0);
    // within 1e-29 of the boundary, tangent to 1e-29: no double computation can tell, refused
    CHECK_THROWS_WITH_AS(el(c.on, c.inward), doctest::Contains("ray_ellipse: the ray is within rounding"),
                         DegenerateFigure);
    CHECK_THROWS_AS(el(c.tangent_start, c.tangent), DegenerateFigure);
    CHECK_THROWS_WITH_AS(rect(c.side, c.side_inward), doctest::Contains("ray_rectangle"), DegenerateFigure);
  }
  // equal radii stay a circle at any angle, decided exactly: no refusal
  CHECK(ellipse(line(p("3", "4"), p("-1", "0"), p("0", "0"), "5", "5", "17")).hit->t == 0);
}

TEST_CASE("turned ellipse values: within 4 ulps of the decimal figure, near tangency too") {
  // |x − exact| in units of `unit`
  const auto off = [](double x, double exact, double unit) { return std::abs(x - exact) / unit; };
  const auto ulp = [](double x) { return std::nextafter(std::abs(x), INFINITY) - std::abs(x); };
  SUBCASE("1. at 57°, 1e-10 of β² from tangency: the kernels' carried ray (cos θ, sin θ and A − C rounded) "
          "was 29,514 ulps off in t; the values come from the decimals in double-double") {
    // worked in 60-digit arithmetic (mpmath): t along u, I = A + t·u, the outward normal
    const auto e = ellipse(line(p("1.173660959529485285e0", "1.0753147787317803645e1"), p("-0.00049299247", "-0.00087003358"),
                                p("2.012", "-4.116"), "8.265", "8.059", "57"));
    REQUIRE(e.hit);
    const double S = 10.753147787317803645;  // the figure's largest datum
    CHECK(off(e.hit->t, 12548.39458878290875533086, ulp(12548.4)) <= 4);
    CHECK(off(e.hit->I.x, -5.012603083329235196075184, ulp(S)) <= 4);
    CHECK(off(e.hit->I.y, -0.1643768800136183022138486, ulp(S)) <= 4);
    CHECK(off(e.hit->N.x, -0.8700265278588711778759098, ulp(1.0)) <= 4);
    CHECK(off(e.hit->N.y, 0.4930049095311697341786966, ulp(1.0)) <= 4);
  }
  SUBCASE("2. a quarter turn, tangent as written at the end of a thin ellipse's axis: N is the axis (it was "
          "26 ulps of its bound off, from the carried ray's canonical point)") {
    const auto e = ellipse(line(p("-3.469", "181.567"), p("0", "-0.073"), p("1.244", "94.957"), "0.116", "4.713", "270"));
    REQUIRE(e.hit);
    CHECK(off(e.hit->t, 1186.438356164383561643836, ulp(1186.4)) <= 4);
    CHECK(off(e.hit->N.x, -1, ulp(1.0)) <= 4);
    CHECK(off(e.hit->N.y, 0, ulp(181.567) / 0.116) <= 4);
  }
}
