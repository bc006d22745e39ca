#include "render/text_measure.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace epure::render;
using epure::render::layout_detail::TextMeasure;

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
          for (std::size_t i = 0; i < lines.size(); ++i) {
            REQUIRE(lines[i].size() == fresh[i].size());
            for (std::size_t k = 0; k < lines[i].size(); ++k) {
              CHECK(lines[i][k].text == fresh[i][k].text);
              CHECK(lines[i][k].shift == fresh[i][k].shift);
              CHECK(lines[i][k].arrow == fresh[i][k].arrow);
              CHECK(lines[i][k].bold == fresh[i][k].bold);
            }
          }
          // From the second word on: the lines of the text's rest.
          if (original.find('\n') == std::string::npos) {
            const auto& rest = measure.wrap(copy, 10, width, weight, 1);
            const auto& again = measure.wrap(copy, 10, width, weight, 1);
            CHECK(&rest == &again);
            const auto& wrapped = measure.wrapped(copy, 10, width, weight, 1);
            CHECK(rest.size() == wrapped.count());
          }
        }
      }
}
