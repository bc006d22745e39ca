// The zsh script: one _arguments function per command (its options with their descriptions, its
// positionals, and a dispatch to its subcommands), in the manner of zsh's own completions.
#include <fmt/format.h>

#include <cctype>

#include "cli/completion.h"

namespace epure::cli {

namespace {

// Text inside an _arguments [description]: brackets escaped, on one line.
std::string bracketed(std::string_view s) {
  std::string d;
  for (char c : s) {
    if (c == '[' || c == ']' || c == '\\') d += '\\';
    d += c == '\n' ? ' ' : c;
  }
  return d;
}

// A name before the first colon of a _describe item or an _arguments message: colons escaped.
std::string colon_escaped(std::string_view s) {
  std::string e;
  for (char c : s) {
    if (c == ':' || c == '\\') e += '\\';
    e += c;
  }
  return e;
}

std::string function_name(const CommandDoc& c) {
  std::string name = "_epure_cmd";
  for (const auto& word : c.path) {
    name += '_';
    for (char ch : word) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  }
  return name;
}

std::string lower(std::string_view s) {
  std::string l;
  for (char c : s) l += c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return l;
}

class Writer {
 public:
  std::string functions;

  void add(const CommandDoc& c) {
    std::vector<std::string> specs;
    for (const auto& o : c.options) {
      std::string exclusions = "(";
      for (const auto& name : o.names) exclusions += (exclusions.size() > 1 ? " " : "") + name;
      for (const auto& name : o.excludes) exclusions += " " + name;
      exclusions += ")";
      // --help and --version end the command line: nothing else after them
      const bool terminal = o.main_name() == "--help" || o.main_name() == "--version";
      if (terminal) exclusions = "(- *)";
      for (const auto& name : o.names) {
        std::string spec = exclusions + name;
        if (o.takes_value) spec += name.starts_with("--") ? "=" : "+";
        spec += "[" + bracketed(o.description) + "]";
        if (o.takes_value) spec += ":" + colon_escaped(lower(o.value.placeholder)) + ":" + action(o.value);
        specs.push_back(single_quoted(spec));
      }
    }
    for (std::size_t i = 0; i < c.positionals.size(); ++i) {
      const OptionDoc& p = c.positionals[i];
      const std::string message = colon_escaped(lower(p.value.placeholder));
      if (p.repeats)
        specs.push_back(single_quoted(fmt::format("*:{}:{}", message, action(p.value))));
      else
        specs.push_back(single_quoted(fmt::format("{}:{}{}:{}", i + 1, p.required ? "" : ":", message, action(p.value))));
    }
    std::string body;
    if (c.subcommands.empty()) {
      body = "  _arguments -s -S : \\\n";
      for (const auto& s : specs) body += "    " + s + " \\\n";
      body.resize(body.size() - 3);  // the last " \\\n"
      body += "\n";
    } else {
      body = "  local curcontext=$curcontext state state_descr line ret=1\n  typeset -A opt_args\n";
      body += "  _arguments -C -s -S : \\\n";
      for (const auto& s : specs) body += "    " + s + " \\\n";
      body += "    '1: :->command' \\\n    '*:: :->argument' && ret=0\n";
      body += "  case $state in\n    (command)\n      local -a commands=(\n";
      for (const auto& sub : c.subcommands)
        body += "        " + single_quoted(colon_escaped(sub.path.back()) + ":" + sub.description) + "\n";
      body += fmt::format("      )\n      _describe -t commands {} commands && ret=0\n      ;;\n",
                          single_quoted(c.command_line() + " command"));
      body += fmt::format("    (argument)\n      curcontext=${{curcontext%:*:*}}:{}-$words[1]:\n      case $words[1] in\n",
                          c.page_name());
      for (const auto& sub : c.subcommands)
        body += fmt::format("        ({}) {} && ret=0 ;;\n", sub.path.back(), function_name(sub));
      body += "      esac\n      ;;\n  esac\n  return ret\n";
    }
    functions += fmt::format("{}() {{\n{}}}\n\n", function_name(c), body);
    for (const auto& sub : c.subcommands) add(sub);
  }

 private:
  int values_ = 0;

  // The completion of a value: a function of its own when it has choices (read from an array,
  // so that a choice may hold a colon: builtin:3d).
  std::string action(const ValueDoc& v) {
    if (v.choices.empty()) return v.directory ? "_files -/" : v.file ? "_files" : " ";
    const std::string name = fmt::format("_epure_value_{}", ++values_);
    std::string choices;
    for (const auto& c : v.choices) choices += " " + single_quoted(c);
    std::string body = fmt::format("  local -a choices=({})\n", choices.substr(1));
    if (!v.separator.empty())  // a list in one word: --format svg,pdf
      body += fmt::format("  _values -s {} value $choices\n", single_quoted(v.separator));
    else if (v.file)
      body += "  _alternative 'choices:choice:compadd -a choices' 'files:file:_files'\n";
    else
      body += "  compadd -a choices\n";
    functions += fmt::format("{}() {{\n{}}}\n\n", name, body);
    return name;
  }
};

}  // namespace

std::string zsh_completion(const CommandDoc& root, std::string_view version) {
  Writer w;
  w.add(root);
  return fmt::format(
      "#compdef epure\n"
      "# zsh completion for epure {}: written by `epure completion zsh` from the options the program\n"
      "# parses; do not edit. Installed as _epure in a directory of $fpath, or for this shell only\n"
      "# (after compinit):\n"
      "#   source <(epure completion zsh)\n"
      "\n"
      "{}"
      "_epure() {{\n  {} \"$@\"\n}}\n\n"
      "# autoloaded from $fpath: complete now; sourced: register\n"
      "if [[ $funcstack[1] == _epure ]]; then\n  _epure \"$@\"\nelse\n  compdef _epure epure\nfi\n",
      version, w.functions, function_name(root));
}

}  // namespace epure::cli
