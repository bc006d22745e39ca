#include "export/qti_package.h"

#include <fmt/format.h>

#include <algorithm>

#include "render/markup_escape.h"

namespace epure::exporting {

namespace {

constexpr std::string_view kQtiNamespace =
    "xmlns=\"http://www.imsglobal.org/xsd/imsqti_v2p1\" "
    "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
    "xsi:schemaLocation=\"http://www.imsglobal.org/xsd/imsqti_v2p1 "
    "http://www.imsglobal.org/xsd/qti/qtiv2p1/imsqti_v2p1.xsd\"";
constexpr std::string_view kCpNamespace =
    "xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\" "
    "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
    "xsi:schemaLocation=\"http://www.imsglobal.org/xsd/imscp_v1p1 "
    "http://www.imsglobal.org/xsd/imscp_v1p1.xsd\"";

// A text box as wide for every answer (20 characters), so that its size tells nothing.
constexpr int kExpectedLength = 20;

std::string item_id(const Variant& v, int n) { return fmt::format("item-{}-{}", v.sheet_id, n); }
std::string item_file(const Variant& v, int n) { return fmt::format("items/{}-{}.xml", v.sheet_id, n); }
std::string response_id(std::size_t part) { return fmt::format("R{}", part + 1); }

// An option's identifier (an NCName): C_between, C_yes, F_px (+x), F_my (−y), F_none.
std::string option_id(const Part& p, std::string_view option) {
  if (p.type != Part::Type::faces) return fmt::format("C_{}", option);
  if (option == "none") return "F_none";
  return fmt::format("F_{}{}", option[0] == '+' ? 'p' : 'm', option.substr(1));
}
std::string feedback_id(std::size_t part, const MistakeAnswer& m) { return fmt::format("M{}_{}", part + 1, m.code); }

std::string points(double x) { return shortest(x); }

std::string add_score(double pts) {
  return fmt::format(
      "        <setOutcomeValue identifier=\"SCORE\"><sum><variable identifier=\"SCORE\"/>"
      "<baseValue baseType=\"float\">{}</baseValue></sum></setOutcomeValue>\n",
      points(pts));
}

std::string add_feedback(std::string_view id, std::string_view indent = "        ") {
  return fmt::format(
      "{}<setOutcomeValue identifier=\"FEEDBACK\"><multiple><variable identifier=\"FEEDBACK\"/>"
      "<baseValue baseType=\"identifier\">{}</baseValue></multiple></setOutcomeValue>\n",
      indent, id);
}

std::string not_asked_id(std::size_t part) { return fmt::format("NA{}", part + 1); }
// The worked solution's feedback (its identifier cannot clash: the others start NA or M).
constexpr std::string_view kSolutionId = "SOLUTION";

// A point marked as a whole (whole_point): its points when the distance to the key's point is
// within the key's rule, (x − x₀)² + (y − y₀)² ≤ r²; a named mistake when every coordinate is
// the mistake's (a coordinate the mistake leaves alone: the key's), each within its width.
// Every named mistake of a whole point's coordinates, once each, in the coordinates' order.
std::vector<const MistakeAnswer*> point_mistakes(const Variant& v, const Block& b) {
  std::vector<const MistakeAnswer*> out;
  for (int i : b.parts)
    for (const auto& m : v.parts[static_cast<std::size_t>(i)].mistakes)
      if (std::none_of(out.begin(), out.end(), [&](const MistakeAnswer* o) { return o->code == m.code; }))
        out.push_back(&m);
  return out;
}

std::string whole_point_condition(const Variant& v, const Block& b) {
  const auto part = [&](int i) -> const Part& { return v.parts[static_cast<std::size_t>(i)]; };
  const Part& first = part(b.parts.front());
  std::string x = "    <responseCondition>\n      <responseIf>\n        <lte><sum>";
  double points = 0;
  for (int i : b.parts) {
    x += fmt::format("<power><subtract><variable identifier=\"{}\"/><baseValue baseType=\"float\">{}</baseValue>"
                     "</subtract><baseValue baseType=\"integer\">2</baseValue></power>",
                     response_id(static_cast<std::size_t>(i)), shortest(part(i).value));
    points += part(i).points;
  }
  x += fmt::format("</sum><baseValue baseType=\"float\">{}</baseValue></lte>\n", shortest(first.radius * first.radius));
  x += add_score(points);
  x += "      </responseIf>\n";
  for (const MistakeAnswer* m : point_mistakes(v, b)) {
    x += "      <responseElseIf>\n        <and>";
    for (int i : b.parts) {
      double value = part(i).value, width = part(i).width;
      for (const auto& other : part(i).mistakes)
        if (other.code == m->code) value = other.value, width = other.width;
      x += fmt::format("<equal toleranceMode=\"absolute\" tolerance=\"{0} {0}\"><baseValue baseType=\"float\">{1}"
                       "</baseValue><variable identifier=\"{2}\"/></equal>",
                       shortest(width), shortest(value), response_id(static_cast<std::size_t>(i)));
    }
    x += "</and>\n";
    x += add_feedback(feedback_id(static_cast<std::size_t>(b.parts.front()), *m));
    x += "      </responseElseIf>\n";
  }
  x += "    </responseCondition>\n";
  return x;
}

std::string interaction(const Part& p, std::size_t i) {
  const std::string r = response_id(i);
  if (p.type == Part::Type::number)
    return fmt::format("<textEntryInteraction responseIdentifier=\"{}\" expectedLength=\"{}\"/>", r, kExpectedLength);
  std::string s = fmt::format("<inlineChoiceInteraction responseIdentifier=\"{}\" shuffle=\"false\">", r);
  for (const auto& o : p.options)
    s += fmt::format("<inlineChoice identifier=\"{}\">{}</inlineChoice>", option_id(p, o.id), o.html);
  s += "</inlineChoiceInteraction>";
  return s;
}

std::string item_xml(const ExportSet& set, const ExerciseSlot& slot, const Variant& v) {
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<assessmentItem {} identifier=\"{}\" title=\"{}\" adaptive=\"false\" timeDependent=\"false\" "
                   "xml:lang=\"{}\">\n",
                   kQtiNamespace, item_id(v, slot.n), render::markup_escaped(v.name), set.language);
  // responses
  for (std::size_t i = 0; i < v.parts.size(); ++i) {
    const Part& p = v.parts[i];
    const std::string r = response_id(i);
    if (!p.asked) {  // a field this case does not ask: any answer, marked for nothing
      x += fmt::format("  <responseDeclaration identifier=\"{}\" cardinality=\"{}\" baseType=\"{}\"/>\n", r,
                       p.type == Part::Type::faces ? "multiple" : "single",
                       p.type == Part::Type::number ? "string" : "identifier");
      continue;
    }
    switch (p.type) {
      case Part::Type::number:
        x += fmt::format("  <responseDeclaration identifier=\"{}\" cardinality=\"single\" baseType=\"float\">"
                         "<correctResponse><value>{}</value></correctResponse></responseDeclaration>\n",
                         r, shortest(p.value));
        break;
      case Part::Type::choice: {
        const auto right = std::find_if(p.options.begin(), p.options.end(), [](const Option& o) { return o.right; });
        x += fmt::format("  <responseDeclaration identifier=\"{}\" cardinality=\"single\" baseType=\"identifier\">"
                         "<correctResponse><value>{}</value></correctResponse></responseDeclaration>\n",
                         r, option_id(p, right->id));
        break;
      }
      case Part::Type::faces: {
        x += fmt::format("  <responseDeclaration identifier=\"{}\" cardinality=\"multiple\" baseType=\"identifier\">"
                         "<correctResponse>",
                         r);
        for (const auto& o : p.options)
          if (o.right) x += fmt::format("<value>{}</value>", option_id(p, o.id));
        x += "</correctResponse></responseDeclaration>\n";
        break;
      }
    }
  }
  x += "  <outcomeDeclaration identifier=\"SCORE\" cardinality=\"single\" baseType=\"float\">"
       "<defaultValue><value>0</value></defaultValue></outcomeDeclaration>\n";
  x += fmt::format("  <outcomeDeclaration identifier=\"MAXSCORE\" cardinality=\"single\" baseType=\"float\">"
                   "<defaultValue><value>{}</value></defaultValue></outcomeDeclaration>\n",
                   points(v.points));
  x += "  <outcomeDeclaration identifier=\"FEEDBACK\" cardinality=\"multiple\" baseType=\"identifier\"/>\n";

  // body, in the sheet's order
  x += "  <itemBody>\n";
  const std::string separator = set.language == "fr" ? " ; " : ", ";
  for (const auto& b : v.blocks) {
    switch (b.kind) {
      case Block::Kind::text: x += "    <p>" + b.html + "</p>\n"; break;
      case Block::Kind::image: {
        const Image& im = v.images[static_cast<std::size_t>(b.image)];
        x += fmt::format("    <p><img src=\"../images/{}\" alt=\"{}\" width=\"{}\"/></p>\n", im.name, render::markup_escaped(im.alt),
                         im.width_px);
        break;
      }
      case Block::Kind::field: {
        const auto first = static_cast<std::size_t>(b.parts.front());
        if (v.parts[first].type == Part::Type::faces) {
          const Part& p = v.parts[first];
          x += fmt::format("    <choiceInteraction responseIdentifier=\"{}\" shuffle=\"false\" maxChoices=\"0\">"
                           "<prompt>{}</prompt>",
                           response_id(first), b.html);
          for (const auto& o : p.options)
            x += fmt::format("<simpleChoice identifier=\"{}\">{}</simpleChoice>", option_id(p, o.id), o.html);
          x += "</choiceInteraction>\n";
          break;
        }
        std::vector<std::string> inner;
        for (int i : b.parts) inner.push_back(interaction(v.parts[static_cast<std::size_t>(i)], static_cast<std::size_t>(i)));
        x += "    <p>" + b.html + " ";
        if (b.point) x += fmt::format("({})", fmt::join(inner, separator));
        else x += fmt::format("{}", fmt::join(inner, " "));
        x += "</p>\n";
        break;
      }
    }
  }
  x += "  </itemBody>\n";

  // scoring: the points of each right answer; a named mistake's value sets its feedback
  x += "  <responseProcessing>\n";
  std::vector<const Block*> point_of(v.parts.size(), nullptr);  // a whole point's block, by part
  for (const auto& b : v.blocks)
    if (b.kind == Block::Kind::field && b.whole_point)
      for (int i : b.parts) point_of[static_cast<std::size_t>(i)] = &b;
  for (std::size_t i = 0; i < v.parts.size(); ++i) {
    const Part& p = v.parts[i];
    const std::string r = response_id(i);
    if (!p.asked) {
      x += fmt::format("    <responseCondition>\n      <responseIf>\n        <not><isNull><variable identifier=\"{}\"/>"
                       "</isNull></not>\n",
                       r);
      x += add_feedback(not_asked_id(i));
      x += "      </responseIf>\n    </responseCondition>\n";
      continue;
    }
    if (point_of[i]) {
      // marked as a whole, on its first coordinate: the others are read there
      if (point_of[i]->parts.front() == static_cast<int>(i)) x += whole_point_condition(v, *point_of[i]);
      continue;
    }
    x += "    <responseCondition>\n      <responseIf>\n";
    if (p.type == Part::Type::number)
      x += fmt::format("        <equal toleranceMode=\"absolute\" tolerance=\"{0} {0}\"><correct identifier=\"{1}\"/>"
                       "<variable identifier=\"{1}\"/></equal>\n",
                       shortest(p.width), r);
    else
      x += fmt::format("        <match><variable identifier=\"{0}\"/><correct identifier=\"{0}\"/></match>\n", r);
    x += add_score(p.points);
    x += "      </responseIf>\n";
    for (const auto& m : p.mistakes) {
      x += "      <responseElseIf>\n";
      if (p.type == Part::Type::number) {
        x += fmt::format("        <equal toleranceMode=\"absolute\" tolerance=\"{0} {0}\"><baseValue baseType=\"float\">{1}"
                         "</baseValue><variable identifier=\"{2}\"/></equal>\n",
                         shortest(m.width), shortest(m.value), r);
      } else if (p.type == Part::Type::choice) {
        x += fmt::format("        <match><variable identifier=\"{}\"/><baseValue baseType=\"identifier\">{}</baseValue>"
                         "</match>\n",
                         r, option_id(p, m.options.front()));
      } else {
        x += fmt::format("        <match><variable identifier=\"{}\"/><multiple>", r);
        for (const auto& o : m.options) x += fmt::format("<baseValue baseType=\"identifier\">{}</baseValue>", option_id(p, o));
        x += "</multiple></match>\n";
      }
      x += add_feedback(feedback_id(i, m));
      x += "      </responseElseIf>\n";
    }
    x += "    </responseCondition>\n";
  }
  // the worked solution, whatever the answers: shown once the item is answered
  if (!v.solution.empty()) x += add_feedback(kSolutionId, "    ");
  x += "  </responseProcessing>\n";
  for (std::size_t i = 0; i < v.parts.size(); ++i) {
    if (!v.parts[i].asked)
      x += fmt::format("  <modalFeedback outcomeIdentifier=\"FEEDBACK\" identifier=\"{}\" showHide=\"show\">"
                       "<p>{}</p></modalFeedback>\n",
                       not_asked_id(i), set.not_asked_feedback_html);
    // a whole point's mistakes are set on its first coordinate only
    if (point_of[i]) {
      if (point_of[i]->parts.front() == static_cast<int>(i))
        for (const MistakeAnswer* m : point_mistakes(v, *point_of[i]))
          x += fmt::format("  <modalFeedback outcomeIdentifier=\"FEEDBACK\" identifier=\"{}\" showHide=\"show\">"
                           "<p>{}</p></modalFeedback>\n",
                           feedback_id(i, *m), m->feedback_html);
      continue;
    }
    for (const auto& m : v.parts[i].mistakes)
      x += fmt::format("  <modalFeedback outcomeIdentifier=\"FEEDBACK\" identifier=\"{}\" showHide=\"show\">"
                       "<p>{}</p></modalFeedback>\n",
                       feedback_id(i, m), m.feedback_html);
  }
  if (!v.solution.empty())
    x += fmt::format("  <modalFeedback outcomeIdentifier=\"FEEDBACK\" identifier=\"{}\" showHide=\"show\" title=\"{}\">\n"
                     "{}  </modalFeedback>\n",
                     kSolutionId, render::markup_escaped(set.solution_title), solution_html(v, "../images/"));
  x += "</assessmentItem>\n";
  return x;
}

std::string test_xml(const ExportSet& set) {
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<assessmentTest {} identifier=\"test\" title=\"{}\">\n", kQtiNamespace, render::markup_escaped(set.title));
  x += "  <outcomeDeclaration identifier=\"SCORE\" cardinality=\"single\" baseType=\"float\">"
       "<defaultValue><value>0</value></defaultValue></outcomeDeclaration>\n";
  x += "  <testPart identifier=\"part\" navigationMode=\"nonlinear\" submissionMode=\"simultaneous\">\n";
  for (const auto& slot : set.exercises) {
    x += fmt::format("    <assessmentSection identifier=\"exercise-{}\" title=\"{}\" visible=\"true\">\n", slot.n,
                     render::markup_escaped(slot.title));
    x += "      <selection select=\"1\"/>\n";
    for (const auto& v : slot.variants)
      x += fmt::format("      <assessmentItemRef identifier=\"{}\" href=\"{}\"/>\n", item_id(v, slot.n),
                       item_file(v, slot.n));
    x += "    </assessmentSection>\n";
  }
  x += "  </testPart>\n";
  x += "  <outcomeProcessing><setOutcomeValue identifier=\"SCORE\"><sum><testVariables variableIdentifier=\"SCORE\"/>"
       "</sum></setOutcomeValue></outcomeProcessing>\n";
  x += "</assessmentTest>\n";
  return x;
}

}  // namespace

std::vector<ZipEntry> qti_files(const ExportSet& set) {
  std::vector<ZipEntry> files;
  files.push_back({"imsmanifest.xml", {}});
  files.push_back({"test.xml", test_xml(set)});
  std::string resources;
  std::string test_dependencies;
  for (const auto& slot : set.exercises)
    for (const auto& v : slot.variants) {
      const std::string file = item_file(v, slot.n);
      files.push_back({file, item_xml(set, slot, v)});
      resources += fmt::format("    <resource identifier=\"{}\" type=\"imsqti_item_xmlv2p1\" href=\"{}\">\n",
                               item_id(v, slot.n), file);
      resources += fmt::format("      <file href=\"{}\"/>\n", file);
      for (const auto* images : {&v.images, &v.solution_images})
        for (const auto& im : *images) {
          files.push_back({"images/" + im.name, im.bytes});
          resources += fmt::format("      <file href=\"images/{}\"/>\n", im.name);
        }
      resources += "    </resource>\n";
      test_dependencies += fmt::format("      <dependency identifierref=\"{}\"/>\n", item_id(v, slot.n));
    }
  std::string m = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  const std::string first = set.exercises.empty() || set.exercises.front().variants.empty()
                                ? std::string("set")
                                : set.exercises.front().variants.front().sheet_id;
  m += fmt::format("<manifest {} identifier=\"epure-{}\">\n", kCpNamespace, first);
  m += "  <metadata><schema>QTIv2.1 Package</schema><schemaversion>1.0.0</schemaversion></metadata>\n";
  m += "  <organizations/>\n";
  m += "  <resources>\n";
  m += "    <resource identifier=\"test\" type=\"imsqti_test_xmlv2p1\" href=\"test.xml\">\n";
  m += "      <file href=\"test.xml\"/>\n";
  m += test_dependencies;
  m += "    </resource>\n";
  m += resources;
  m += "  </resources>\n";
  m += "</manifest>\n";
  files.front().bytes = std::move(m);
  return files;
}

std::string qti_package(const ExportSet& set) { return zip_archive(qti_files(set)); }

}  // namespace epure::exporting
