#include "export/export_set.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "render/markup_escape.h"
#include "render/text.h"

// The pieces every platform writer shares (export_set.h, "shared pieces of the writers"): markup
// as HTML, a variant's worked solution as XHTML, numbers as the shortest decimals, the key's rules
// as widths, the face sets of a part.
namespace epure::exporting {

std::vector<std::vector<std::string>> face_sets(const Part& faces) {
  std::vector<std::string> sides;
  for (const auto& o : faces.options)
    if (o.id != "none") sides.push_back(o.id);
  // every subset, as a mask over the sides; then by size, the sides in the options' order
  std::vector<std::vector<std::string>> sets;
  for (unsigned mask = 0; mask < (1u << sides.size()); ++mask) {
    std::vector<std::string> set;
    for (std::size_t i = 0; i < sides.size(); ++i)
      if (mask & (1u << i)) set.push_back(sides[i]);
    sets.push_back(std::move(set));
  }
  std::stable_sort(sets.begin(), sets.end(), [&](const auto& a, const auto& b) {
    if (a.size() != b.size()) return a.size() < b.size();
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), [&](const auto& x, const auto& y) {
      return std::find(sides.begin(), sides.end(), x) < std::find(sides.begin(), sides.end(), y);
    });
  });
  return sets;
}

std::string face_set_html(const Part& faces, const std::vector<std::string>& set) {
  const auto html_of_option = [&](std::string_view id) {
    for (const auto& o : faces.options)
      if (o.id == id) return o.html;
    return render::markup_escaped(id);
  };
  if (set.empty()) return html_of_option("none");
  std::string out;
  for (const auto& f : set) out += (out.empty() ? "" : ", ") + html_of_option(f);
  return out;
}

std::string html_of(std::string_view rich) {
  std::string out;
  for (const auto& run : render::parse_rich_text(rich)) {
    std::string text;
    for (char c : run.text) {
      if (c == '\n') text += "<br/>";
      else render::append_markup_escaped(text, std::string_view(&c, 1));
    }
    if (run.arrow) text += "\u20d7";  // a combining arrow over the vector's (last) letter
    if (run.bold) text = "<b>" + text + "</b>";
    switch (run.shift) {
      case render::Shift::none: out += text; break;
      case render::Shift::sub: out += "<sub>" + text + "</sub>"; break;
      case render::Shift::super: out += "<sup>" + text + "</sup>"; break;
    }
  }
  return out;
}

std::string solution_html(const Variant& v, std::string_view image_src) {
  std::string out;
  bool table = false;
  for (const auto& b : v.solution) {
    if (b.kind == SolutionBlock::Kind::answer) {
      if (!table) out += "<table><tbody>\n";
      table = true;
      out += fmt::format("<tr><td>{}</td><td>{}</td></tr>\n", b.html, b.answer_html);
      continue;
    }
    if (table) out += "</tbody></table>\n";
    table = false;
    switch (b.kind) {
      case SolutionBlock::Kind::heading: out += "<p><strong>" + b.html + "</strong></p>\n"; break;
      case SolutionBlock::Kind::text: out += "<p>" + b.html + "</p>\n"; break;
      case SolutionBlock::Kind::image: {
        const Image& im = v.solution_images[static_cast<std::size_t>(b.image)];
        out += fmt::format("<p><img src=\"{}{}\" alt=\"{}\" width=\"{}\"/></p>\n", image_src, im.name,
                           render::markup_escaped(im.alt), im.width_px);
        break;
      }
      case SolutionBlock::Kind::answer: break;
    }
  }
  if (table) out += "</tbody></table>\n";
  return out;
}

std::string shortest(double x) {
  if (!std::isfinite(x)) throw ExportError(fmt::format("a number that is not finite ({}) cannot be exported", x));
  if (x == 0) return "0";  // and not "-0"
  return fmt::format("{}", x);
}

double rule_width(const ToleranceRule& rule, double at) {
  switch (rule.kind) {
    case ToleranceRule::Kind::isclose: return std::max(rule.rel * std::abs(at), rule.abs);
    case ToleranceRule::Kind::distance: return rule.abs / std::sqrt(2.0);
    case ToleranceRule::Kind::exact: return 0;
  }
  return 0;
}

double conservative_width(double width, double value) {
  const double w = width - 1e-12 * std::max(1.0, std::abs(value));
  if (!(w > 0)) return 0;
  const int e = static_cast<int>(std::floor(std::log10(w)));
  // w = m·10^(e−3) with m in [1000, 10000): keep m's integer part
  const int k = 3 - e;
  const auto scaled = [&](double m) { return k >= 0 ? m / std::pow(10.0, k) : m * std::pow(10.0, -k); };
  double m = std::floor(k >= 0 ? w * std::pow(10.0, k) : w / std::pow(10.0, -k));
  while (m > 0 && scaled(m) > w) m -= 1;  // the decimal's double may round up past w
  return scaled(m);
}

}  // namespace epure::exporting
