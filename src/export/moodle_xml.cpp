#include "export/moodle_xml.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "render/markup_escape.h"
#include "support/base64.h"

namespace epure::exporting {

namespace {

// Moodle's grades (question_bank::fraction_options_full), in percent, as its list spells them.
constexpr std::string_view kGrades[] = {"100",      "90", "83.33333", "80",       "75",   "70",      "66.66667",
                                        "60",       "50", "40",       "33.33333", "30",   "25",      "20",
                                        "16.66667", "14.28571", "12.5", "11.11111", "10", "5", "0"};

// A wrong answer no student types, wider than any value shortest() writes (at most 24
// characters: "-1.2345678901234567e-100"): Moodle sizes a Cloze number box after its longest
// answer, which would otherwise show the answer's length (R/exams' exams2moodle adds such an
// answer for the same reason).
constexpr std::string_view kWideWrong = "%0%999999999999999999999999:0";

// Statement text in the question text: outside a part the importer reads nothing, but a brace
// is written as an entity all the same, so that no text can ever look like a part.
std::string brace_safe(std::string_view html) {
  std::string out;
  for (char c : html) {
    if (c == '{') out += "&#123;";
    else if (c == '}') out += "&#125;";
    else out.push_back(c);
  }
  return out;
}

// The smallest of 1, 2, 4, 8 that makes every part's points of the slot a whole number: Cloze
// weights are whole numbers, and the key's points are quarter points.
int weight_scale(const ExerciseSlot& slot) {
  for (int scale : {1, 2, 4, 8}) {
    bool whole = true;
    for (const auto& v : slot.variants)
      for (const auto& p : v.parts) whole = whole && std::abs(p.points * scale - std::round(p.points * scale)) < 1e-9;
    if (whole) return scale;
  }
  throw ExportError(fmt::format("{}: points that are not quarter points cannot be Cloze weights", slot.title));
}

// A category path segment: Moodle splits the path at '/', and reads "//" as a slash.
std::string category_segment(std::string_view s) {
  std::string out;
  for (char c : s) {
    out.push_back(c);
    if (c == '/') out.push_back('/');
  }
  return out;
}

}  // namespace

std::string cloze_escape(std::string_view html) {
  std::string out;
  for (char c : html) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '}': out += "&#125;"; break;
      case '#': out += "&#35;"; break;
      case '~': out += "&#126;"; break;
      // the importer decodes entities once and then turns \\} into }: a backslash stays an
      // entity after that decoding, so that it never meets a brace
      case '\\': out += "&amp;#92;"; break;
      // an answer's first = or % would read as its grade
      case '=': out += "&#61;"; break;
      case '%': out += "&#37;"; break;
      default: out.push_back(c);
    }
  }
  return out;
}

std::string cdata(std::string_view text) {
  std::string out = "<![CDATA[";
  std::size_t start = 0;
  for (std::size_t at; (at = text.find("]]>", start)) != std::string_view::npos; start = at + 2) {
    out.append(text.substr(start, at + 2 - start));
    out += "]]><![CDATA[";
  }
  out.append(text.substr(start));
  out += "]]>";
  return out;
}

std::string moodle_fraction(double percent) {
  for (std::string_view g : kGrades) {
    const double v = std::stod(std::string(g));
    for (double sign : {1.0, -1.0})
      if (std::abs(percent - sign * v) < 1e-4) return fmt::format("{}{}", sign < 0 && v != 0 ? "-" : "", g);
  }
  throw ExportError(fmt::format("{}% is not one of Moodle's grades", percent));
}

namespace {

// The options of a list, each with its wording, whether it is right and the feedback it gives.
struct ListOption {
  std::string html;
  bool right = false;
  std::string feedback_html;
};

std::string multichoice(const std::vector<ListOption>& options) {
  std::string s = "MULTICHOICE:";
  bool first = true;
  for (const auto& o : options) {
    if (!first) s += '~';
    first = false;
    s += o.right ? "=" : "";
    s += cloze_escape(o.html);
    if (!o.feedback_html.empty()) s += '#' + cloze_escape(o.feedback_html);
  }
  return s;
}

// A mistake's set of faces as face_sets() spells it ("none" is the empty set).
std::vector<std::string> as_set(const std::vector<std::string>& options) {
  std::vector<std::string> out;
  for (const auto& o : options)
    if (o != "none") out.push_back(o);
  return out;
}

bool same_set(std::vector<std::string> a, std::vector<std::string> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

}  // namespace

std::string cloze_part(const Part& part, int weight, const ClozeContext& context) {
  std::string s = fmt::format("{{{}:", weight);
  const std::string_view not_asked_feedback = part.asked ? std::string_view() : context.not_asked_feedback_html;
  switch (part.type) {
    case Part::Type::number: {
      if (!part.asked) {
        // Marked for nothing, but a box like a number's: a dash (any of the usual ones) is
        // taken as "nothing to give", anything else says that nothing is asked here.
        s += "SHORTANSWER:=-~=\u2013~=\u2014~=\u2212";
        s += fmt::format("~%0%*#{}", cloze_escape(context.not_asked_feedback_html));
        s += fmt::format("~%0%{}", kWideWrong.substr(3, kWideWrong.size() - 3 - 2));
        break;
      }
      s += fmt::format("NUMERICAL:={}:{}", shortest(part.value), shortest(part.width));
      for (const auto& m : part.mistakes)
        s += fmt::format("~%0%{}:{}#{}", shortest(m.value), shortest(m.width), cloze_escape(m.feedback_html));
      s += '~';
      s += kWideWrong;
      break;
    }
    case Part::Type::choice: {
      std::vector<ListOption> options;
      for (const auto& o : part.options) {
        ListOption l{o.html, o.right, std::string(not_asked_feedback)};
        for (const auto& m : part.mistakes)
          if (m.options.front() == o.id) {
            l.feedback_html = m.feedback_html;
            break;
          }
        options.push_back(std::move(l));
      }
      if (context.does_not_apply_offered) options.push_back({context.does_not_apply_html, !part.asked, {}});
      s += multichoice(options);
      break;
    }
    case Part::Type::faces: {
      // One list of the candidate sets, the whole set right or wrong, as the key marks it
      // (a MULTIRESPONSE would give part marks for part of the set).
      std::vector<std::string> right;
      for (const auto& o : part.options)
        if (o.right && o.id != "none") right.push_back(o.id);
      std::vector<ListOption> options;
      for (const auto& set : face_sets(part)) {
        ListOption l{face_set_html(part, set), part.asked && same_set(set, right), std::string(not_asked_feedback)};
        for (const auto& m : part.mistakes)
          if (same_set(as_set(m.options), set)) {
            l.feedback_html = m.feedback_html;
            break;
          }
        options.push_back(std::move(l));
      }
      if (context.does_not_apply_offered) options.push_back({context.does_not_apply_html, !part.asked, {}});
      s += multichoice(options);
      break;
    }
  }
  s += '}';
  return s;
}

std::string moodle_xml(const ExportSet& set) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n";
  const bool comma = set.language == "fr";
  for (const auto& slot : set.exercises) {
    const int scale = weight_scale(slot);
    // the exercise as the sheet heads it: the same name as its questions' ids' number
    const std::string category =
        fmt::format("$course$/top/{}/{}", category_segment(set.title), category_segment(slot.title));
    out += "  <question type=\"category\">\n";
    out += fmt::format("    <category><text>{}</text></category>\n", render::markup_escaped(category));
    out += "    <info format=\"html\"><text></text></info>\n";
    out += "  </question>\n";
    for (const auto& v : slot.variants) {
      std::string html;
      for (const auto& b : v.blocks) {
        switch (b.kind) {
          case Block::Kind::text: html += "<p>" + brace_safe(b.html) + "</p>\n"; break;
          case Block::Kind::image: {
            const Image& im = v.images[static_cast<std::size_t>(b.image)];
            html += fmt::format("<p><img src=\"@@PLUGINFILE@@/{}\" alt=\"{}\" width=\"{}\"/></p>\n", im.name,
                                render::markup_escaped(im.alt), im.width_px);
            break;
          }
          case Block::Kind::field: {
            html += "<p>" + brace_safe(b.html) + " ";
            std::vector<std::string> parts;
            for (int i : b.parts) {
              const Part& p = v.parts[static_cast<std::size_t>(i)];
              const int weight = static_cast<int>(std::lround(p.points * scale));
              const ClozeContext context{
                  std::find(slot.not_asked.begin(), slot.not_asked.end(), p.question_id) != slot.not_asked.end(),
                  set.does_not_apply_html, set.not_asked_feedback_html};
              parts.push_back(cloze_part(p, weight, context));
            }
            if (b.point) html += fmt::format("({})", fmt::join(parts, comma ? " ; " : ", "));
            else html += fmt::format("{}", fmt::join(parts, " "));
            html += "</p>\n";
            break;
          }
        }
      }
      out += "  <question type=\"multianswer\">\n";
      out += fmt::format("    <name><text>{}</text></name>\n", render::markup_escaped(v.name));
      out += "    <questiontext format=\"html\">\n";
      out += "      <text>" + cdata(html) + "</text>\n";
      for (const auto& im : v.images)
        out += fmt::format("      <file name=\"{}\" path=\"/\" encoding=\"base64\">{}</file>\n", render::markup_escaped(im.name),
                           base64(im.bytes));
      out += "    </questiontext>\n";
      // the key's worked solution for this variant, its diagrams as the feedback's own files
      out += "    <generalfeedback format=\"html\">\n";
      out += "      <text>" + cdata(solution_html(v, "@@PLUGINFILE@@/")) + "</text>\n";
      for (const auto& im : v.solution_images)
        out += fmt::format("      <file name=\"{}\" path=\"/\" encoding=\"base64\">{}</file>\n", render::markup_escaped(im.name),
                           base64(im.bytes));
      out += "    </generalfeedback>\n";
      out += "    <penalty>0.3333333</penalty>\n";  // Moodle's default, for a quiz with several tries
      out += "    <hidden>0</hidden>\n";
      out += fmt::format("    <idnumber>{}-{}</idnumber>\n", v.sheet_id, slot.n);
      out += "  </question>\n";
    }
  }
  out += "</quiz>\n";
  return out;
}

}  // namespace epure::exporting
