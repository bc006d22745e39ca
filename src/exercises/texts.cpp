#include "exercises/texts.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <stdexcept>

#include "embed/embedded.h"

namespace epure {

namespace {

void flatten(const toml::table& table, const std::string& prefix,
             std::map<std::string, std::string, std::less<>>& out, std::string_view source) {
  for (const auto& [key, node] : table) {
    std::string name = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const auto* sub = node.as_table()) {
      flatten(*sub, name, out, source);
    } else if (const auto* text = node.as_string()) {
      out.emplace(name, text->get());
    } else {
      const auto& where = node.source().begin;
      throw std::runtime_error(fmt::format("{}:{}:{}: key '{}': expected a string", source,
                                           where.line, where.column, name));
    }
  }
}

}  // namespace

std::string substitute(std::string_view text, const TextVars& vars) {
  std::string out;
  out.reserve(text.size() + 32);
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '$' && i + 1 < text.size() && text[i + 1] == '{') {
      const std::size_t close = text.find('}', i + 2);
      if (close == std::string_view::npos) throw std::invalid_argument("unclosed ${ in template");
      const std::string_view name = text.substr(i + 2, close - i - 2);
      bool found = false;
      for (const auto& [k, v] : vars)
        if (k == name) {
          out += v;
          found = true;
          break;
        }
      if (!found) throw std::invalid_argument(fmt::format("template needs ${{{}}}, not given", name));
      i = close + 1;
    } else {
      // up to the next '$', the text as it is
      const std::size_t next = std::min(text.find('$', i + 1), text.size());
      out.append(text, i, next - i);
      i = next;
    }
  }
  return out;
}

Texts Texts::parse(std::string_view toml_text, std::string_view source_name) {
  toml::table table;
  try {
    table = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(fmt::format("{}:{}:{}: {}", source_name, e.source().begin.line,
                                         e.source().begin.column, e.description()));
  }
  Texts texts;
  texts.language_ = table["language"].value_or(std::string{});
  flatten(table, "", texts.entries_, source_name);
  return texts;
}

std::vector<std::string> builtin_languages() { return {"en", "fr"}; }

namespace {

// Every templates/text/<language>/*.toml file, merged: one file per exercise kind, so that each
// kind's sentences sit together.
Texts load_builtin(const std::string& language) {
  Texts merged;
  const std::string prefix = "text/" + language + "/";
  for (auto name : embedded_files()) {
    if (name.substr(0, prefix.size()) != prefix) continue;
    Texts part = Texts::parse(*embedded_file(name), "templates/" + std::string(name));
    merged.merge(part);
  }
  merged.set_language(language);
  return merged;
}

}  // namespace

void Texts::merge(const Texts& other) {
  for (const auto& [k, v] : other.entries_) entries_[k] = v;
}

const Texts& Texts::builtin(std::string_view language) {
  static const Texts en = load_builtin("en");
  static const Texts fr = load_builtin("fr");
  if (language == "en") return en;
  if (language == "fr") return fr;
  throw std::invalid_argument(fmt::format("no texts for language '{}' (there are: en, fr)", language));
}

bool Texts::has(std::string_view key) const { return entries_.find(key) != entries_.end(); }

const std::string& Texts::get(std::string_view key) const {
  auto it = entries_.find(key);
  if (it == entries_.end())
    throw std::out_of_range(fmt::format("no text '{}' in language '{}'", key, language_));
  return it->second;
}

std::string Texts::format(std::string_view key, const TextVars& vars) const {
  try {
    return substitute(get(key), vars);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("text '{}' ({}): {}", key, language_, e.what()));
  }
}

}  // namespace epure
