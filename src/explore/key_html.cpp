#include "explore/key_html.h"

#include <string_view>
#include <variant>

#include "render/markup_escape.h"
#include "render/text.h"

namespace epure::explore {

namespace {

// The label markup (t_{ab}, r^{2}, \vec{AB}) as HTML, through the parser every backend uses,
// appended to `out`: each of parse_rich_text's runs (pieces of one shift and arrow) in its tags.
class HtmlRuns final : public render::RichSink {
 public:
  explicit HtmlRuns(std::string& out) : out_(out) {}
  ~HtmlRuns() { close(); }
  void piece(std::string_view text, render::Shift shift, bool arrow) override {
    if (!open_ || shift != shift_ || arrow != arrow_) {
      close();
      open_ = true, shift_ = shift, arrow_ = arrow;
      if (const char* tag = script()) out_ += '<', out_ += tag, out_ += '>';
      if (arrow_) out_ += "<span class=\"vec\">";
    }
    render::append_markup_escaped(out_, text);
  }

 private:
  const char* script() const {
    return shift_ == render::Shift::sub ? "sub" : shift_ == render::Shift::super ? "sup" : nullptr;
  }
  void close() {
    if (!open_) return;
    if (arrow_) out_ += "</span>";
    if (const char* tag = script()) out_ += "</", out_ += tag, out_ += '>';
  }
  std::string& out_;
  bool open_ = false, arrow_ = false;
  render::Shift shift_ = render::Shift::none;
};

void append_rich_html(std::string& out, std::string_view rich) {
  HtmlRuns runs(out);
  render::parse_rich_pieces(rich, runs);
}

}  // namespace

KeyView key_view(render::Section& key) {
  KeyView v;
  std::string& out = v.steps;
  for (auto& block : key.blocks) {
    if (const auto* h = std::get_if<render::Heading>(&block)) {
      const std::string level = std::to_string(h->level + 1);
      out += "<h" + level + '>';
      append_rich_html(out, h->text);
      out += "</h" + level + ">\n";
    } else if (const auto* p = std::get_if<render::Paragraph>(&block)) {
      out += p->emphasis ? "<p class=\"emphasis\">" : "<p>";
      append_rich_html(out, p->text);
      out += "</p>\n";
    } else if (const auto* a = std::get_if<render::AnswerLine>(&block)) {
      out += "<p class=\"answer\" data-question=\"";
      out += a->question_id;
      out += "\"><span class=\"prompt\">";
      append_rich_html(out, a->prompt);
      out += "</span> ";
      append_rich_html(out, a->answer);
      out += "</p>\n";
    } else if (auto* f = std::get_if<render::Figure>(&block)) {
      if (v.figure == nullptr) v.figure = &f->scene;
      out += "<div class=\"figure-here\"></div>\n";
    }
  }
  return v;
}

}  // namespace epure::explore
