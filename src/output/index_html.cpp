#include "output/index_html.h"

#include <fmt/format.h>

#include "render/markup_escape.h"

namespace epure::output {

namespace {

std::string escape(std::string_view s) { return render::markup_escaped(s); }

// "explore: 1 2 3": each exercise of the sheet in the interactive page, with its own data.
std::string explore_links(const IndexEntry& e, bool explore) {
  if (!explore || e.exercises == 0) return {};
  std::string links = "<p class=\"explore\"><a href=\"explore.html\">explore</a>:";
  for (int n = 1; n <= e.exercises; ++n)
    links += fmt::format(" <a href=\"explore.html#{0}.{1}\">{1}</a>", escape(e.id), n);
  return links + "</p>\n";
}

}  // namespace

void write_index_html(const std::function<void(std::string_view)>& write, const std::string& title,
                      const std::string& course, const std::string& language,
                      const std::vector<IndexEntry>& entries, PdfLinks pdfs, bool explore) {
  write(fmt::format(
      "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>{}</title>\n<style>\n"
      "body{{font-family:'DejaVu Sans',sans-serif;margin:2em;background:#f4f4f4;color:#222}}\n"
      "h1{{font-size:1.4em}} .course{{color:#555}}\n"
      "section{{background:#fff;margin:1.5em 0;padding:1em;box-shadow:0 1px 3px #0002}}\n"
      "section h2{{font-size:1.1em;font-family:monospace}}\n"
      ".pair{{display:flex;gap:1em;align-items:flex-start}} .pair a{{flex:1}}\n"
      ".pair img{{width:100%;border:1px solid #ccc;background:#fff}}\n"
      "nav a{{margin-right:.6em;font-family:monospace}}\n"
      "</style>\n</head>\n<body>\n<h1>{}</h1>\n<p class=\"course\">{}</p>\n"
      "<p>{} sheets. <a href=\"key.json\">key.json</a>{}</p>\n<nav>\n",
      escape(language), escape(title), escape(title), escape(course), entries.size(),
      pdfs == PdfLinks::class_set ? " · <a href=\"sheets.pdf\">sheets.pdf</a> · <a href=\"keys.pdf\">keys.pdf</a>" : ""));
  for (const auto& e : entries) write(fmt::format("<a href=\"#s-{0}\">{0}</a>\n", escape(e.id)));
  write("</nav>\n");
  for (const auto& e : entries) {
    const std::string id = escape(e.id);
    write(fmt::format(
        "<section id=\"s-{0}\">\n<h2>{0}{1}</h2>\n<div class=\"pair\">\n"
        "<a href=\"sheets/{0}.svg\"><img src=\"sheets/{0}.svg\" alt=\"sheet {0}\" loading=\"lazy\"></a>\n"
        "<a href=\"keys/{0}.svg\"><img src=\"keys/{0}.svg\" alt=\"key {0}\" loading=\"lazy\"></a>\n"
        "</div>\n{2}</section>\n",
        id,
        pdfs == PdfLinks::per_sheet
            ? fmt::format(" <a href=\"sheets/{0}.pdf\">sheet PDF</a> <a href=\"keys/{0}.pdf\">key PDF</a>", id)
            : std::string(),
        explore_links(e, explore)));
  }
  write("</body>\n</html>\n");
}

}  // namespace epure::output
