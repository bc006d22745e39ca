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
//   - the weight is a whole number; a fraction must be one of Moodle's grades.
#include <string>
#include <string_view>

#include "export/export_set.h"

namespace epure::exporting {

// The whole file, deterministic: the same set gives the same bytes.
std::string moodle_xml(const ExportSet& set);

// HTML put into a Cloze answer or feedback so that the importer reads it back as this HTML:
// & doubled into &amp; (the importer decodes entities once), } # ~ \ as &#125; &#35; &#126; &#92;.
std::string cloze_escape(std::string_view html);
// Text inside <![CDATA[…]]>, a "]]>" in it split across two sections.
std::string cdata(std::string_view text);
// One of Moodle's allowed grades, as the importer's list spells it ("33.33333", "-50"), for a
// fraction given in percent; throws ExportError for one that is not in the list.
std::string moodle_fraction(double percent);
// One Cloze part: {weight:TYPE:…}.
std::string cloze_part(const Part& part, int weight);

}  // namespace epure::exporting
