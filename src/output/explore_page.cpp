#include "output/explore_page.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

#include "embed/embedded.h"

namespace epure::output {

namespace {
// The page's configuration element, as src/explore/page.html writes it empty.
constexpr std::string_view kConfig = "<script id=\"epure-config\" type=\"application/json\">{}</script>";
}  // namespace

bool explore_available() { return explore_page().has_value(); }

std::string explore_unavailable_message() {
  return "this epure was built without the explorer page: em++ was not found when it was configured, "
         "or -DEPURE_EXPLORE=OFF (install Debian's emscripten package, then configure and build again; "
         "see README, \"epure explore\")";
}

std::string explore_html(std::string_view language, const std::vector<ExploreSheet>& sheets) {
  const auto page = explore_page();
  if (!page) throw std::runtime_error(explore_unavailable_message());
  nlohmann::json config = {{"lang", language}, {"set", nlohmann::json::object()}};
  for (const auto& s : sheets) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& i : s.instances) list.push_back(nlohmann::json::parse(i));
    config["set"][s.id] = std::move(list);
  }
  std::string text = config.dump();
  // inside <script>: no "</" may close it early
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  const auto at = page->find(kConfig);
  if (at == std::string_view::npos) throw std::logic_error("explore page: no configuration element");
  std::string html;
  html.reserve(page->size() + text.size());
  html.append(page->substr(0, at));
  html.append("<script id=\"epure-config\" type=\"application/json\">").append(text).append("</script>");
  html.append(page->substr(at + kConfig.size()));
  return html;
}

}  // namespace epure::output
