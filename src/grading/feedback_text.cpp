#include "grading/feedback_text.h"

#include <fmt/format.h>

#include <cmath>

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
    case AnswerType::number: {
      std::string s = numbers_.rounded(q.number, decimals_);
      // an exact form when it is short enough to help ("16/61", "5 − √11"), not "25√1066/1066"
      if (q.exact && q.exact->find_first_not_of("-0123456789") != std::string::npos && q.exact->size() <= kShortExact)
        s += fmt::format(" (= {})", numbers_.localise(pretty_exact(*q.exact)));
      return s;
    }
    case AnswerType::boolean: return texts_.get(q.boolean ? "common.yes" : "common.no");
    case AnswerType::word: {
      const std::string key = "choice." + q.word;
      return texts_.has(key) ? texts_.get(key) : q.word;
    }
    case AnswerType::faces: return face_list(q.faces, texts_.get("common.none"));
  }
  return {};
}

const std::string& FeedbackText::verdict(Verdict v) const {
  return texts_.get(fmt::format("grading.verdict.{}", to_string(v)));
}

std::string FeedbackText::sentence(const QuestionKey& q, const QuestionMark& m) const { return compose(q, m, true); }

std::string FeedbackText::explanation(const QuestionKey& q, const QuestionMark& m) const { return compose(q, m, false); }

std::string FeedbackText::compose(const QuestionKey& q, const QuestionMark& m, bool whole) const {
  const TextVars vars = {{"expected", expected(q)},
                         {"given", std::string(m.given.raw)},
                         {"value", std::isfinite(m.value) ? number(m.value) : std::string()},
                         {"detail", m.detail},
                         {"why", m.given.why.empty() ? std::string()
                                                     : texts_.get(fmt::format("grading.why.{}", m.given.why))}};
  auto say = [&](std::string_view key) { return texts_.format(key, vars); };
  const std::string mistake = m.mistake.empty() ? std::string() : say(fmt::format("grading.mistake.{}", m.mistake));
  auto join = [](std::string a, const std::string& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return a + " " + b;
  };
  switch (m.verdict) {
    case Verdict::right: return {};
    case Verdict::follow_through: return join(mistake, say("grading.say.follow_through"));
    case Verdict::unanswered: return whole ? say("grading.say.unanswered") : std::string();
    case Verdict::unreadable: return whole ? say("grading.say.unreadable") : say("grading.say.unreadable_short");
    case Verdict::wrong: {
      std::string s = join(whole ? say("grading.say.wrong") : std::string(), mistake);
      if (!m.from.empty()) s = join(s, say("grading.say.follow_through_off"));
      return s;
    }
  }
  return {};
}

}  // namespace epure::grading
