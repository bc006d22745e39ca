#include "grading/feedback_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "render/text.h"

namespace epure::grading {

namespace {
constexpr std::size_t kShortExact = 12;
}  // namespace

std::string pretty_exact(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.compare(i, 5, "sqrt(") == 0) {
      const auto close = s.find(')', i + 5);
      const auto inner = s.substr(i + 5, close - (i + 5));
      const bool digits = !inner.empty() && inner.find_first_not_of("0123456789") == std::string_view::npos;
      out += "\u221a";
      if (digits) out += inner;
      else out += fmt::format("({})", inner);
      i = close;
    } else if (s[i] == '*') {
      if (s.compare(i + 1, 5, "sqrt(") != 0) out += "\u00b7";
    } else if (s[i] == '-') {
      out += (i == 0 || s[i - 1] == '(') ? "\u2212" : " \u2212 ";
    } else if (s[i] == '+') {
      out += " + ";
    } else {
      out += s[i];
    }
  }
  return out;
}

namespace {

// The Unicode superscript of one character, or empty when it has none.
std::string_view superscript(std::string_view c) {
  static constexpr std::pair<std::string_view, std::string_view> kSuper[] = {
      {"0", "\u2070"}, {"1", "\u00b9"}, {"2", "\u00b2"}, {"3", "\u00b3"}, {"4", "\u2074"},
      {"5", "\u2075"}, {"6", "\u2076"}, {"7", "\u2077"}, {"8", "\u2078"}, {"9", "\u2079"},
      {"+", "\u207a"}, {"-", "\u207b"}, {"\u2212", "\u207b"}, {"=", "\u207c"}, {"(", "\u207d"},
      {")", "\u207e"}, {"n", "\u207f"}, {"i", "\u2071"}, {"T", "\u1d40"}};
  for (const auto& [plain, super] : kSuper)
    if (c == plain) return super;
  return {};
}

// Length of the UTF-8 character starting with byte c.
std::size_t char_length(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0xc0 ? 1 : u < 0xe0 ? 2 : u < 0xf0 ? 3 : 4;
}

// One run of parsed label markup, as plain text.
void append_run(const render::TextRun& run, std::string& out) {
  const std::string& text = run.text;
  if (run.shift == render::Shift::none) {
    out += text;
    return;
  }
  if (run.shift == render::Shift::super) {
    std::string raised;
    bool all = !text.empty();
    for (std::size_t k = 0; all && k < text.size(); k += char_length(text[k])) {
      const std::string_view super = superscript(std::string_view(text).substr(k, char_length(text[k])));
      all = !super.empty();
      raised += super;
    }
    if (all) {
      out += raised;
      return;
    }
  }
  std::size_t characters = 0;
  for (std::size_t k = 0; k < text.size(); k += char_length(text[k])) ++characters;
  const bool word = !text.empty() && std::all_of(text.begin(), text.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
  });
  out += run.shift == render::Shift::sub ? '_' : '^';
  // a subscript that is a name reads as the ids spell it (t_proj); a longer superscript
  // without a Unicode form needs its parentheses (r^(ab) is not r^a·b)
  if (characters == 1 || (run.shift == render::Shift::sub && word)) out += text;
  else out += "(" + text + ")";
}

}  // namespace

// The markup is parsed by the renderer's own parser (render/text.h), so that the plain text reads
// exactly the groups, escapes and unbalanced braces the drawn text shows.
std::string plain_text(std::string_view rich) {
  const std::vector<render::TextRun> runs = render::parse_rich_text(rich);
  std::string out;
  out.reserve(rich.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const bool arrow = runs[i].arrow;
    if (arrow && (i == 0 || !runs[i - 1].arrow)) out += "vec(";
    append_run(runs[i], out);
    if (arrow && (i + 1 == runs.size() || !runs[i + 1].arrow)) out += ')';
  }
  return out;
}

std::string rich_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '{' || c == '}' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out;
}

FeedbackText::FeedbackText(std::string_view language, int decimals)
    : texts_(Texts::builtin(language)), numbers_(NumberStyle::for_language(language)), decimals_(decimals) {}

std::string FeedbackText::points(double x) const {
  std::string s = fmt::format("{}", std::round(x * 1000) / 1000);
  if (numbers_.decimal_comma)
    for (char& c : s)
      if (c == '.') c = ',';
  return s;
}

std::string FeedbackText::expected(const QuestionKey& q) const {
  switch (q.type) {
    case AnswerType::point:  // never a key's question: read as the number it would be
    case AnswerType::number: {
      std::string s = numbers_.rounded(q.number, decimals_);
      // an exact form when it is short enough to help ("16/61", "5 − √11"), not "25√1066/1066"
      if (q.exact && q.exact->find_first_not_of("-0123456789") != std::string::npos && q.exact->size() <= kShortExact)
        s += fmt::format(" (= {})", numbers_.localise(pretty_exact(*q.exact)));
      return s;
    }
    case AnswerType::boolean: return texts_.get(q.boolean ? "common.yes" : "common.no");
    case AnswerType::choice: {
      const std::string key = "choice." + q.word;
      return texts_.has(key) ? texts_.get(key) : q.word;
    }
    case AnswerType::faces: return face_list(q.faces, texts_.get("common.none"));
  }
  return {};
}

std::string FeedbackText::given_shown(const QuestionKey& q, const QuestionMark& m) const {
  if (!m.given.readable()) return given(m);
  switch (q.type) {
    case AnswerType::point:  // never a key's question: read as the number it would be
    case AnswerType::number: return given(m);
    case AnswerType::boolean: return texts_.get(m.given.boolean ? "common.yes" : "common.no");
    case AnswerType::choice: {
      const std::string key = fmt::format("choice.{}", m.given.word);
      return texts_.has(key) ? texts_.get(key) : given(m);
    }
    case AnswerType::faces: return face_list(m.given.faces, texts_.get("common.none"));
  }
  return given(m);
}

const std::string& FeedbackText::verdict(Verdict v) const {
  return texts_.get(fmt::format("grading.verdict.{}", to_string(v)));
}

std::string FeedbackText::sentence(const QuestionKey& q, const QuestionMark& m) const { return compose(q, m, true, true); }

std::string FeedbackText::explanation(const QuestionKey& q, const QuestionMark& m) const {
  return compose(q, m, false, false);
}

std::string FeedbackText::compose(const QuestionKey& q, const QuestionMark& m, bool whole, bool plain) const {
  // plain: the student's own text is escaped before it goes into the template, so that making
  // the template plain turns its markup into text and leaves what they typed as they typed it
  const auto theirs = [&](std::string_view text) { return plain ? rich_escape(text) : std::string(text); };
  const TextVars vars = {{"expected", expected(q)},
                         {"given", theirs(given_shown(q, m))},
                         {"value", std::isfinite(m.value) ? number(m.value) : std::string()},
                         {"detail", theirs(m.detail)},
                         {"why", m.given.why.empty() ? std::string()
                                                     : texts_.get(fmt::format("grading.why.{}", m.given.why))},
                         {"other", rich_escape(m.note_field)}};
  auto say = [&](std::string_view key) {
    std::string text = texts_.format(key, vars);
    return plain ? plain_text(text) : text;
  };
  const std::string mistake = m.mistake.empty() ? std::string() : say(fmt::format("grading.mistake.{}", m.mistake));
  auto join = [](std::string a, const std::string& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return a + " " + b;
  };
  // how the answer was read, when not as typed where asked
  std::string read_as = m.note.empty() ? std::string() : say(fmt::format("grading.say.{}", m.note));
  if (m.corrected) read_as = join(read_as, say("grading.say.corrected"));
  switch (m.verdict) {
    case Verdict::right: return read_as;
    case Verdict::follow_through: return join(read_as, join(mistake, say("grading.say.follow_through")));
    case Verdict::unanswered: return whole ? say("grading.say.unanswered") : std::string();
    case Verdict::to_check: return join(read_as, whole ? say("grading.say.to_check") : say("grading.say.to_check_short"));
    case Verdict::wrong: {
      std::string s = join(read_as, join(whole ? say("grading.say.wrong") : std::string(), mistake));
      if (!m.from.empty()) s = join(s, say("grading.say.follow_through_off"));
      return s;
    }
  }
  return {};
}

}  // namespace epure::grading
