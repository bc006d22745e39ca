#pragma once
// The set as a Moodle XML question bank (the format Moodle's question/format/xml imports): one
// category per exercise, `$course$/top/<set title>/<n>. <exercise title>`, holding one Cloze
// (multianswer) question per student variant, named `<n>. <exercise title> — <sheet id>`, with
// its diagram embedded in the question text. What the importer does with a Cloze text was read
// in its source (question/type/multianswer/questiontype.php) and is written down here:
//   - a part is {weight:TYPE:answer~answer…}; an answer is `=` (right) or `%fraction%`, the
//     answer, then `#feedback`; answers are tried in order and the first match wins;
//   - an answer ends at the first ~ # } not preceded by \ or &, a feedback at the first ~ } not
//     preceded by \; both are then HTML-entity-decoded, and only \} and \# are unescaped;
//   - a NUMERICAL answer is `value:tolerance`, the tolerance absolute, widened by Moodle by
//     10^−precision·max(tolerance, |value|) (question/type/numerical/question.php);
//   - the weight is a whole number, 0 allowed (an empty one reads as 1); a fraction must be one
//     of Moodle's grades.
#include <string>
#include <string_view>

#include "export/export_set.h"

namespace epure::exporting {

// The whole file, deterministic: the same set gives the same bytes.
std::string moodle_xml(const ExportSet& set);

// HTML put into a Cloze answer or feedback so that the importer reads it back as this HTML:
// & doubled into &amp; (the importer decodes entities once), } # ~ as &#125; &#35; &#126;, = % as
// &#61; &#37; (an answer's first one would be its grade), and \ as &amp;#92; (decoded once, a
// backslash must still not meet a brace: the importer then turns \} into }).
std::string cloze_escape(std::string_view html);
// Text inside <![CDATA[…]]>, a "]]>" in it split across two sections.
std::string cdata(std::string_view text);
// One of Moodle's allowed grades, as the importer's list spells it ("33.33333", "-50"), for a
// fraction given in percent; throws ExportError for one that is not in the list.
std::string moodle_fraction(double percent);
// What a part's list needs from its exercise: where some variant does not ask this field, its
// list offers "— (does not apply)" on every variant (right where it is not asked: a Moodle list
// must have a right option), and a box that is not asked says so when filled in.
struct ClozeContext {
  bool does_not_apply_offered = false;
  std::string does_not_apply_html;
  std::string not_asked_feedback_html;
};
// One Cloze part: {weight:TYPE:…}. A number is NUMERICAL (a field not asked: a SHORTANSWER box of
// the same width, weight 0); a choice is a MULTICHOICE; a set of faces is a MULTICHOICE over the
// candidate sets (face_sets), since the key marks the set as a whole.
std::string cloze_part(const Part& part, int weight, const ClozeContext& context = {});

}  // namespace epure::exporting
