#include "output/explore_page.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <utility>

#include "embed/embedded.h"
#include "exercises/texts.h"
#include "render/markup_escape.h"

namespace epure::output {

namespace {
// The page's configuration element, as src/explore/page.html writes it empty.
constexpr std::string_view kConfig = "<script id=\"epure-config\" type=\"application/json\">{}</script>";
// Its language and title, as page.html writes them; set to the set's before the script runs, so
// that a reader, a search or a screen reader that never runs it gets them too.
constexpr std::string_view kLang = "<html lang=\"en\">";
constexpr std::string_view kTitle = "<title></title>";

std::string head_in(std::string_view page_head, std::string_view language) {
  std::string head(page_head);
  const auto lang_at = head.find(kLang);
  const auto title_at = head.find(kTitle);
  if (lang_at == std::string::npos || title_at == std::string::npos || title_at < lang_at)
    throw std::logic_error("explore page: no <html lang> or <title> to set");
  std::string title = "<title>";
  render::append_markup_escaped(title, Texts::builtin(language).get("explore.title"));
  title += "</title>";
  head.replace(title_at, kTitle.size(), title);
  std::string lang = "<html lang=\"";
  render::append_markup_escaped(lang, language);
  lang += "\">";
  head.replace(lang_at, kLang.size(), lang);
  return head;
}
}  // namespace

bool explore_available() { return explore_page().has_value(); }

std::string explore_unavailable_message() {
  return "this epure was built without the explorer page: em++ was not found when it was configured, "
         "or -DEPURE_EXPLORE=OFF (install Debian's emscripten package, then configure and build again; "
         "see README, \"epure explore\")";
}

ExplorePageWriter::ExplorePageWriter(std::string_view language, Write write, const ExerciseLabels& labels)
    : write_(std::move(write)) {
  const auto page = explore_page();
  if (!page) throw std::runtime_error(explore_unavailable_message());
  page_ = *page;
  config_at_ = page_.find(kConfig);
  if (config_at_ == std::string_view::npos) throw std::logic_error("explore page: no configuration element");
  write_(head_in(page_.substr(0, config_at_), language));
  write_("<script id=\"epure-config\" type=\"application/json\">");
  // {"labels":{…},"lang":…,"set":{"<id>":[…],…}}, as nlohmann::json's dump() writes the object:
  // no spaces, keys in order ("labels" < "lang" < "set"; the ids added in increasing order);
  // without labels, no "labels"
  std::string head = "{";
  if (!labels.empty()) head += "\"labels\":" + nlohmann::json(labels).dump() + ",";
  put(head + "\"lang\":" + nlohmann::json(language).dump() + ",\"set\":{");
}

void ExplorePageWriter::add(const ExploreSheet& sheet) {
  if (!first_ && !(last_id_ < sheet.id)) throw std::logic_error("explore page: sheets out of id order");
  nlohmann::json list = nlohmann::json::array();
  // each instance as its text, a JSON string: the page hands it to the core as it is, so that a
  // number means the decimals written here, not what a JavaScript double writes back
  for (const auto& i : sheet.instances) list.push_back(i);
  std::string piece = first_ ? "" : ",";
  piece.append(nlohmann::json(sheet.id).dump()).append(":").append(list.dump());
  put(std::move(piece));
  first_ = false;
  last_id_ = sheet.id;
}

void ExplorePageWriter::finish() {
  put("}}");
  write_("</script>");
  write_(page_.substr(config_at_ + kConfig.size()));
}

// Inside <script>, no "</" may close it early, and no "<!--" may open the script's escaped
// state (where the page's real </script> would no longer close it): every '<' is written as
// \u003c, which JSON reads back as the same character (a spec's heading can hold anything).
void ExplorePageWriter::put(std::string text) {
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 6))
    text.replace(at, 1, "\\u003c");
  write_(text);
}

std::string explore_html(std::string_view language, const std::vector<ExploreSheet>& sheets,
                         const ExerciseLabels& labels) {
  std::string html;
  ExplorePageWriter page(language, [&](std::string_view bytes) { html.append(bytes); }, labels);
  for (const auto& s : sheets) page.add(s);
  page.finish();
  return html;
}

}  // namespace epure::output
