#include "cli/command_tree.h"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace epure::cli {

namespace {

std::string trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

std::vector<std::string> split(std::string_view s, std::string_view separator) {
  std::vector<std::string> parts;
  for (;;) {
    const auto at = s.find(separator);
    parts.emplace_back(s.substr(0, at));
    if (at == std::string_view::npos) return parts;
    s.remove_prefix(at + separator.size());
  }
}

std::string upper(std::string_view s) {
  std::string u;
  for (char c : s) u += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

// The names CLI11 gives a value by its C++ type: not worth a synopsis of their own.
bool generic_type(std::string_view type) {
  for (std::string_view t : {"", "TEXT", "INT", "UINT", "FLOAT", "NUMBER", "BOOLEAN", "CHAR", "ENUM", "COMPLEX"})
    if (type == t) return true;
  return false;
}

// One alternative of a check's description, as CLI11 writes them: "{a,b}" (IsMember; "{a->x}"
// for a map), "FILE", "DIR", "PATH(existing)", "INT in [1 - 32768]".
void read_check(std::string_view description, ValueDoc& value) {
  std::string d = trim(description);
  while (d.size() >= 2 && d.front() == '(' && d.back() == ')') d = trim(std::string_view(d).substr(1, d.size() - 2));
  if (d.size() >= 2 && d.front() == '{' && d.back() == '}') {
    // The items are joined by ',' with nothing escaped: a choice that is a comma itself (grade's
    // --delimiter) leaves two empty items side by side, read back as ','. (A choice holding a
    // comma among other characters cannot be told from two: such a check is better a list,
    // delimiter(','), as --format is.)
    const auto items = split(std::string_view(d).substr(1, d.size() - 2), ",");
    for (std::size_t i = 0; i < items.size(); ++i) {
      std::string name = trim(items[i]);
      if (name.empty() && i + 1 < items.size() && trim(items[i + 1]).empty()) {
        name = ",";
        ++i;
      }
      if (const auto arrow = name.find("->"); arrow != std::string::npos) name = trim(std::string_view(name).substr(0, arrow));
      if (!name.empty() && std::find(value.choices.begin(), value.choices.end(), name) == value.choices.end())
        value.choices.push_back(name);
    }
  } else if (d == "FILE" || d.starts_with("PATH")) {
    value.file = true;
  } else if (d == "DIR") {
    value.directory = true;
  } else if (const auto in = d.find(" in ["); in != std::string::npos && d.back() == ']') {
    const std::string bounds = d.substr(in + 5, d.size() - in - 6);
    const auto parts = split(bounds, " - ");
    value.range = parts.size() == 2 ? trim(parts[0]) + " to " + trim(parts[1]) : bounds;
  }
}

OptionDoc describe_option(CLI::Option& option) {
  OptionDoc doc;
  for (const auto& s : option.get_snames()) doc.names.push_back("-" + s);
  for (const auto& l : option.get_lnames()) doc.names.push_back("--" + l);
  if (!option.nonpositional()) doc.positional = option.get_name(true);
  doc.description = option.get_description();
  doc.default_value = option.get_default_str();
  doc.takes_value = option.get_items_expected_max() > 0;
  doc.required = option.get_required();
  doc.repeats = !option.nonpositional() && option.get_items_expected_max() > 1;
  for (const CLI::Option* other : option.get_excludes()) {
    const auto& l = other->get_lnames();
    doc.excludes.push_back(l.empty() ? other->get_name() : "--" + l.front());
  }
  std::sort(doc.excludes.begin(), doc.excludes.end());
  doc.environment = option.get_envname();
  if (!doc.takes_value) return doc;

  ValueDoc& value = doc.value;
  if (option.get_delimiter() != '\0') value.separator = std::string(1, option.get_delimiter());
  // a list's default as CLI11 writes it, "[svg,pdf]": as it is typed
  const auto& d = doc.default_value;
  if (option.get_items_expected_max() > 1 && d.size() >= 2 && d.front() == '[' && d.back() == ']')
    doc.default_value = d.substr(1, d.size() - 2);
  for (int i = 0;; ++i) {
    const CLI::Validator* check = nullptr;
    try {
      check = option.get_validator(i);
    } catch (const CLI::OptionNotFound&) {
      break;  // CLI11 counts them for nobody: the first index past the end says it
    }
    for (const auto& alternative : split(check->get_description(), " OR ")) read_check(alternative, value);
  }
  const std::string full_type = option.get_type_name();
  const std::string type = full_type.substr(0, full_type.find(':'));
  value.number = value.choices.empty() && (type == "INT" || type == "UINT" || type == "FLOAT" || type == "NUMBER");
  const bool checked_file = value.file;
  // a free text is a path as far as a shell can tell (an output file or directory)
  if (value.choices.empty() && !value.number && !value.directory) value.file = true;
  if (!generic_type(type)) {
    value.placeholder = type;
  } else if (!doc.positional.empty()) {
    value.placeholder = upper(doc.positional);
  } else if (value.choices.empty() && checked_file) {
    value.placeholder = "FILE";
  } else if (value.choices.empty() && value.directory) {
    value.placeholder = "DIR";
  } else {
    value.placeholder = upper(doc.main_name().substr(doc.main_name().find_first_not_of('-')));
  }
  return doc;
}

void add_options(CLI::App& app, CommandDoc& doc) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_group().empty()) continue;  // hidden
    OptionDoc o = describe_option(*option);
    (o.positional.empty() ? doc.options : doc.positionals).push_back(std::move(o));
  }
}

CommandDoc describe(CLI::App& app, std::vector<std::string> path) {
  CommandDoc doc;
  doc.path = std::move(path);
  doc.description = app.get_description();
  doc.footer = trim(app.get_footer());
  doc.needs_subcommand = app.get_require_subcommand_min() > 0;
  add_options(app, doc);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_name().empty()) {
      add_options(*sub, doc);  // an option group: its options are the command's
      continue;
    }
    if (sub->get_group().empty()) continue;  // hidden
    auto sub_path = doc.path;
    sub_path.push_back(sub->get_name());
    doc.subcommands.push_back(describe(*sub, std::move(sub_path)));
  }
  return doc;
}

std::string join(const std::vector<std::string>& parts, std::string_view separator) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : std::string(separator)) + p;
  return s;
}

}  // namespace

std::string OptionDoc::main_name() const {
  if (!positional.empty()) return positional;
  for (const auto& n : names)
    if (n.starts_with("--")) return n;
  return names.empty() ? std::string() : names.front();
}

std::string CommandDoc::command_line() const { return join(path, " "); }
std::string CommandDoc::page_name() const { return join(path, "-"); }

CommandDoc describe_commands(CLI::App& app) { return describe(app, {app.get_name().empty() ? "epure" : app.get_name()}); }

}  // namespace epure::cli
