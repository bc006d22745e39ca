#pragma once
// The set as an IMS QTI 2.1 content package (a zip, IMS CP 1.1): imsmanifest.xml, one
// assessmentItem per student variant and exercise (items/<sheet id>-<n>.xml, titled
// `<n>. <exercise title> — <sheet id>`), its diagrams (images/), and an assessmentTest
// (test.xml) with one section per exercise that selects one of its items.
//   - Numbers are textEntryInteractions with float responses, matched by
//     <equal toleranceMode="absolute" tolerance="t t"> with <correct> as the first operand (the
//     relative mode is a percentage of the first operand, and flips for a negative one);
//   - choices are inlineChoiceInteractions, sets of faces a choiceInteraction (with "none");
//   - responseProcessing adds each right answer's points to SCORE, and a named mistake's value
//     sets its identifier in FEEDBACK, shown by the item's modalFeedback of that mistake.
#include <string>
#include <vector>

#include "export/export_set.h"
#include "export/zip_writer.h"

namespace epure::exporting {

// Every file of the package, the manifest first, in a fixed order.
std::vector<ZipEntry> qti_files(const ExportSet& set);
// The package, zipped (zip_writer.h: byte-identical on reruns).
std::string qti_package(const ExportSet& set);

}  // namespace epure::exporting
