#include "render/text_measure.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace epure::render;
using epure::render::layout_detail::TextMeasure;
using epure::render::layout_detail::WrappedText;

namespace {

void check_same_runs(const std::vector<TextRun>& got, const std::vector<TextRun>& want) {
  REQUIRE(got.size() == want.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    CHECK(got[k].text == want[k].text);
    CHECK(got[k].shift == want[k].shift);
    CHECK(got[k].arrow == want[k].arrow);
    CHECK(got[k].bold == want[k].bold);
  }
}

// Each line's runs are parse_rich_text of the line's source (its words one space apart).
void check_lines(const std::vector<std::vector<TextRun>>& runs, const WrappedText& wrapped, Weight weight) {
  REQUIRE(runs.size() == wrapped.count());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    CAPTURE(i);
    check_same_runs(runs[i], parse_rich_text(line_source(*wrapped.measured, wrapped.lines[i]), weight));
  }
}

}  // namespace

TEST_CASE("TextMeasure::wrap: the lines' runs of wrap_rich_text, in a later document too") {
  // The runs of a text's lines are kept with its measure, shared by content with the thread's
  // later documents, and parsed from a view of the text where the line's words stand one space
  // apart: a text set again (another copy, another document, another width, another first
  // word) must get the lines and runs a fresh wrap gives.
  const std::vector<std::string> texts = {
      "The ray \\vec{u} = (2 ; -1) meets the circle of centre C_{0} and radius r^{2} = 4 at two points.",
      "Heading",
      "A long statement without any markup at all, long enough to wrap over several lines here.",
      "x_{1} y_{2} z^{3} \\vec{AB} {braces} \\{escaped\\} and the rest of the words after them",
      "line one\nline two with C_{1}",
      // words more than one space apart: the line's source is built, not a view of the text
      "Two  spaces   here and C_{1}  there, then   more words to wrap the line  again and again.",
      "  leading and trailing spaces  ",
  };
  for (const double width : {60.0, 140.0, 400.0})
    for (const Weight weight : {Weight::regular, Weight::bold})
      for (const std::string& original : texts) {
        CAPTURE(original);
        CAPTURE(width);
        const auto fresh = wrap_rich_text(original, 10, width, weight);
        for (int document = 0; document < 3; ++document) {
          TextMeasure measure;
          const std::string copy = original;  // another address, the same content
          const auto& lines = measure.wrap(copy, 10, width, weight);
          REQUIRE(lines.size() == fresh.size());
          for (std::size_t i = 0; i < lines.size(); ++i) check_same_runs(lines[i], fresh[i]);
          check_lines(lines, measure.wrapped(copy, 10, width, weight), weight);
          // From the second word on: the lines of the text's rest.
          if (original.find('\n') == std::string::npos)
            check_lines(measure.wrap(copy, 10, width, weight, 1), measure.wrapped(copy, 10, width, weight, 1), weight);
        }
      }
}
