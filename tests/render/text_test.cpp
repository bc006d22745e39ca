#include "render/text.h"

#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "render/font_metrics.h"
#include "render/utf8.h"

using namespace epure::render;

namespace {

// Widths are sums of a few table entries: exact up to rounding in the last bits.
constexpr double kEps = 1e-12;

// DejaVu Sans advances at 2048 units per em, from the font (FreeType, unhinted).
constexpr double kN = 1298.0 / 2048.0;
constexpr double kA = 1255.0 / 2048.0;

std::string joined(const std::vector<TextRun>& runs) {
  std::string s;
  for (const auto& r : runs) s += r.text;
  return s;
}

}  // namespace

TEST_CASE("parse_rich_text: the three markups, escapes, and literal leftovers") {
  SUBCASE("1. plain text is one run") {
    auto runs = parse_rich_text("AB = 3");
    REQUIRE(runs.size() == 1);
    CHECK(runs[0].text == "AB = 3");
    CHECK(runs[0].shift == Shift::none);
    CHECK_FALSE(runs[0].arrow);
  }
  SUBCASE("2. subscript") {
    auto runs = parse_rich_text("t_{ab} = 0");
    REQUIRE(runs.size() == 3);
    CHECK(runs[0].text == "t");
    CHECK(runs[1].text == "ab");
    CHECK(runs[1].shift == Shift::sub);
    CHECK(runs[2].text == " = 0");
  }
  SUBCASE("3. superscript") {
    auto runs = parse_rich_text("r^{2}");
    REQUIRE(runs.size() == 2);
    CHECK(runs[1].shift == Shift::super);
    CHECK(runs[1].text == "2");
  }
  SUBCASE("4. vector arrow") {
    auto runs = parse_rich_text("\\vec{AB}·\\vec{AC}");
    REQUIRE(runs.size() == 3);
    CHECK(runs[0].arrow);
    CHECK(runs[0].text == "AB");
    CHECK_FALSE(runs[1].arrow);
    CHECK(runs[2].arrow);
  }
  SUBCASE("5. escaped braces and backslash are literal") {
    auto runs = parse_rich_text("\\{x\\} \\\\ a_\\{b\\}");
    REQUIRE(runs.size() == 1);
    CHECK(runs[0].text == "{x} \\ a_{b}");
  }
  SUBCASE("6. unbalanced braces are taken literally") {
    CHECK(joined(parse_rich_text("a_{b")) == "a_{b");
    CHECK(joined(parse_rich_text("\\vec{AB")) == "\\vec{AB");
    CHECK(joined(parse_rich_text("}{")) == "}{");
    CHECK(parse_rich_text("a_{b").size() == 1);
  }
  SUBCASE("7. nested groups combine: a script keeps its shift, an arrow inside it too") {
    auto runs = parse_rich_text("x_{\\vec{u}2^{3}}");
    REQUIRE(runs.size() == 3);
    CHECK(runs[1].text == "u");
    CHECK(runs[1].shift == Shift::sub);
    CHECK(runs[1].arrow);
    CHECK(runs[2].text == "23");
    CHECK(runs[2].shift == Shift::sub);
  }
  SUBCASE("8. empty text and empty groups give no empty runs") {
    CHECK(parse_rich_text("").empty());
    CHECK(joined(parse_rich_text("a_{}b")) == "ab");
  }
  SUBCASE("9. weight is carried to every run") {
    for (const auto& r : parse_rich_text("t_{ab}", Weight::bold)) CHECK(r.bold);
  }
}

TEST_CASE("parse_rich_text and text_width: the short ways give the parser's runs and their widths") {
  // The parser's pieces gathered into runs as parse_rich_text gathers them, against its short way
  // for texts without '\\', '_' or '^' (braces alone are literal); and text_width, which sums a
  // text's advances piece by piece without making runs, against text_width of those runs, to
  // the bit.
  struct Gather final : RichSink {
    std::vector<TextRun> runs;
    bool bold = false;
    void piece(std::string_view text, Shift shift, bool arrow) override {
      if (runs.empty() || runs.back().shift != shift || runs.back().arrow != arrow) runs.push_back(TextRun{{}, shift, arrow, bold});
      runs.back().text += text;
    }
  };
  const std::string alphabet[] = {"a", "Z", "1", " ", ".", "{", "}", "(", "é", "→", "−", "_", "^", "\\", "\\vec{u}", "_{1}"};
  std::uint64_t state = 12345;
  for (int n = 0; n < 3000; ++n) {
    std::string text;
    const int length = n % 17;
    for (int k = 0; k < length; ++k) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      // two thirds of the texts without markup characters
      const std::size_t pick = static_cast<std::size_t>(state >> 33) % (n % 3 == 0 ? 16 : 11);
      text += alphabet[pick];
    }
    CAPTURE(text);
    for (const Weight weight : {Weight::regular, Weight::bold}) {
      Gather g;
      g.bold = weight == Weight::bold;
      parse_rich_pieces(text, g);
      const auto runs = parse_rich_text(text, weight);
      REQUIRE(runs.size() == g.runs.size());
      for (std::size_t i = 0; i < runs.size(); ++i) {
        CHECK(runs[i].text == g.runs[i].text);
        CHECK(runs[i].shift == g.runs[i].shift);
        CHECK(runs[i].arrow == g.runs[i].arrow);
        CHECK(runs[i].bold == g.runs[i].bold);
      }
      const double size = 7.5 + n % 5;
      CHECK(std::bit_cast<std::uint64_t>(text_width(text, size, weight)) == std::bit_cast<std::uint64_t>(text_width(g.runs, size)));
    }
  }
}

TEST_CASE("text_width: DejaVu Sans advances, scripts scaled") {
  CHECK(text_width("n", 10) == doctest::Approx(10 * kN).epsilon(kEps));
  CHECK(text_width("an", 12) == doctest::Approx(12 * (kA + kN)).epsilon(kEps));
  // A subscript is set at kScriptScale of the size.
  CHECK(text_width("n_{n}", 10) == doctest::Approx(10 * kN * (1 + kScriptScale)).epsilon(kEps));
  // The arrow of \vec sits above its run and takes no width.
  CHECK(text_width("\\vec{an}", 10) == doctest::Approx(text_width("an", 10)).epsilon(kEps));
  CHECK(text_width("n", 10, Weight::bold) > text_width("n", 10));
  CHECK(text_width("", 10) == doctest::Approx(0).epsilon(kEps));
  // A character outside the table (a CJK ideograph) is measured as a typical glyph.
  CHECK(text_width("\u4E00", 10) == doctest::Approx(10 * kFallbackAdvanceEm).epsilon(kEps));
  // Invalid UTF-8 is measured too (one fallback glyph per bad byte), never crashes.
  CHECK(text_width(std::string("a\xff"), 10) ==
        doctest::Approx(10 * (kA + kFallbackAdvanceEm)).epsilon(kEps));
}

TEST_CASE("font metrics cover the characters of the course's texts") {
  const std::string needed = "éèêàçùôîïœÉÈÀÇŒëüâû«»·∧√≈‖→←⇒²³⁻¹∈≤≥−×∘θπ∞⊥∠αβγδλμΔ…–—’ ";
  for (std::size_t i = 0; i < needed.size();) {
    const auto d = epure::render::utf8::decode(needed, i);
    CAPTURE(std::string(needed.substr(i, d.length)));
    CHECK(d.valid);
    CHECK(has_glyph(d.cp));
    i += d.length;
  }
  const auto v = vertical_metrics();
  CHECK(v.cap_height == doctest::Approx(1493.0 / 2048).epsilon(kEps));
  CHECK(v.ascent > v.cap_height);
  CHECK(v.descent > 0);
}

TEST_CASE("wrap_rich_text: no break inside a formula nor before French punctuation") {
  const double size = 10;
  // Every width from the widest glued run to the whole text: a break lands anywhere it may. (A
  // narrower line breaks a run at its own spaces: subcase 4.)
  const auto every_wrap = [&](const std::string& text, const std::string& widest_run, auto check) {
    for (double width = text_width(widest_run, size) + 0.5; width < text_width(text, size) + 10; width += 3) {
      CAPTURE(width);
      const auto lines = wrap_rich_text(text, size, width);
      for (std::size_t i = 0; i < lines.size(); ++i) check(joined(lines[i]), i, lines.size());
    }
  };
  SUBCASE("1. a line never starts or ends at '=', '+', '−' or '∘'") {
    const std::string text = "donc I = A + t·û et T = translation(C) ∘ rotation(θ) ∘ échelle(a ; b), puis t = 2 − 1 enfin";
    every_wrap(text, "T = translation(C) ∘ rotation(θ) ∘ échelle(a ; b),", [](const std::string& line, std::size_t, std::size_t) {
      for (const std::string op : {"=", "+", "−", "∘"}) {
        CHECK(line.rfind(op + " ", 0) != 0);
        CHECK((line.size() < op.size() + 1 || line.compare(line.size() - op.size() - 1, std::string::npos, " " + op) != 0));
      }
    });
  }
  SUBCASE("2. a short bracketed group stays on one line, prose in parentheses may wrap") {
    every_wrap("le point (−2,5 ; 4) et le carré [−1 ; 1] sont donnés ici", "(−2,5 ; 4)", [](const std::string& line, std::size_t, std::size_t) {
      CHECK((line.find("(−2,5") == std::string::npos || line.find("(−2,5 ; 4)") != std::string::npos));
      CHECK((line.find("[−1") == std::string::npos || line.find("[−1 ; 1]") != std::string::npos));
    });
    const auto long_group = wrap_rich_text("a (b c d e f g h i j k l m n o p q r s t u v w x y z) z", size, 40);
    CHECK(long_group.size() > 2);
  }
  SUBCASE("3. '?', ':', ';' and '»' never start a line; '«' never ends one") {
    every_wrap("A est-il à l’intérieur ? Cochez « aucun » : il n’y en a pas ; voilà !", text_width("l’intérieur ?", size) > text_width("« aucun » :", size) ? "l’intérieur ?" : "« aucun » :",
               [](const std::string& line, std::size_t, std::size_t) {
                 for (const std::string p : {"?", ":", ";", "»", "!"}) CHECK(line.rfind(p, 0) != 0);
                 CHECK((line.size() < 3 || line.compare(line.size() - 3, 3, " «") != 0));
               });
  }
  SUBCASE("5. a bracket closed inside a markup group does not glue the rest of the line") {
    const std::string text = "(a_{b)} c d e f g h i j k (f ; g) h";
    every_wrap(text, "(f ; g)", [](const std::string& line, std::size_t, std::size_t) {
      CHECK((line.find("(f") == std::string::npos || line.find("(f ; g)") != std::string::npos));
    });
    CHECK(wrap_rich_text(text, size, text_width("c d e f", size)).size() > 3);
  }
  SUBCASE("4. a glued run wider than the line still wraps, at its own spaces") {
    const auto lines = wrap_rich_text("x = a + b + c + d + e + f + g + h", size, 25);
    CHECK(lines.size() > 2);
    for (const auto& l : lines)
      if (text_width(l, size) > 25) CHECK(joined(l).find(' ') == std::string::npos);
  }
}

TEST_CASE("wrap_rich_text: greedy, at spaces, never inside a group") {
  const double size = 10;
  SUBCASE("1. every line fits, and the words come back in order") {
    const std::string text =
        "The projection of C on the line AB is the point P such that \\vec{PC}·\\vec{AB} = 0; "
        "its parameter t_{P} is found from the dot products.";
    for (double width : {40.0, 80.0, 120.0, 200.0, 1000.0}) {
      CAPTURE(width);
      auto lines = wrap_rich_text(text, size, width);
      REQUIRE_FALSE(lines.empty());
      std::string back;
      for (const auto& l : lines) {
        if (l.size() > 0 && text_width(l, size) > width) {
          // Only a single word may overflow.
          CHECK(joined(l).find(' ') == std::string::npos);
        }
        if (!back.empty()) back += ' ';
        back += joined(l);
      }
      CHECK(back == joined(parse_rich_text(text)));
    }
  }
  SUBCASE("2. a word wider than the line gets its own line") {
    auto lines = wrap_rich_text("a Supercalifragilistic b", size, 30);
    REQUIRE(lines.size() == 3);
    CHECK(joined(lines[1]) == "Supercalifragilistic");
  }
  SUBCASE("3. a space inside markup does not break") {
    auto lines = wrap_rich_text("x \\vec{A B} y", size, 1);
    REQUIRE(lines.size() == 3);
    CHECK(joined(lines[1]) == "A B");
    CHECK(lines[1][0].arrow);
  }
  SUBCASE("4. a greedy line takes as many words as fit") {
    const double w = text_width("aa aa", size);
    auto lines = wrap_rich_text("aa aa aa aa", size, w + 1e-9);
    REQUIRE(lines.size() == 2);
    CHECK(joined(lines[0]) == "aa aa");
  }
  SUBCASE("5. newlines force breaks; empty text gives no line") {
    auto lines = wrap_rich_text("a\n\nb", size, 1000);
    REQUIRE(lines.size() == 3);
    CHECK(lines[1].empty());
    CHECK(wrap_rich_text("", size, 100).empty());
  }
  SUBCASE("6. repeated spaces collapse") {
    auto lines = wrap_rich_text("  a   b  ", size, 1000);
    REQUIRE(lines.size() == 1);
    CHECK(joined(lines[0]) == "a b");
  }
}

TEST_CASE("wrap_rich_source: the lines' markup, which joined gives the text back") {
  const std::string text =
      "A ray starts at A(5, 8) with direction \\vec{u} = (4, −2); let û = \\vec{u}/‖\\vec{u}‖, so that t "
      "is a distance along the ray, t_{proj} = û·\\vec{AC} and d^{2} = ‖\\vec{CP}‖^{2}.";
  for (double width : {60.0, 120.0, 240.0, 480.0}) {
    CAPTURE(width);
    const auto source = wrap_rich_source(text, 10, width);
    const auto lines = wrap_rich_text(text, 10, width);
    REQUIRE(source.size() == lines.size());
    std::string joined;
    for (std::size_t i = 0; i < source.size(); ++i) {
      joined += (i > 0 ? " " : "") + source[i];
      CHECK(text_width(parse_rich_text(source[i]), 10) == doctest::Approx(text_width(lines[i], 10)));
    }
    CHECK(joined == text);
  }
}

TEST_CASE("break_measured: wrap_measured's lines as word spans, their widths, and a paragraph's rest") {
  const std::string texts[] = {
      "Les points A, B et C sont donnés. Calculer t_{ab} avec \\vec{AB}·\\vec{AC} = 3, puis P = (−2 ; 4) ; "
      "« aucun » si A est à l'intérieur : est-ce le cas ?",
      "Un mot trèstrèstrèstrèstrèslongquidépasselaligne puis d'autres mots courts encore et encore.",
      "Première ligne\nseconde pièce du texte, après un saut de ligne\n\nune dernière"};
  for (const auto& text : texts) {
    const MeasuredText m = measure_text(text, 10);
    for (double width : {40.0, 90.0, 150.0, 300.0, 1e9}) {
      CAPTURE(text);
      CAPTURE(width);
      const auto lines = break_measured(m, width);
      const auto sources = wrap_rich_source(text, 10, width);
      REQUIRE(lines.size() == sources.size());
      for (std::size_t i = 0; i < lines.size(); ++i) {
        CHECK(line_source(m, lines[i]) == sources[i]);
        // the width the breaking measured is the line's own (the same advances, summed otherwise)
        CHECK(lines[i].width == doctest::Approx(text_width(sources[i], 10)).epsilon(1e-9));
      }
      // A paragraph's rest from a line's first word on breaks as that rest alone does.
      if (m.pieces.size() == 1 && lines.size() >= 2) {
        const auto rest = break_measured(m, width, lines[1].first);
        CHECK(rest.size() == sources.size() - 1);
        CHECK(line_source(m, rest.front()) == sources[1]);
      }
    }
  }
}
