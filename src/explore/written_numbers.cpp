#include "explore/written_numbers.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>

#include "solve/line_reader.h"

namespace epure::explore {

namespace {

using nlohmann::json;

bool same_double(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }  // -0 is not 0

// The double nlohmann read at (field, item) of `doc`: item < 0 for the field itself.
const json* number_at(const json& doc, const std::string& field, int item) {
  const auto it = doc.find(field);
  if (it == doc.end()) return nullptr;
  const json* v = &*it;
  if (item >= 0) {
    if (!v->is_array() || static_cast<std::size_t>(item) >= v->size()) return nullptr;
    v = &(*v)[static_cast<std::size_t>(item)];
  }
  return v->is_number_float() ? v : nullptr;
}

}  // namespace

std::string with_written_numbers(std::string_view canonical, std::string_view written) {
  const json doc = json::parse(written, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return std::string(canonical);
  solve::NumberTexts texts;
  texts.read(written);

  // A scan of `canonical`: depth 1 holds the fields, depth 2 an array's items; a string at depth
  // 1 followed by ':' is the field being read.
  std::string out;
  out.reserve(canonical.size() + 32);
  std::string field;
  int depth = 0, item = 0;
  bool field_ok = false;
  for (std::size_t i = 0; i < canonical.size();) {
    const char c = canonical[i];
    if (c == '"') {  // a string, escapes included, copied as it is
      std::size_t j = i + 1;
      while (j < canonical.size() && canonical[j] != '"') j += canonical[j] == '\\' ? 2 : 1;
      j = std::min(j + 1, canonical.size());
      const std::string_view s = canonical.substr(i, j - i);
      std::size_t k = j;
      while (k < canonical.size() && (canonical[k] == ' ' || canonical[k] == '\t')) ++k;
      if (depth == 1 && k < canonical.size() && canonical[k] == ':') {
        const json key = json::parse(s, nullptr, false);
        field_ok = key.is_string();
        field = field_ok ? key.get<std::string>() : std::string();
      }
      out += s;
      i = j;
      continue;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t j = i + 1;
      while (j < canonical.size() && std::strchr("0123456789.eE+-", canonical[j]) != nullptr) ++j;
      const std::string token(canonical.substr(i, j - i));
      const int at = depth == 1 ? -1 : item;
      const solve::NumberTexts::Texts* t = field_ok && (depth == 1 || depth == 2) ? texts.of(field) : nullptr;
      const std::size_t slot = at < 0 ? 0 : static_cast<std::size_t>(at);
      const json* typed = t && slot < t->size() && !(*t)[slot].empty() ? number_at(doc, field, at) : nullptr;
      if (typed && same_double(typed->get<double>(), std::strtod(token.c_str(), nullptr))) out += (*t)[slot];
      else out += token;
      i = j;
      continue;
    }
    if (c == '{' || c == '[') {
      ++depth;
      if (depth == 2) item = 0;
    } else if (c == '}' || c == ']') {
      --depth;
    } else if (c == ',' && depth == 2) {
      ++item;
    }
    out += c;
    ++i;
  }
  return out;
}

}  // namespace epure::explore
