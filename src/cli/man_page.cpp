#include "cli/man_page.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace epure::cli {

namespace {

// The next code point of UTF-8 text at `i` (advanced past it); U+FFFD for a malformed byte.
char32_t next_code_point(std::string_view s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
  if (length == 0 || i + static_cast<std::size_t>(length) > s.size()) {
    ++i;
    return 0xFFFD;
  }
  char32_t c = length == 1 ? lead : lead & (0x7F >> length);
  for (int k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) {
      ++i;
      return 0xFFFD;
    }
    c = (c << 6) | (byte(i + k) & 0x3F);
  }
  i += static_cast<std::size_t>(length);
  return c;
}

// The typographic characters groff names, which it also renders in ASCII (a man page read in
// the C locale): the rest are written as \[uXXXX].
const char* typographic(char32_t c) {
  switch (c) {
    case U'\u2026': return "...";
    case U'\u2212': return "\\-";
    case U'\u2013': return "\\(en";
    case U'\u2014': return "\\(em";
    case U'\u2018': return "\\(oq";
    case U'\u2019': return "\\(cq";
    case U'\u201C': return "\\(lq";
    case U'\u201D': return "\\(rq";
    case U'\u00D7': return "\\(mu";
    case U'\u00A0': return "\\ ";
    default: return nullptr;
  }
}

// A name (a page's, an option's, a choice) with every dash as \-, where no line breaks.
std::string name_escape(std::string_view name) {
  std::string e;
  for (char c : roff_escape(name)) e += c == '-' && (e.empty() || e.back() != '\\') ? std::string("\\-") : std::string(1, c);
  return e;
}

// Bold option names, italic values: "\fB\-n\fR, \fB\-\-sheets\fR \fISHEETS\fR".
std::string option_heading(const OptionDoc& o) {
  if (!o.positional.empty()) return fmt::format("\\fI{}\\fR{}", roff_escape(o.value.placeholder), o.repeats ? " ..." : "");
  std::string heading;
  for (const auto& name : o.names) heading += (heading.empty() ? "" : ", ") + fmt::format("\\fB{}\\fR", name_escape(name));
  if (o.takes_value) heading += fmt::format(" \\fI{}\\fR", roff_escape(o.value.placeholder));
  return heading;
}

std::string sentence(std::string text) {
  while (!text.empty() && text.back() == ' ') text.pop_back();
  if (!text.empty() && text.back() != '.' && text.back() != ')' && text.back() != '!' && text.back() != '?') text += '.';
  if (!text.empty() && text.back() == ')') text += '.';
  return text;
}

// Choices or option names in bold, a comma between; one that is punctuation (grade's
// --delimiter ',') in quotes, to be told from the commas between.
std::string bold_list(const std::vector<std::string>& items) {
  std::string list;
  for (const auto& item : items) {
    const bool word = std::all_of(item.begin(), item.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == ':' || c == '.' || c == '/';
    });
    const std::string bold = fmt::format("\\fB{}\\fR", name_escape(item));
    list += (list.empty() ? "" : ", ") + (word ? bold : "\\(oq" + bold + "\\(cq");
  }
  return list;
}

// An option's paragraph: what it does, then what its value may be, its default, its limits.
std::string option_text(const OptionDoc& o) {
  std::string text = roff_escape(sentence(o.description)) + "\n";
  const ValueDoc& v = o.value;
  if (o.takes_value && !v.separator.empty())
    text += fmt::format("Several values separated by '{}'{}", roff_escape(v.separator),
                        v.choices.empty() ? ".\n" : ", each one of: " + bold_list(v.choices) + ".\n");
  else if (o.takes_value && !v.choices.empty())
    text += (v.file ? "A file, or one of: " : "One of: ") + bold_list(v.choices) + ".\n";
  if (!v.range.empty()) text += roff_escape(fmt::format("From {}.", v.range)) + "\n";
  if (!o.default_value.empty()) text += fmt::format("Default: \\fB{}\\fR.\n", roff_escape(o.default_value));
  if (o.required) text += "Required.\n";
  if (!o.excludes.empty()) text += "Not with " + bold_list(o.excludes) + ".\n";
  if (!o.environment.empty()) text += fmt::format("Also read from \\fB{}\\fR.\n", name_escape(o.environment));
  return text;
}

std::string page_reference(const CommandDoc& c) { return fmt::format("\\fB{}\\fR(1)", name_escape(c.page_name())); }

void add_all_pages(const CommandDoc& c, std::vector<const CommandDoc*>& all) {
  all.push_back(&c);
  for (const auto& sub : c.subcommands) add_all_pages(sub, all);
}

std::string synopsis(const CommandDoc& c) {
  std::string s = fmt::format(".B {}\n", roff_escape(c.command_line()));
  for (const auto& o : c.options)
    if (o.required) s += fmt::format("\\fB{}\\fR \\fI{}\\fR\n", name_escape(o.main_name()), roff_escape(o.value.placeholder));
  s += "[\\fIOPTIONS\\fR]\n";
  if (!c.subcommands.empty()) s += c.needs_subcommand ? "\\fICOMMAND\\fR [\\fIARGS\\fR]\n" : "[\\fICOMMAND\\fR [\\fIARGS\\fR]]\n";
  for (const auto& p : c.positionals)
    s += p.required ? option_heading(p) + "\n" : "[" + option_heading(p) + "]\n";
  return s;
}

// What every command shares, said once on epure(1).
constexpr std::string_view kRootSections = R"(.SH EXIT STATUS
.TP
.B 0
Everything asked was done.
.TP
.B 1
Some of it could not be done (a line that could not be solved, an answer that could not be read,
a file that could not be written): each is said on standard error with its file and line, and the
rest was done.
.TP
.B 2
Nothing was done: a usage error, a spec or key that cannot be read, or no input that could be used.
.SH ENVIRONMENT
.TP
.B SOURCE_DATE_EPOCH
The creation date written into PDF files, in seconds since 1970 (the reproducible-builds
convention). Without it the PDFs carry no date, so that the same spec and seed give the same bytes.
.SH FILES
The worksheet specs built into the program are listed by \fBepure generate \-\-help\fR; the
README (installed with the program's documentation, \fI/usr/share/doc/epure/README.md\fR on
Debian) describes the spec format, the answer spreadsheets and every output.
)";

std::string page(const CommandDoc& c, const CommandDoc& root, std::string_view version, int draw_version) {
  const bool is_root = c.path.size() == 1;
  // the root's description may name the program ("epure: randomised …"), as NAME does already
  std::string_view description = c.description;
  if (const std::string named = c.path.back() + ": "; description.starts_with(named)) description.remove_prefix(named.size());
  std::string title;
  for (char ch : c.page_name()) title += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  std::string r;
  r += fmt::format(".\\\" Written by `epure __docs` from the options epure {} parses; do not edit.\n", version);
  r += fmt::format(".TH {} 1 \"\" \"epure {}\" \"epure manual\"\n", name_escape(title), version);
  r += ".nh\n.ad l\n";  // no hyphen inside an option's name, no stretched spaces: text to copy from
  r += fmt::format(".SH NAME\n{} \\- {}\n", name_escape(c.page_name()), roff_escape(description));
  r += ".SH SYNOPSIS\n" + synopsis(c);
  std::string first = sentence(std::string(description));
  if (!first.empty()) first[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(first[0])));
  r += ".SH DESCRIPTION\n" + roff_escape(first) + "\n";
  if (!c.footer.empty()) r += ".PP\n" + roff_escape(c.footer) + "\n";
  if (is_root)
    r += fmt::format(
        ".PP\nThis is epure {}; its sheets are drawn by the generator's draw version {} (a sheet's id names "
        "the version it was drawn by, and a key is rebuilt only by the same version).\n",
        version, draw_version);
  if (!c.subcommands.empty()) {
    r += ".SH COMMANDS\n";
    for (const auto& sub : c.subcommands)
      r += fmt::format(".TP\n\\fB{}\\fR\n{} See {}.\n", roff_escape(sub.path.back()), roff_escape(sentence(sub.description)),
                       page_reference(sub));
  }
  if (!c.positionals.empty()) {
    r += ".SH ARGUMENTS\n";
    for (const auto& p : c.positionals) r += ".TP\n" + option_heading(p) + "\n" + option_text(p);
  }
  if (!c.options.empty()) {
    r += ".SH OPTIONS\n";
    for (const auto& o : c.options) r += ".TP\n" + option_heading(o) + "\n" + option_text(o);
  }
  if (is_root) r += kRootSections;
  // SEE ALSO: the root names every page; a subcommand its parent's, its own subcommands' and epure(1)
  std::vector<const CommandDoc*> see;
  if (is_root) {
    add_all_pages(root, see);
    see.erase(see.begin());
  } else {
    see.push_back(&root);
    if (c.path.size() > 2) {
      const CommandDoc* parent = &root;
      for (std::size_t i = 1; i + 1 < c.path.size(); ++i)
        for (const auto& sub : parent->subcommands)
          if (sub.path[i] == c.path[i]) {
            parent = &sub;
            break;
          }
      see.push_back(parent);
    }
    for (const auto& sub : c.subcommands) see.push_back(&sub);
  }
  if (!see.empty()) {
    std::string list;
    for (const CommandDoc* s : see) list += (list.empty() ? "" : ",\n") + page_reference(*s);
    r += ".SH SEE ALSO\n" + list + "\n";
  }
  return r;
}

}  // namespace

std::string roff_escape(std::string_view text) {
  std::string out;
  bool line_start = true;
  bool option_word = false;  // in a word that started with a dash (--follow-through): all its dashes are \-
  char previous = ' ';
  for (std::size_t i = 0; i < text.size();) {
    const char32_t c = next_code_point(text, i);
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    line_start = c == '\n';
    if (c < 0x80 && (std::isspace(static_cast<int>(c)) || c == ')' || c == ',' || c == '\'')) option_word = false;
    if (c == '\\') {
      out += "\\e";
    } else if (c == '-') {
      // an option's dashes (at a word's start, or after another dash) are minus signs, to be
      // copied and pasted; a dash inside a word ("double-sided") is a hyphen
      const bool word_start = std::isspace(static_cast<unsigned char>(previous)) || previous == '(' || previous == '\'' ||
                              previous == '`' || previous == '[' || previous == ',';
      option_word = option_word || word_start;
      out += option_word ? "\\-" : "-";
    } else if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (const char* named = typographic(c)) {
      out += named;
    } else {
      out += fmt::format("\\[u{:04X}]", static_cast<std::uint32_t>(c));
    }
    previous = c < 0x80 ? static_cast<char>(c) : 'x';
  }
  return out;
}

std::vector<ManPage> man_pages(const CommandDoc& root, std::string_view version, int draw_version) {
  std::vector<const CommandDoc*> all;
  add_all_pages(root, all);
  std::vector<ManPage> pages;
  for (const CommandDoc* c : all) pages.push_back({c->page_name(), page(*c, root, version, draw_version)});
  return pages;
}

}  // namespace epure::cli
