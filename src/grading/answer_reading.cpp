#include "grading/answer_reading.h"

#include <algorithm>
#include <utility>

#include "grading/expression.h"
#include "grading/words.h"

namespace epure::grading {

namespace {

bool is_space_at(std::string_view s, std::size_t i, std::size_t& width) {
  const char c = s[i];
  if (c == ' ' || c == '\t' || c == '\r' || c == '\n') return width = 1, true;
  if (c == '\xc2' && i + 1 < s.size() && s[i + 1] == '\xa0') return width = 2, true;
  if (c == '\xe2' && i + 2 < s.size() && s[i + 1] == '\x80' && (s[i + 2] == '\xaf' || s[i + 2] == '\x89'))
    return width = 3, true;
  return false;
}

// yes/no in the spellings most cells use, without building a folded string.
int fast_boolean(std::string_view s) {
  if (s.size() > 5) return -1;
  char b[6];
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    b[i] = c;
  }
  const std::string_view w(b, s.size());
  if (w == "yes" || w == "true" || w == "1" || w == "oui") return 1;
  if (w == "no" || w == "false" || w == "0" || w == "non") return 0;
  return -1;
}

}  // namespace

std::string_view trim_cell_spaces(std::string_view s) {
  std::size_t w = 0;
  while (!s.empty() && is_space_at(s, 0, w)) s.remove_prefix(w);
  // from the end: the last byte of a no-break space is 0xA0 / 0xAF / 0x89
  for (;;) {
    if (s.empty()) break;
    const char c = s.back();
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      s.remove_suffix(1);
    } else if (c == '\xa0' && s.size() >= 2 && s[s.size() - 2] == '\xc2') {
      s.remove_suffix(2);
    } else if ((c == '\xaf' || c == '\x89') && s.size() >= 3 && s[s.size() - 3] == '\xe2' && s[s.size() - 2] == '\x80') {
      s.remove_suffix(3);
    } else {
      break;
    }
  }
  return s;
}

bool read_faces(std::string_view text, FaceBits& out) {
  out = 0;
  if (auto w = read_word(text); w && *w == "none") return true;
  const std::string s = fold_word(text);
  std::size_t i = 0;
  bool any = false;
  while (i < s.size()) {
    const char c = s[i];
    if (c == ' ' || c == ',' || c == ';' || c == '/' || c == '|' || c == '&' || c == '{' || c == '}' ||
        c == '[' || c == ']' || c == '(' || c == ')') {
      ++i;
      continue;
    }
    if (s.compare(i, 4, "and ") == 0 || s.compare(i, 3, "et ") == 0) {
      i += s[i] == 'a' ? 4 : 3;
      continue;
    }
    int sign = 0;
    if (c == '+') sign = 1, ++i;
    else if (c == '-') sign = -1, ++i;
    else if (s.compare(i, 3, "\u2212") == 0) sign = -1, i += 3;
    while (i < s.size() && s[i] == ' ') ++i;
    if (i >= s.size()) return false;
    const char axis = s[i];
    if (axis != 'x' && axis != 'y' && axis != 'z') return false;
    ++i;
    if (sign == 0) {
      // "x=1", "x = -1": the side's equation
      while (i < s.size() && s[i] == ' ') ++i;
      if (i >= s.size() || s[i] != '=') return false;
      ++i;
      while (i < s.size() && s[i] == ' ') ++i;
      if (i < s.size() && s[i] == '+') ++i;
      if (s.compare(i, 1, "1") == 0) sign = 1, i += 1;
      else if (s.compare(i, 2, "-1") == 0) sign = -1, i += 2;
      else if (s.compare(i, 4, "\u22121") == 0) sign = -1, i += 4;
      else return false;
    }
    const std::string name{sign > 0 ? '+' : '-', axis};
    out |= face_bit(name);
    any = true;
  }
  return any;
}

PointCell read_point_cell(std::string_view cell, int dims, bool decimal_comma, std::array<std::string_view, 3>& parts) {
  std::string_view s = trim_cell(cell);
  // "P = (3 ; 5)", "P(3 ; 5)": the point's name before it
  if (const auto open = s.find_first_of("(["); open != std::string_view::npos && open > 0 && open <= 4) {
    std::string_view name = s.substr(0, open);
    while (!name.empty() && (name.back() == ' ' || name.back() == '=')) name.remove_suffix(1);
    if (!name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
          return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
        }))
      s = s.substr(open);
  }
  bool bracketed = false;
  if (s.size() >= 2 && ((s.front() == '(' && s.back() == ')') || (s.front() == '[' && s.back() == ']'))) {
    s = trim_cell(s.substr(1, s.size() - 2));
    bracketed = true;
  }
  const auto split = [&](auto&& at) -> int {
    int n = 0;
    std::string_view rest = s;
    for (;;) {
      const auto [where, width] = at(rest);
      const std::string_view part = trim_cell(rest.substr(0, where));
      if (n == 3 || part.empty()) return -1;
      parts[static_cast<std::size_t>(n++)] = part;
      if (where == std::string_view::npos) return n;
      rest.remove_prefix(where + width);
    }
  };
  auto semicolon = [](std::string_view r) { return std::pair{r.find(';'), std::size_t(1)}; };
  auto comma_blank = [](std::string_view r) {
    for (std::size_t i = 0; i + 1 < r.size(); ++i)
      if (r[i] == ',' && (r[i + 1] == ' ' || r[i + 1] == '\t')) return std::pair{i, std::size_t(1)};
    return std::pair{std::string_view::npos, std::size_t(1)};
  };
  auto comma = [](std::string_view r) { return std::pair{r.find(','), std::size_t(1)}; };
  int n = -1;
  if (s.find(';') != std::string_view::npos) n = split(semicolon);
  else if (comma_blank(s).first != std::string_view::npos) n = split(comma_blank);
  else if (s.find(',') != std::string_view::npos) {
    // "3,5" without brackets is a number in every language (a decimal comma is read anywhere);
    // "(3,5)" is a point in a language of decimal points, but in one of decimal commas it may be
    // the number 3,5 in brackets: not guessed.
    if (!bracketed) return PointCell::not_a_point;
    n = split(comma);
    if (decimal_comma) {
      bool numbers = n == dims;
      for (int i = 0; numbers && i < n; ++i) numbers = parse_number(parts[static_cast<std::size_t>(i)]).ok;
      return numbers ? PointCell::ambiguous : PointCell::not_a_point;
    }
  }
  if (n != dims) return PointCell::not_a_point;
  for (int i = 0; i < n; ++i)
    if (!parse_number(parts[static_cast<std::size_t>(i)]).ok) return PointCell::not_a_point;
  return PointCell::point;
}

void read_answer(std::string_view cell, AnswerType type, Given& g) {
  const std::string_view s = trim_cell(cell);
  g = Given{};
  g.raw = s;
  if (s.empty()) return;  // not answered
  const auto unreadable = [&](std::string_view why) {
    g = Given{};
    g.state = Given::State::unreadable;
    g.raw = s;
    g.why = why;
  };
  switch (type) {
    case AnswerType::point:  // never a key's question: read as the number it would be
    case AnswerType::number: {
      const ParsedNumber p = parse_number(s);
      if (!p.ok) return unreadable(p.why);
      g.number = p.value;
      break;
    }
    case AnswerType::boolean: {
      int b = fast_boolean(s);
      if (b < 0) {
        const auto w = read_word(s);
        if (w && *w == "true") b = 1;
        else if (w && *w == "false") b = 0;
        else return unreadable("boolean");
      }
      g.boolean = b == 1;
      break;
    }
    case AnswerType::choice: {
      const auto w = read_word(s);
      static constexpr std::string_view kChoices[] = {"before",  "between",  "after",     "intersects", "outside",
                                                      "parallel", "collinear", "behind", "miss"};
      if (!w || std::find(std::begin(kChoices), std::end(kChoices), *w) == std::end(kChoices))
        return unreadable("word");
      g.word = *w;
      break;
    }
    case AnswerType::faces: {
      if (!read_faces(s, g.faces)) return unreadable("faces");
      break;
    }
  }
  g.state = Given::State::value;
}

Given read_answer(std::string_view cell, AnswerType type) {
  Given g;
  read_answer(cell, type, g);
  return g;
}

}  // namespace epure::grading
