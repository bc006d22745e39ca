#include "grading/sheet_lookup.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace epure::grading {

namespace {

std::string normalise(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '-' || c == ' ' || c == '\t') continue;
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    if (c == 'O') c = '0';
    if (c == 'I' || c == 'L') c = '1';
    out.push_back(c);
  }
  return out;
}

}  // namespace

int id_distance(std::string_view a_text, std::string_view b_text) {
  const std::string a = normalise(a_text), b = normalise(b_text);
  const std::size_t n = a.size(), m = b.size();
  std::vector<int> d((n + 1) * (m + 1));
  auto at = [&](std::size_t i, std::size_t j) -> int& { return d[i * (m + 1) + j]; };
  for (std::size_t i = 0; i <= n; ++i) at(i, 0) = static_cast<int>(i);
  for (std::size_t j = 0; j <= m; ++j) at(0, j) = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      int v = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) v = std::min(v, at(i - 2, j - 2) + 1);
      at(i, j) = v;
    }
  return at(n, m);
}

SheetLookup find_sheet(const AnswerKey& key, std::string_view typed) {
  return find_sheet(key, typed, Texts::builtin(key.info.language));
}

SheetLookup find_sheet(const AnswerKey& key, std::string_view typed, const Texts& texts) {
  SheetLookup out;
  if (const SheetKey* s = key.find(typed)) {
    out.sheet = s;
    return out;
  }
  const auto parsed = parse_sheet_id(typed);
  if (parsed.id) {
    const std::string canonical = parsed.id->str();
    if (const SheetKey* s = key.find(canonical)) {
      out.sheet = s;
      return out;
    }
    if (key.refused().count(canonical)) {
      // key_from_spec refuses only ids of another draw version (its reason, in English, is for
      // the command's own report): said here in the set's language
      out.why = texts.format("grading.lookup.refused", {{"sheet", canonical},
                                                        {"version", std::to_string(parsed.id->version)},
                                                        {"draw", std::to_string(kDrawVersion)}});
    } else if (parsed.id->version != key.info.draw_version) {
      out.why = texts.format("grading.lookup.other_version", {{"sheet", canonical},
                                                              {"version", std::to_string(parsed.id->version)},
                                                              {"key_version", std::to_string(key.info.draw_version)}});
    } else if (parsed.id->seed != key.info.seed) {
      out.why = texts.format("grading.lookup.other_seed", {{"sheet", canonical},
                                                           {"seed", std::to_string(parsed.id->seed)},
                                                           {"key_seed", std::to_string(key.info.seed)}});
    } else {
      out.why = texts.format("grading.lookup.not_in_key",
                             {{"sheet", canonical}, {"number", std::to_string(parsed.id->index + 1)}});
    }
  } else {
    const SheetIdError& e = parsed.error;
    const std::string why =
        e.code == "character" ? texts.format("grading.lookup.character", {{"character", e.detail}})
        : e.code == "length"  ? texts.format("grading.lookup.length", {{"count", e.detail}})
        : e.code == "too_long" ? texts.get("grading.lookup.too_long")
        : e.code == "check"    ? texts.get("grading.lookup.check")
                               : e.message;
    out.why = texts.format("grading.lookup.invalid", {{"typed", std::string(typed)}, {"why", why}});
  }
  int best = 1 << 30;
  for (const auto& s : key.sheets()) {
    const int d = id_distance(typed, s.id);
    if (d < best) {
      best = d;
      out.nearest = s.id;
    }
  }
  out.distance = best;
  return out;
}

}  // namespace epure::grading
