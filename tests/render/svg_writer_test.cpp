#include "render/svg_writer.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "exercises/rng.h"

using epure::render::append_escaped;
using epure::render::format_number;
using epure::render::SvgWriter;

namespace {

std::string escaped(std::string_view s, bool attribute) {
  std::string out;
  append_escaped(out, s, attribute);
  return out;
}

}  // namespace

TEST_CASE("format_number: short, fixed, no negative zero") {
  CHECK(format_number(0) == "0");
  CHECK(format_number(2.0) == "2");
  CHECK(format_number(1.5) == "1.5");
  CHECK(format_number(1.25) == "1.25");
  CHECK(format_number(123.456) == "123.46");
  CHECK(format_number(-2.5) == "-2.5");
  CHECK(format_number(10) == "10");
  CHECK(format_number(100.001) == "100");
  CHECK(format_number(1e6) == "1000000");
  SUBCASE("negative zero and tiny negatives print as 0") {
    CHECK(format_number(-0.0) == "0");
    CHECK(format_number(-0.001) == "0");
    CHECK(format_number(-0.004) == "0");
  }
  SUBCASE("other precisions") {
    CHECK(format_number(3.14159, 0) == "3");
    CHECK(format_number(3.14159, 4) == "3.1416");
    CHECK(format_number(-0.00001, 4) == "0");
  }
  SUBCASE("not finite: refused") {
    CHECK_THROWS_AS(format_number(std::nan("")), std::domain_error);
    CHECK_THROWS_AS(format_number(std::numeric_limits<double>::infinity()), std::domain_error);
  }
}

TEST_CASE("escaping: every string the writer emits is well-formed XML") {
  CHECK(escaped("a < b && c > d", false) == "a &lt; b &amp;&amp; c &gt; d");
  CHECK(escaped("say \"hi\"", false) == "say \"hi\"");
  CHECK(escaped("say \"hi\"", true) == "say &quot;hi&quot;");
  CHECK(escaped("it's", true) == "it's");  // attributes are double-quoted
  CHECK(escaped("a\tb\nc\rd", true) == "a&#9;b&#10;c&#13;d");
  CHECK(escaped("a\nb", false) == "a\nb");
  SUBCASE("controls XML forbids are dropped") {
    CHECK(escaped(std::string("a\x01\x1f\x7f") + "b", false) == "ab");
    CHECK(escaped(std::string("a\0b", 3), false) == "ab");
  }
  SUBCASE("UTF-8 kept; invalid bytes become U+FFFD") {
    CHECK(escaped("é → √ ‖u‖", false) == "é → √ ‖u‖");
    CHECK(escaped("a\xff"
                  "b",
                  false) ==
          "a\xEF\xBF\xBD"
          "b");
    CHECK(escaped("\xC3", false) == "\xEF\xBF\xBD");                          // truncated sequence
    CHECK(escaped("\xC0\xAF", false) == "\xEF\xBF\xBD\xEF\xBF\xBD");          // overlong '/'
    CHECK(escaped("\xED\xA0\x80", false).find("\xED") == std::string::npos);  // a surrogate
    CHECK(escaped("\xEF\xBF\xBF", false).empty());  // U+FFFF is not an XML character
  }
}

TEST_CASE("SvgWriter: balanced tags, attributes in order, indentation outside text") {
  SvgWriter w;
  w.declaration();
  w.start("svg", {{"xmlns", "http://www.w3.org/2000/svg"}, {"width", 10.5}, {"height", 3}});
  w.element("title", {}, "A & B");
  w.start("g", {{"class", "data"}, {"id", "p1"}});
  w.element("path", {{"d", "M0 0 L1 1"}, {"stroke", "#000"}});
  w.end("g");
  w.start_inline("text", {{"x", 1.0}, {"y", -0.0}});
  w.text("t");
  w.start_inline("tspan", {{"dy", 2.5}});
  w.text("ab<");
  w.end("tspan");
  w.end("text");
  w.end("svg");
  const std::string expected =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10.5\" height=\"3\">\n"
      " <title>A &amp; B</title>\n"
      " <g class=\"data\" id=\"p1\">\n"
      "  <path d=\"M0 0 L1 1\" stroke=\"#000\"/>\n"
      " </g>\n"
      " <text x=\"1\" y=\"0\">t<tspan dy=\"2.5\">ab&lt;</tspan></text>\n"
      "</svg>\n";
  CHECK(w.finish() == expected);
}

TEST_CASE("SvgWriter: misuse is refused") {
  SUBCASE("1. closing the wrong tag") {
    SvgWriter w;
    w.start("svg");
    w.start("g");
    CHECK_THROWS_AS(w.end("svg"), std::logic_error);
  }
  SUBCASE("2. closing with nothing open") {
    SvgWriter w;
    CHECK_THROWS_AS(w.end("g"), std::logic_error);
  }
  SUBCASE("3. finishing with an element open") {
    SvgWriter w;
    w.start("svg");
    CHECK(w.depth() == 1);
    CHECK_THROWS_AS(w.finish(), std::logic_error);
  }
  SUBCASE("4. text outside any element") {
    SvgWriter w;
    CHECK_THROWS_AS(w.text("x"), std::logic_error);
  }
  SUBCASE("5. a declaration after content") {
    SvgWriter w;
    w.element("svg");
    CHECK_THROWS_AS(w.declaration(), std::logic_error);
  }
  SUBCASE("6. a NaN attribute") {
    SvgWriter w;
    CHECK_THROWS_AS(w.element("rect", {{"x", std::nan("")}}), std::domain_error);
  }
}

TEST_CASE("SvgWriter: ids count per prefix, deterministically") {
  SvgWriter a, b;
  for (SvgWriter* w : {&a, &b}) {
    CHECK(w->next_id("clip") == "clip1");
    CHECK(w->next_id("panel") == "panel1");
    CHECK(w->next_id("clip") == "clip2");
  }
}

TEST_CASE("SvgWriter: the streamed form writes what the list form writes") {
  SvgWriter a, b;
  for (SvgWriter* w : {&a, &b}) w->start("g");
  a.element("path", {{"d", "M0 0"}, {"stroke-width", 1.25}, {"fill", "a\"b"}});
  b.open("path");
  b.attribute("d", "M0 0");
  b.attribute("stroke-width", 1.25);
  b.attribute("fill", "a\"b");
  b.close_empty();
  a.start_inline("text", {{"x", 1.0}});
  b.open("text");
  b.attribute("x", 1.0);
  b.close_start_inline();
  for (SvgWriter* w : {&a, &b}) {
    w->text("t");
    w->end("text");
    w->end("g");
  }
  CHECK(a.finish() == b.finish());
  SUBCASE("misuse") {
    SvgWriter w;
    CHECK_THROWS_AS(w.attribute("x", 1.0), std::logic_error);  // no start tag
    w.open("svg");
    CHECK_THROWS_AS(w.open("g"), std::logic_error);  // the previous tag is still open
    CHECK_THROWS_AS(w.finish(), std::logic_error);
  }
}

TEST_CASE("SvgWriter: open and end indent as start and end do, at any depth and tag length") {
  // open() and end() write a usual tag in one append and a deep or long one piece by piece:
  // against start() and end(), whose bytes are the element form's, to depth 80 with tags of 1
  // to 70 characters, inline content and empty elements between.
  SvgWriter a, b;
  std::vector<std::string> tags;
  for (int depth = 0; depth < 80; ++depth) {
    const std::string tag = std::string(1, static_cast<char>('a' + depth % 26)) + std::string(static_cast<std::size_t>(depth * 7 % 70), 'x');
    tags.push_back(tag);
    a.start(tag);
    b.open(tag);
    b.close_start();
    if (depth % 9 == 4) {
      a.element("leaf");
      b.open("leaf");
      b.close_empty();
      a.start_inline("t");
      b.open("t");
      b.close_start_inline();
      for (SvgWriter* w : {&a, &b}) {
        w->text("x");
        w->end("t");
      }
    }
  }
  for (auto it = tags.rbegin(); it != tags.rend(); ++it)
    for (SvgWriter* w : {&a, &b}) w->end(*it);
  const std::string out = a.finish();
  CHECK(out == b.finish());
  // The same document written out by hand: one element a line, indented by its depth.
  std::string expected;
  const auto indent = [&](int depth) { expected += "\n" + std::string(static_cast<std::size_t>(depth), ' '); };
  for (int depth = 0; depth < 80; ++depth) {
    if (depth > 0) indent(depth);
    expected += "<" + tags[static_cast<std::size_t>(depth)] + ">";
    if (depth % 9 == 4) {
      indent(depth + 1);
      expected += "<leaf/>";
      indent(depth + 1);
      expected += "<t>x</t>";
    }
  }
  for (int depth = 79; depth >= 0; --depth) {
    if (depth < 79) indent(depth);  // the innermost element has no children
    expected += "</" + tags[static_cast<std::size_t>(depth)] + ">";
  }
  CHECK(out == expected + "\n");
}

TEST_CASE("SvgWriter: a number attribute is ` name=\"` format_number `\"`, short or long, near or far") {
  // The writer puts a usual name and number in one append and falls back to piece by piece for
  // a long name or a number beyond the fast form: the same bytes either way.
  epure::Rng rng(7, 3);
  const std::string long_name(40, 'n');
  for (int i = 0; i < 20000; ++i) {
    const double v = (rng.uniform() - 0.5) * std::pow(10.0, static_cast<double>(rng.integer(-3, 15)));
    const std::string name = i % 5 == 0 ? long_name : std::string(static_cast<std::size_t>(rng.integer(1, 32)), 'a');
    CAPTURE(v);
    CAPTURE(name);
    SvgWriter w;
    w.open("g");
    w.attribute(name, v);
    w.close_empty();
    CHECK(w.finish() == "<g " + name + "=\"" + format_number(v) + "\"/>\n");
  }
}

TEST_CASE("format_number: rounds half away from zero, as llround of the scaled value, over random values") {
  // The reference: the plain way (llround of v·10^d, then the integer and its decimals), which
  // the writer's digit loop must match byte for byte, halves and near-halves included.
  const auto reference = [](double v, int d) {
    long long scale = 1;
    for (int k = 0; k < d; ++k) scale *= 10;
    const long long n = std::llround(v * static_cast<double>(scale));
    if (n == 0) return std::string("0");
    const unsigned long long m = static_cast<unsigned long long>(n < 0 ? -n : n);
    std::string s = fmt::format("{}{}", n < 0 ? "-" : "", m / static_cast<unsigned long long>(scale));
    std::string frac = fmt::format("{:0{}}", m % static_cast<unsigned long long>(scale), d);
    while (!frac.empty() && frac.back() == '0') frac.pop_back();
    if (d > 0 && !frac.empty()) s += "." + frac;
    return s;
  };
  epure::Rng rng(99, 1);
  for (int i = 0; i < 200000; ++i) {
    const int d = static_cast<int>(rng.integer(0, 6));
    double v = 0;
    switch (i % 4) {
      case 0: v = static_cast<double>(rng.integer(-8000000, 8000000)) / 8.0; break;  // exact halves
      case 1: v = (static_cast<double>(rng.integer(-1000000, 1000000)) + 0.5) / std::pow(10.0, d); break;
      case 2: v = std::nextafter((static_cast<double>(rng.integer(-100000, 100000)) + 0.5) / std::pow(10.0, d),
                                 rng.chance(0.5) ? 1e9 : -1e9); break;
      default: v = (rng.uniform() - 0.5) * std::pow(10.0, static_cast<double>(rng.integer(0, 11)));
    }
    CAPTURE(v);
    CAPTURE(d);
    REQUIRE(epure::render::format_number(v, d) == reference(v, d));
  }
}
