#include "grading/words.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "exercises/texts.h"

namespace epure::grading {

namespace {

// The contract words the lists map to.
constexpr std::string_view kTokens[] = {"true",     "false",     "none",   "before", "between", "after",
                                        "intersects", "outside", "parallel", "collinear", "behind", "miss",
                                        "sheet",    "student",   "student_number", "email", "first_name",
                                        "last_name"};

// The ASCII letter a Latin-1 letter (the byte after 0xC3 in UTF-8) folds to, or 0.
char fold_latin1(unsigned char b) {
  b = static_cast<unsigned char>(b | 0x20);  // upper → lower half (À 0x80 → à 0xA0)
  if (b >= 0xa0 && b <= 0xa5) return 'a';
  if (b == 0xa7) return 'c';
  if (b >= 0xa8 && b <= 0xab) return 'e';
  if (b >= 0xac && b <= 0xaf) return 'i';
  if (b == 0xb1) return 'n';
  if (b >= 0xb2 && b <= 0xb6) return 'o';
  if (b >= 0xb9 && b <= 0xbc) return 'u';
  if (b == 0xbd || b == 0xbf) return 'y';
  return 0;
}

// Calls fn on each comma-separated entry of a [grading.read] list.
template <class Fn>
void each_entry(std::string_view list, Fn&& fn) {
  while (!list.empty()) {
    const auto comma = list.find(',');
    fn(list.substr(0, comma));
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
}

struct WordTable {
  std::unordered_map<std::string, std::string_view> words;
  // What may surround an answer without changing it ("le rayon … du cercle"), folded, longest
  // first so that "la droite du rayon" is taken before "la droite".
  std::vector<std::string> leads, tails;
};

const WordTable& word_table() {
  static const WordTable table = [] {
    WordTable t;
    auto add = [&](std::string_view word, std::string_view token) {
      const std::string key = fold_word(word);
      if (!key.empty()) t.words.emplace(key, token);
    };
    for (auto token : kTokens) add(token, token);
    for (const auto& language : builtin_languages()) {
      const Texts& texts = Texts::builtin(language);
      for (auto token : kTokens) {
        const std::string list_key = "grading.read." + std::string(token);
        if (texts.has(list_key)) each_entry(texts.get(list_key), [&](std::string_view w) { add(w, token); });
        const std::string choice_key = "choice." + std::string(token);
        if (texts.has(choice_key)) add(texts.get(choice_key), token);
      }
      for (const auto& affix : {std::pair{"grading.read.lead", &t.leads}, std::pair{"grading.read.tail", &t.tails}}) {
        std::vector<std::string>* into = affix.second;
        if (texts.has(affix.first))
          each_entry(texts.get(affix.first), [into](std::string_view w) {
            if (std::string f = fold_word(w); !f.empty()) into->push_back(std::move(f));
          });
      }
    }
    for (auto* list : {&t.leads, &t.tails}) {
      std::sort(list->begin(), list->end(), [](const std::string& a, const std::string& b) {
        return a.size() != b.size() ? a.size() > b.size() : a < b;
      });
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    return t;
  }();
  return table;
}

// `folded` without a lead ("le rayon ") or a tail (" du cercle") of the table, as whole words;
// empty when it has neither.
std::string_view without(std::string_view folded, const std::vector<std::string>& affixes, bool lead) {
  for (const auto& a : affixes) {
    if (folded.size() <= a.size() + 1) continue;
    if (lead && folded.starts_with(a) && folded[a.size()] == ' ') return folded.substr(a.size() + 1);
    if (!lead && folded.ends_with(a) && folded[folded.size() - a.size() - 1] == ' ')
      return folded.substr(0, folded.size() - a.size() - 1);
  }
  return {};
}

}  // namespace

std::string fold_word(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  bool space = false;
  auto put = [&](char c) {
    if (c == ' ') {
      space = !out.empty();
      return;
    }
    if (space) out.push_back(' ');
    space = false;
    out.push_back(c);
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto b = static_cast<unsigned char>(s[i]);
    if (b < 0x80) {
      char c = static_cast<char>(b);
      if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
      if (c == '\'' || c == '_' || c == '\t' || c == '"' || c == '\r' || c == '\n') c = ' ';
      put(c);
    } else if (b == 0xc3 && i + 1 < s.size()) {
      const char f = fold_latin1(static_cast<unsigned char>(s[i + 1]));
      if (f) {
        put(f);
        ++i;
      } else {
        put(s[i]);
      }
    } else if (b == 0xc5 && i + 1 < s.size() && (s[i + 1] == '\x93' || s[i + 1] == '\x92')) {
      put('o'), put('e'), ++i;  // œ, Œ
    } else if (b == 0xc2 && i + 1 < s.size() && s[i + 1] == '\xa0') {
      put(' '), ++i;  // no-break space
    } else if (b == 0xe2 && i + 2 < s.size() && s[i + 1] == '\x80' &&
               (s[i + 2] == '\x98' || s[i + 2] == '\x99' || s[i + 2] == '\xaf' || s[i + 2] == '\x89')) {
      put(' '), i += 2;  // ‘ ’ and narrow or thin spaces
    } else if (b == 0xe2 && i + 2 < s.size() && s[i + 1] == '\x80' && (s[i + 2] == '\x9c' || s[i + 2] == '\x9d')) {
      put(' '), i += 2;  // “ ”
    } else if (b == 0xc2 && i + 1 < s.size() && (s[i + 1] == '\xab' || s[i + 1] == '\xbb')) {
      put(' '), ++i;  // « »
    } else {
      put(s[i]);
    }
  }
  while (!out.empty() && (out.back() == '.' || out.back() == ' ')) out.pop_back();
  return out;
}

std::optional<std::string_view> read_word(std::string_view text) {
  const auto& table = word_table();
  const std::string folded = fold_word(text);
  const auto find = [&](std::string_view w) -> std::optional<std::string_view> {
    if (w.empty()) return std::nullopt;
    auto it = table.words.find(std::string(w));
    if (it == table.words.end()) return std::nullopt;
    return it->second;
  };
  if (auto w = find(folded)) return w;
  // the answer inside a sentence: "le rayon passe à côté du cercle", "P est avant A"
  const std::string_view no_lead = without(folded, table.leads, true);
  if (auto w = find(no_lead)) return w;
  const std::string_view base = no_lead.empty() ? std::string_view(folded) : no_lead;
  if (auto w = find(without(base, table.tails, false))) return w;
  if (!no_lead.empty())
    if (auto w = find(without(folded, table.tails, false))) return w;
  return std::nullopt;
}

}  // namespace epure::grading
