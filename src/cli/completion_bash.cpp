// The bash script: the command tree as four associative arrays (a command's subcommands and
// options, what an option's or a positional's value is, its choices), and one fixed function that
// walks the words typed so far through them. Needs bash 4.3; works with or without the
// bash-completion package, and under set -u.
#include <fmt/format.h>

#include <cctype>

#include "cli/completion.h"

namespace epure::cli {

std::string single_quoted(std::string_view s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

namespace {

// A word as the shell reads it back (compgen -W expands its list): a backslash before each
// character the shell would take otherwise (--delimiter's ';').
std::string escaped(std::string_view word) {
  std::string e;
  for (char c : word) {
    const bool plain = static_cast<unsigned char>(c) >= 0x80 || std::isalnum(static_cast<unsigned char>(c)) ||
                       std::string_view("_./:@%+=-").find(c) != std::string_view::npos;
    if (!plain) e += '\\';
    e += c;
  }
  return e;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

// What a value is, in the script's words: file, dir, choices, file+choices, or none (a number).
std::string value_kind(const ValueDoc& v) {
  if (!v.choices.empty()) return v.file ? "file+choices" : "choices";
  if (v.directory) return "dir";
  if (v.file) return "file";
  return "none";
}

struct Tables {
  std::string subcommands, options, values, choices, separators;

  void value(const std::string& key, const ValueDoc& v) {
    values += fmt::format("  [{}]={}\n", single_quoted(key), value_kind(v));
    if (!v.separator.empty()) separators += fmt::format("  [{}]={}\n", single_quoted(key), single_quoted(v.separator));
    if (v.choices.empty()) return;
    std::vector<std::string> words;
    for (const auto& c : v.choices) words.push_back(escaped(c));
    choices += fmt::format("  [{}]={}\n", single_quoted(key), single_quoted(joined(words)));
  }

  void add(const CommandDoc& c) {
    const std::string path = c.command_line();
    if (!c.subcommands.empty()) {
      std::vector<std::string> names;
      for (const auto& sub : c.subcommands) names.push_back(sub.path.back());
      subcommands += fmt::format("  [{}]={}\n", single_quoted(path), single_quoted(joined(names)));
    }
    std::vector<std::string> names;
    for (const auto& o : c.options) {
      for (const auto& name : o.names) {
        names.push_back(name);
        if (o.takes_value) value(path + " " + name, o.value);
      }
    }
    options += fmt::format("  [{}]={}\n", single_quoted(path), single_quoted(joined(names)));
    for (std::size_t i = 0; i < c.positionals.size(); ++i) {
      const OptionDoc& p = c.positionals[i];
      value(fmt::format("{} #{}", path, i), p.value);
      if (p.repeats) value(path + " #+", p.value);
    }
    for (const auto& sub : c.subcommands) add(sub);
  }
};

// The walk: which command the words name, whether the word under the cursor is an option's
// value, a positional or an option, and the candidates for it.
constexpr std::string_view kFunctions = R"BASH(
# COMP_WORDS as typed: bash splits a word at ':' and '=' (COMP_WORDBREAKS), so that
# --spec=builtin:3d arrives as five words; they are glued back where the line has no blank.
_epure_words() {
  local i w rest blanks line=${COMP_LINE:0:COMP_POINT} pos=0
  words=() cword=0
  for ((i = 0; i < ${#COMP_WORDS[@]}; i++)); do
    w=${COMP_WORDS[i]}
    rest=${line:pos}
    blanks=${rest%%[![:space:]]*}
    pos=$((pos + ${#blanks} + ${#w}))
    if ((i > 0)) && [[ -z $blanks && ( $w == [:=]* || ${words[-1]} == *[:=] ) ]]; then
      words[-1]+=$w
    else
      words+=("$w")
    fi
    if ((i == COMP_CWORD)); then
      cword=$((${#words[@]} - 1))
      return
    fi
  done
  words+=("") cword=$((${#words[@]} - 1))
}

# The candidates for the value $2 of the option or positional $1 (a key of _epure_values).
_epure_value() {
  local kind=${_epure_values[$1]-} typed=$2 line list="" separator=${_epure_separators[$1]-}
  # a list in one word (--format svg,pdf): the item after the last separator is completed
  if [[ -n $separator && $typed == *"$separator"* ]]; then
    list=${typed%"$separator"*}$separator
    typed=${typed##*"$separator"}
  fi
  case $kind in
    *choices*)
      # quoted as they are to be typed (printf %q: --delimiter ';' as \;)
      while IFS= read -r line; do
        printf -v line %q "$line"
        COMPREPLY+=("$line")
      done < <(compgen -W "${_epure_choices[$1]-}" -- "$typed")
      ;;
  esac
  case $kind in
    file*)
      while IFS= read -r line; do COMPREPLY+=("$line"); done < <(compgen -f -- "$typed")
      compopt -o filenames 2>/dev/null
      ;;
    dir)
      while IFS= read -r line; do COMPREPLY+=("$line"); done < <(compgen -d -- "$typed")
      compopt -o filenames 2>/dev/null
      ;;
  esac
  local i
  if [[ -n $list ]]; then  # the items not given yet, after those given
    for i in "${!COMPREPLY[@]}"; do
      if [[ $separator$list == *"$separator${COMPREPLY[i]}$separator"* ]]; then
        unset 'COMPREPLY[i]'
      else
        COMPREPLY[i]=$list${COMPREPLY[i]}
      fi
    done
    COMPREPLY=("${COMPREPLY[@]}")
    typed=$list$typed
  fi
  # bash replaces only what follows the last ':' or '=' of the word: the candidates lose the rest
  local breaks=${COMP_WORDBREAKS//[^:=]/}
  if [[ -n $breaks && $typed == *[$breaks]* ]]; then
    local head=${typed%"${typed##*[$breaks]}"}
    for i in "${!COMPREPLY[@]}"; do COMPREPLY[i]=${COMPREPLY[i]#"$head"}; done
  fi
}

_epure() {
  local words cword cur path=epure i word positional=0 key
  COMPREPLY=()
  _epure_words
  cur=${words[cword]}
  for ((i = 1; i < cword; i++)); do
    word=${words[i]}
    if [[ $word == -?* ]]; then
      # an option: skip its value unless it was given as --option=value
      [[ $word != *=* && -n ${_epure_values["$path $word"]+set} ]] && ((i++))
    elif ((positional == 0)) && [[ " ${_epure_subcommands[$path]-} " == *" $word "* ]]; then
      path+=" $word"
    else
      ((positional++))
    fi
  done
  if [[ $cur == -*=* ]]; then
    key="$path ${cur%%=*}"
    [[ -n ${_epure_values[$key]+set} ]] && _epure_value "$key" "${cur#*=}"
    return 0
  fi
  if ((cword > 1)) && [[ ${words[cword - 1]} == -?* && ${words[cword - 1]} != *=* ]]; then
    key="$path ${words[cword - 1]}"
    if [[ -n ${_epure_values[$key]+set} ]]; then
      _epure_value "$key" "$cur"
      return 0
    fi
  fi
  if [[ $cur != -* ]]; then
    if [[ -n ${_epure_subcommands[$path]+set} ]]; then
      COMPREPLY=($(compgen -W "${_epure_subcommands[$path]-}" -- "$cur"))
      return 0
    fi
    key="$path #$positional"
    [[ -z ${_epure_values[$key]+set} ]] && key="$path #+"
    if [[ -n ${_epure_values[$key]+set} ]]; then
      _epure_value "$key" "$cur"
      return 0
    fi
  fi
  COMPREPLY=($(compgen -W "${_epure_options[$path]-}" -- "$cur"))
  return 0
}

complete -F _epure epure
)BASH";

}  // namespace

std::string bash_completion(const CommandDoc& root, std::string_view version) {
  Tables t;
  t.add(root);
  return fmt::format(
      "# bash completion for epure {}: written by `epure completion bash` from the options the program\n"
      "# parses; do not edit. Installed as bash-completion/completions/epure, or for this shell only:\n"
      "#   source <(epure completion bash)\n"
      "\n"
      "# Each command (its words, joined by blanks): its subcommands and its options.\n"
      "declare -gA _epure_subcommands=(\n{})\n"
      "declare -gA _epure_options=(\n{})\n"
      "# What the value of an option (\"command --option\") or of a positional (\"command #index\",\n"
      "# \"command #+\" for one that repeats) is: file, dir, choices, file+choices or none (a number).\n"
      "declare -gA _epure_values=(\n{})\n"
      "declare -gA _epure_choices=(\n{})\n"
      "# The separator of a list given in one word (--format svg,pdf).\n"
      "declare -gA _epure_separators=(\n{})\n"
      "{}",
      version, t.subcommands, t.options, t.values, t.choices, t.separators, kFunctions);
}

}  // namespace epure::cli
