// The shared pieces of the platform exports: Cloze escaping, Moodle's grades, CDATA, numbers
// and tolerances as the importers read them.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <string>

#include "exercises/rng.h"
#include "export/export_set.h"
#include "export/moodle_xml.h"

using namespace epure;
using namespace epure::exporting;

TEST_CASE("cloze_escape: nothing in an answer or a feedback can end a Cloze part") {
  const std::string s = cloze_escape("a}b#c~d\\e&f<g>=h%");
  CHECK(s == "a&#125;b&#35;c&#126;d&amp;#92;e&amp;f<g>&#61;h&#37;");
  // the importer ends an answer at ~ # } not preceded by \, & or &amp;: every # left follows one
  for (std::size_t i = 0; i < s.size(); ++i) {
    CAPTURE(i);
    CHECK(s[i] != '}');
    CHECK(s[i] != '~');
    CHECK(s[i] != '\\');
    if (s[i] == '#') CHECK((s[i - 1] == '&' || (i >= 5 && s.compare(i - 5, 5, "&amp;") == 0)));
  }
  // an option starting with = or % would be read as its grade
  CHECK(cloze_escape("=x")[0] == '&');
  CHECK(cloze_escape("%50%x")[0] == '&');
  // an HTML entity survives the importer's one decoding: &lt; is written &amp;lt;
  CHECK(cloze_escape("x &lt; 1") == "x &amp;lt; 1");
}

TEST_CASE("cdata: a ]]> inside is split across two sections") {
  CHECK(cdata("a") == "<![CDATA[a]]>");
  CHECK(cdata("a]]>b") == "<![CDATA[a]]]]><![CDATA[>b]]>");
  CHECK(cdata("]]>]]>") == "<![CDATA[]]]]><![CDATA[>]]]]><![CDATA[>]]>");
}

TEST_CASE("moodle_fraction: only Moodle's grades") {
  CHECK(moodle_fraction(100) == "100");
  CHECK(moodle_fraction(100.0 / 3) == "33.33333");
  CHECK(moodle_fraction(-50) == "-50");
  CHECK(moodle_fraction(100.0 / 6) == "16.66667");
  CHECK(moodle_fraction(0) == "0");
  CHECK_THROWS_AS(moodle_fraction(45), ExportError);
  CHECK_THROWS_AS(moodle_fraction(100.0 / 7 + 0.01), ExportError);
}

TEST_CASE("shortest: the value reads back exactly, with a '.' and no '+'") {
  for (double x : {0.26229508196721313, -18.0, 24.200000000000006, 1e-7, -0.0, 123456789.125}) {
    CAPTURE(x);
    const std::string s = shortest(x);
    CHECK(s.find(',') == std::string::npos);
    CHECK(s.find('+') == std::string::npos);
    CHECK(std::stod(s) == x);
  }
  CHECK(shortest(-0.0) == "0");
  CHECK_THROWS_AS(shortest(NAN), ExportError);
}

TEST_CASE("conservative_width: never looser than the key once Moodle widens it, and close to it") {
  Rng rng(14);
  for (int i = 0; i < 20000; ++i) {
    const double width = std::pow(10.0, -4 + 5 * rng.uniform());
    const double value = (rng.uniform() - 0.5) * std::pow(10.0, 6 * rng.uniform());
    CAPTURE(width);
    CAPTURE(value);
    const double t = conservative_width(width, value);
    // Moodle: tolerance + 10^-14·max(tolerance, |value|, 10^-14), read from the decimal written
    const double read = std::stod(shortest(t));
    const double moodle = read + 1e-14 * std::max({read, std::abs(value), 1e-14});
    CHECK(moodle <= width);
    CHECK(read >= 0.999 * width - 1e-12 * std::max(1.0, std::abs(value)));
    CHECK(shortest(t).size() <= 12);
  }
}

TEST_CASE("rule_width: the key's rule as an absolute half-width") {
  ToleranceRule r;
  r.kind = ToleranceRule::Kind::isclose;
  r.rel = 1e-3;
  r.abs = 0.0075;
  CHECK(rule_width(r, 2) == doctest::Approx(0.0075).epsilon(1e-15));
  CHECK(rule_width(r, -100) == doctest::Approx(0.1).epsilon(1e-15));
  r.kind = ToleranceRule::Kind::distance;
  r.abs = 0.01;
  // both coordinates within abs/√2: the point within abs
  CHECK(std::hypot(rule_width(r, 5), rule_width(r, 5)) <= 0.01 * (1 + 1e-15));
}

namespace {

// HTML entities decoded once (the importer's html_entity_decode, or a browser showing HTML).
std::string entities(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '&') {
      const auto semi = s.find(';', i);
      const std::string_view e = s.substr(i + 1, semi - i - 1);
      if (e == "amp") out += '&';
      else if (e == "lt") out += '<';
      else if (e == "gt") out += '>';
      else if (!e.empty() && e[0] == '#') out += static_cast<char>(std::stoi(std::string(e.substr(1))));
      else out += std::string(s.substr(i, semi - i + 1));
      i = semi;
    } else {
      out += s[i];
    }
  }
  return out;
}

// The importer's reading of one answer or feedback (qtype_multianswer_extract_question), once
// found: entities decoded once, then \} and \# unescaped. What it stores is HTML.
std::string moodle_reads(std::string_view s) {
  std::string out = entities(s);
  for (std::string_view escaped : {"\\}", "\\#"})
    for (std::size_t at; (at = out.find(escaped)) != std::string::npos;) out.erase(at, 1);
  return out;
}

// Where the importer ends an answer (at ~ # } not preceded by \, & or &amp;) or a feedback (at ~ }
// not preceded by \), in text without raw '~'.
std::size_t end_of(std::string_view s, std::size_t from, std::string_view stops, bool amp_escapes) {
  for (std::size_t i = from; i < s.size(); ++i) {
    const bool after_amp = (i > 0 && s[i - 1] == '&') || (i >= 5 && s.substr(i - 5, 5) == "&amp;");
    if (stops.find(s[i]) != std::string_view::npos && !(i > 0 && (s[i - 1] == '\\' || (amp_escapes && after_amp))))
      return i;
  }
  return s.size();
}

}  // namespace

TEST_CASE("cloze_part: answers and feedback with } # ~ \\ & < read back as written") {
  // what a browser shows of the stored HTML must be what it shows of ours (\} and \# included)
  const std::string nasty = "a}b#c~d\\e\\}f\\#=h%&amp;f&lt;g <sub>x</sub>";
  Part p;
  p.type = Part::Type::choice;
  p.options = {{"yes", nasty, true}, {"no", "no " + nasty, false}};
  MistakeAnswer m;
  m.code = "t_swapped";
  m.options = {"no"};
  m.feedback_html = "why: " + nasty;
  p.mistakes = {m};
  const std::string s = cloze_part(p, 3);
  REQUIRE(s.rfind("{3:MULTICHOICE:", 0) == 0);
  // the part ends at its last character, and nowhere before
  const std::size_t body = std::string("{3:MULTICHOICE:").size();
  CHECK(end_of(s, body, "}", false) == s.size() - 1);
  CHECK(s.find('~', body) == s.find("~no"));  // the only separator
  const std::string first = s.substr(body, s.find('~', body) - body);
  const std::string second = s.substr(s.find('~', body) + 1, s.size() - 1 - s.find('~', body) - 1);
  // first: "=" + answer; second: answer # feedback
  CHECK(end_of(first, 0, "#}", true) == first.size());
  CHECK(entities(moodle_reads(first.substr(1))) == entities(nasty));
  const std::size_t hash = end_of(second, 0, "#}", true);
  REQUIRE(hash < second.size());
  CHECK(entities(moodle_reads(second.substr(0, hash))) == entities("no " + nasty));
  CHECK(end_of(second, hash + 1, "}", false) == second.size());
  CHECK(entities(moodle_reads(second.substr(hash + 1))) == entities("why: " + nasty));
}

TEST_CASE("cloze_part: a number: the right value first, the mistakes, a wide wrong answer last") {
  Part p;
  p.type = Part::Type::number;
  p.value = -0.1 + 0.3;  // 0.19999999999999998: written so that it reads back exactly
  p.width = 0.007499;
  MistakeAnswer m;
  m.code = "far_intersection";
  m.value = 2.5;
  m.width = 0.01499;
  m.feedback_html = "far";
  p.mistakes = {m};
  CHECK(cloze_part(p, 2) == "{2:NUMERICAL:=0.19999999999999998:0.007499~%0%2.5:0.01499#far~%0%999999999999999999999999:0}");
  p.type = Part::Type::faces;
  p.options = {{"+x", "+x", true}, {"+y", "+y", true}, {"-x", "-x", false}, {"none", "none", false}};
  m.options = {"-x"};
  p.mistakes = {m};
  // one list of every set of the sides offered (2³ here), the key's whole set right
  CHECK(cloze_part(p, 1) == "{1:MULTICHOICE:none~+x~+y~-x#far~=+x, +y~+x, -x~+y, -x~+x, +y, -x}");
}

TEST_CASE("face_sets: every set of sides once, the empty set first, by size") {
  Part square;
  square.type = Part::Type::faces;
  for (const char* f : {"+x", "+y", "-x", "-y", "none"}) square.options.push_back({f, f, false});
  const auto sets = face_sets(square);
  CHECK(sets.size() == 16);
  CHECK(sets.front().empty());
  CHECK(sets[1] == std::vector<std::string>{"+x"});
  CHECK(sets[2] == std::vector<std::string>{"+y"});
  CHECK(sets[5] == std::vector<std::string>{"+x", "+y"});
  CHECK(sets.back() == std::vector<std::string>{"+x", "+y", "-x", "-y"});
  CHECK(face_set_html(square, {}) == "none");
  CHECK(face_set_html(square, {"+x", "-y"}) == "+x, -y");
  Part cube = square;
  cube.options.insert(cube.options.end() - 1, {{"+z", "+z", false}, {"-z", "-z", false}});
  const auto cube_sets = face_sets(cube);
  CHECK(cube_sets.size() == 64);
  for (std::size_t i = 0; i < cube_sets.size(); ++i) {
    CAPTURE(i);
    for (std::size_t j = 0; j < i; ++j) CHECK(cube_sets[i] != cube_sets[j]);
    if (i > 0) CHECK(cube_sets[i - 1].size() <= cube_sets[i].size());
  }
}

TEST_CASE("cloze_part: a field the case does not ask looks like the others and is marked for nothing") {
  const ClozeContext context{true, "— (does not apply)", "not marked"};
  SUBCASE("a number: a box of the same width, taking a dash") {
    Part p;
    p.type = Part::Type::number;
    p.asked = false;
    p.points = 0;
    const std::string s = cloze_part(p, 0, context);
    CHECK(s == "{0:SHORTANSWER:=-~=\u2013~=\u2014~=\u2212~%0%*#not marked~%0%999999999999999999999999}");
    Part asked;
    asked.value = 1.5;
    asked.width = 0.005;
    const std::string n = cloze_part(asked, 4, context);
    // Moodle sizes a box after its longest answer: both end with the same 24-digit one
    CHECK(n.substr(n.rfind('~')) == "~%0%999999999999999999999999:0}");
  }
  SUBCASE("a choice: the same list, with the does-not-apply option right only where not asked") {
    Part p;
    p.type = Part::Type::choice;
    p.options = {{"behind", "behind", true}, {"miss", "miss", false}};
    CHECK(cloze_part(p, 2, context) == "{2:MULTICHOICE:=behind~miss~\u2014 (does not apply)}");
    p.asked = false;
    p.options[0].right = false;
    CHECK(cloze_part(p, 0, context) ==
          "{0:MULTICHOICE:behind#not marked~miss#not marked~=\u2014 (does not apply)}");
    CHECK(cloze_part(p, 0, ClozeContext{}).find('=') == std::string::npos);  // only offered when asked for
  }
}

TEST_CASE("solution_html: the key's steps, its diagrams at the writer's path, each run of answers one table") {
  Variant v;
  v.solution_images.push_back({"S-2-key-1.png", "image/png", "…", 480, "a \"ray\" & a circle"});
  using K = SolutionBlock::Kind;
  v.solution = {{K::text, "t = 1", {}, -1},       {K::image, {}, {}, 0},
                {K::answer, "t =", "1", -1},       {K::answer, "I =", "(1, 2)", -1},
                {K::heading, "Check", {}, -1},     {K::answer, "N =", "(0, 1)", -1}};
  const std::string moodle = solution_html(v, "@@PLUGINFILE@@/");
  CHECK(moodle ==
        "<p>t = 1</p>\n"
        "<p><img src=\"@@PLUGINFILE@@/S-2-key-1.png\" alt=\"a &quot;ray&quot; &amp; a circle\" width=\"480\"/></p>\n"
        "<table><tbody>\n<tr><td>t =</td><td>1</td></tr>\n<tr><td>I =</td><td>(1, 2)</td></tr>\n</tbody></table>\n"
        "<p><strong>Check</strong></p>\n"
        "<table><tbody>\n<tr><td>N =</td><td>(0, 1)</td></tr>\n</tbody></table>\n");
  CHECK(solution_html(v, "../images/").find("src=\"../images/S-2-key-1.png\"") != std::string::npos);
  CHECK(solution_html(Variant{}, "x/").empty());
}
