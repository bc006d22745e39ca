#pragma once
// Statement and worked-solution text, per language, from templates/text/<lang>/*.toml (compiled
// into the binary). No sentence is written in C++: exercises fill placeholders ${name} with
// values already formatted for the language (numbers.h), and the result is RichText
// (render/scene.h markup: t_{ab}, r^{2}, \vec{AB}).
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace epure {

using TextVars = std::vector<std::pair<std::string, std::string>>;

class Texts {
 public:
  // The built-in texts of a language ("en", "fr"); throws std::invalid_argument naming the
  // languages there are.
  static const Texts& builtin(std::string_view language);
  // Parses a TOML text (tables give dotted keys: [projection] statement → "projection.statement").
  // Throws std::runtime_error with the source name, line and key for bad TOML.
  static Texts parse(std::string_view toml_text, std::string_view source_name);

  const std::string& language() const { return language_; }
  bool has(std::string_view key) const;
  // The raw template; throws std::out_of_range naming the key and the language.
  const std::string& get(std::string_view key) const;
  // The template with every ${name} replaced; throws std::invalid_argument for a placeholder
  // that `vars` does not give (a template and its exercise disagree: a bug, caught by tests).
  std::string format(std::string_view key, const TextVars& vars = {}) const;

  const std::map<std::string, std::string, std::less<>>& all() const { return entries_; }
  void merge(const Texts& other);  // other's entries win
  void set_language(std::string language) { language_ = std::move(language); }

 private:
  std::string language_;
  std::map<std::string, std::string, std::less<>> entries_;
};

// Substitutes ${name} in `text`; throws std::invalid_argument for an unknown name.
std::string substitute(std::string_view text, const TextVars& vars);

// The language codes the binary has texts for.
std::vector<std::string> builtin_languages();

}  // namespace epure
