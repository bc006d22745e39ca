#include "scan/layout_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

namespace epure::scan {

namespace {

using nlohmann::json;

struct Reader {
  const std::string& source;
  std::string where;  // "sheet X, page 2, field 2.t"

  [[noreturn]] void fail(std::string_view what) const {
    throw LayoutError(where.empty() ? fmt::format("{}: {}", source, what) : fmt::format("{}: {}: {}", source, where, what));
  }
  const json& member(const json& o, const char* name) const {
    auto it = o.find(name);
    if (it == o.end()) fail(fmt::format("'{}' is missing", name));
    return *it;
  }
  double number(const json& o, const char* name, double lo, double hi) const {
    const json& v = member(o, name);
    if (!v.is_number()) fail(fmt::format("'{}' must be a number", name));
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi) fail(fmt::format("'{}' must be from {} to {}", name, lo, hi));
    return d;
  }
  std::string text(const json& o, const char* name) const {
    const json& v = member(o, name);
    if (!v.is_string()) fail(fmt::format("'{}' must be a string", name));
    return v.get<std::string>();
  }
  // [x, y, width, height] within a page of the given size
  Rect rect(const json& v, double w, double h, const char* what) const {
    if (!v.is_array() || v.size() != 4) fail(fmt::format("{} must be [x, y, width, height]", what));
    double d[4];
    for (int i = 0; i < 4; ++i) {
      if (!v[static_cast<std::size_t>(i)].is_number()) fail(fmt::format("{} must hold numbers", what));
      d[i] = v[static_cast<std::size_t>(i)].get<double>();
      if (!std::isfinite(d[i])) fail(fmt::format("{} must hold finite numbers", what));
    }
    if (d[2] <= 0 || d[3] <= 0 || d[0] < 0 || d[1] < 0 || d[0] + d[2] > w + 1e-6 || d[1] + d[3] > h + 1e-6)
      fail(fmt::format("{} [{}, {}, {}, {}] is not a rectangle on the page", what, d[0], d[1], d[2], d[3]));
    return {d[0], d[1], d[2], d[3]};
  }
};

FieldLayout read_field(Reader& r, const json& f, double w, double h) {
  if (!f.is_object()) r.fail("a field must be an object");
  FieldLayout out;
  out.question = r.text(f, "question");
  if (out.question.empty() || out.question.size() > 64) r.fail("'question' must be 1 to 64 characters");
  r.where += fmt::format(", field {}", out.question);
  const std::string type = r.text(f, "type");
  if (type == "comb") out.type = FieldType::comb;
  else if (type == "tick") out.type = FieldType::tick;
  else r.fail(fmt::format("'type' must be \"comb\" or \"tick\", not \"{}\"", type));
  const json& cells = r.member(f, "cells");
  if (!cells.is_array() || cells.empty() || cells.size() > kMaxCellsPerField)
    r.fail(fmt::format("'cells' must be a list of 1 to {} rectangles", kMaxCellsPerField));
  for (const auto& c : cells) out.cells.push_back(r.rect(c, w, h, "a cell"));
  if (out.type == FieldType::comb) {
    if (auto it = f.find("sign"); it != f.end()) {
      if (!it->is_boolean()) r.fail("'sign' must be true or false");
      out.sign = it->get<bool>();
    }
    if (f.contains("decimals")) {
      const double d = r.number(f, "decimals", 0, 16);
      if (d != std::floor(d)) r.fail("'decimals' must be a whole number");
      out.decimals = static_cast<int>(d);
    }
    if (static_cast<std::size_t>(out.decimals + (out.sign ? 1 : 0)) + 1 > out.cells.size())
      r.fail("the sign and decimal cells leave no cell for the integer part");
  } else {
    const json& values = r.member(f, "values");
    if (!values.is_array() || values.size() != out.cells.size()) r.fail("'values' must give one answer per cell");
    for (const auto& v : values) {
      if (!v.is_string() || v.get<std::string>().empty()) r.fail("'values' must be non-empty strings");
      out.values.push_back(v.get<std::string>());
    }
    if (auto it = f.find("select"); it != f.end()) {
      if (*it == "one") out.multiple = false;
      else if (*it == "any") out.multiple = true;
      else r.fail("'select' must be \"one\" or \"any\"");
    }
  }
  return out;
}

PageLayout read_page(Reader& r, const json& p, const std::string& sheet_where) {
  if (!p.is_object()) r.fail("a page must be an object");
  PageLayout out;
  out.page = static_cast<int>(r.number(p, "page", 1, static_cast<double>(kMaxPagesPerSheet)));
  r.where = fmt::format("{}, page {}", sheet_where, out.page);
  out.width = r.number(p, "width", 72, 14400);
  out.height = r.number(p, "height", 72, 14400);
  const json& marks = r.member(p, "marks");
  if (!marks.is_array() || marks.size() != 4) r.fail("'marks' must be four [x, y] centres");
  for (std::size_t i = 0; i < 4; ++i) {
    const json& m = marks[i];
    if (!m.is_array() || m.size() != 2 || !m[0].is_number() || !m[1].is_number()) r.fail("a mark must be [x, y]");
    const double x = m[0].get<double>(), y = m[1].get<double>();
    if (!(x >= 0 && x <= out.width && y >= 0 && y <= out.height)) r.fail("a mark lies off the page");
    out.marks[i] = {x, y};
  }
  out.mark_size = r.number(p, "mark_size", 2, 72);
  out.code = r.rect(r.member(p, "code"), out.width, out.height, "'code'");
  const json& fields = r.member(p, "fields");
  if (!fields.is_array()) r.fail("'fields' must be a list");
  const std::string page_where = r.where;
  for (const auto& f : fields) {
    out.fields.push_back(read_field(r, f, out.width, out.height));
    r.where = page_where;
  }
  return out;
}

}  // namespace

SetLayout read_layout(std::string_view text, const std::string& source) {
  if (text.size() > kMaxLayoutBytes)
    throw LayoutError(fmt::format("{}: {} bytes: a layout.json holds at most {}", source, text.size(), kMaxLayoutBytes));
  auto depth_check = [&](int depth, json::parse_event_t event, json&) {
    if (depth > kMaxLayoutDepth && (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start))
      throw LayoutError(fmt::format("{}: nested deeper than {} levels: not a layout.json", source, kMaxLayoutDepth));
    return true;
  };
  json root;
  try {
    root = json::parse(text.begin(), text.end(), depth_check);
  } catch (const json::exception& e) {
    throw LayoutError(fmt::format("{}: not JSON: {}", source, e.what()));
  }
  Reader r{source, {}};
  // json::value() throws its own type_error when the member is of another type: compare in place
  const auto format = root.is_object() ? root.find("format") : root.end();
  if (!root.is_object() || format == root.end() || *format != "epure-layout")
    r.fail("not a layout.json (\"format\": \"epure-layout\" is missing)");
  if (!root.contains("version") || root["version"] != 1)
    r.fail("a layout.json of another version: this epure reads version 1");
  SetLayout out;
  if (root.contains("title") && root["title"].is_string()) out.title = root["title"].get<std::string>();
  out.language = r.text(root, "language");
  out.decimal_separator = r.text(root, "decimal_separator");
  if (out.decimal_separator != "." && out.decimal_separator != ",") r.fail("'decimal_separator' must be \".\" or \",\"");
  out.seed = static_cast<std::uint64_t>(r.number(root, "seed", 0, 34359738367.0));
  out.draw_version = static_cast<int>(r.number(root, "draw_version", 0, 31));
  const json& sheets = r.member(root, "sheets");
  if (!sheets.is_array()) r.fail("'sheets' must be a list");
  for (const auto& s : sheets) {
    r.where.clear();
    if (!s.is_object()) r.fail("a sheet must be an object");
    SheetLayout sheet;
    sheet.sheet = r.text(s, "sheet");
    const std::string where = fmt::format("sheet {}", sheet.sheet);
    r.where = where;
    if (auto it = s.find("student"); it != s.end() && !it->is_null()) {
      if (!it->is_object()) r.fail("'student' must be an object");
      sheet.student = StudentLayout{r.text(*it, "number"), it->contains("name") ? r.text(*it, "name") : ""};
    }
    const json& pages = r.member(s, "pages");
    if (!pages.is_array() || pages.empty() || pages.size() > kMaxPagesPerSheet)
      r.fail(fmt::format("'pages' must be a list of 1 to {} pages", kMaxPagesPerSheet));
    for (const auto& p : pages) {
      sheet.pages.push_back(read_page(r, p, where));
      if (sheet.pages.back().page != static_cast<int>(sheet.pages.size())) r.fail("pages must be numbered 1, 2, … in order");
    }
    if (out.sheets.count(sheet.sheet)) r.fail("this sheet is listed twice");
    out.sheets.emplace(sheet.sheet, std::move(sheet));
  }
  return out;
}

SetLayout read_layout_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LayoutError(fmt::format("{}: cannot be read", path));
  std::ostringstream ss;
  ss << in.rdbuf();
  return read_layout(ss.str(), path);
}

std::string layout_json_begin(const SetLayout& layout) {
  json root = {{"format", "epure-layout"}, {"version", 1}, {"title", layout.title}, {"language", layout.language},
               {"decimal_separator", layout.decimal_separator}, {"seed", layout.seed},
               {"draw_version", layout.draw_version}};
  std::string head = root.dump(1);
  head.erase(head.rfind('\n'));  // the closing brace: the sheets follow
  return head + ",\n \"sheets\": [\n";
}

std::string layout_json_sheet(const SheetLayout& s, bool first) {
  auto rect = [](const Rect& r) { return json::array({r.x, r.y, r.width, r.height}); };
  json pages = json::array();
  for (const auto& p : s.pages) {
    json fields = json::array();
    for (const auto& f : p.fields) {
      json cells = json::array();
      for (const auto& c : f.cells) cells.push_back(rect(c));
      json o = {{"question", f.question}, {"type", f.type == FieldType::comb ? "comb" : "tick"}, {"cells", cells}};
      if (f.type == FieldType::comb) {
        o["sign"] = f.sign;
        o["decimals"] = f.decimals;
      } else {
        o["values"] = f.values;
        o["select"] = f.multiple ? "any" : "one";
      }
      fields.push_back(std::move(o));
    }
    json marks = json::array();
    for (const auto& m : p.marks) marks.push_back(json::array({m.x, m.y}));
    pages.push_back({{"page", p.page}, {"width", p.width}, {"height", p.height}, {"marks", marks},
                     {"mark_size", p.mark_size}, {"code", rect(p.code)}, {"fields", fields}});
  }
  json sheet = {{"sheet", s.sheet}, {"pages", pages}};
  if (s.student) sheet["student"] = {{"number", s.student->number}, {"name", s.student->name}};
  return (first ? "" : ",\n") + sheet.dump(1);
}

std::string layout_json_end() { return "\n]}\n"; }

std::string layout_json(const SetLayout& layout) {
  std::string out = layout_json_begin(layout);
  bool first = true;
  for (const auto& [id, s] : layout.sheets) {
    SheetLayout named = s;
    named.sheet = id;
    out += layout_json_sheet(named, std::exchange(first, false));
  }
  return out + layout_json_end();
}

}  // namespace epure::scan
