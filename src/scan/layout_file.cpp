#include "scan/layout_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <fstream>
#include <memory>
#include <sstream>
#include <utility>

#include "support/portable.h"

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

namespace {

// A number's text as nlohmann writes it, remembered in a slot chosen by the number's bits (a
// thread's table, 4,096 slots: a later number of the same slot takes it over).
struct NumberText {
  bool used = false;
  unsigned char length = 0;
  std::uint64_t bits = 0;
  char text[30];
};
// nlohmann's to_chars writes at most 24 bytes for a double (a sign, 17 digits, the point, the
// exponent's 'e', sign and three digits): every finite number's text fits its slot.
static_assert(sizeof NumberText::text >= 24);
NumberText& number_slot(std::uint64_t bits) {
  // On the heap, made at a thread's first number: a thread_local array (192 KB) would be part of
  // the executable's static TLS block, which every thread the process creates gets zeroed.
  using Slots = std::array<NumberText, 4096>;
  thread_local std::unique_ptr<Slots> slots;
  if (!slots) slots = std::make_unique<Slots>();
  return (*slots)[static_cast<std::size_t>((bits * 0x9e3779b97f4a7c15ULL) >> 52)];
}

// A sheet's JSON written straight into a string, byte for byte as nlohmann's dump(1) writes the
// same value (the file's bytes do not change), without building the tree: `epure generate`
// writes one per sheet, and building and dumping nlohmann's tree of maps cost 9 % of an SVG set's
// CPU (bench/README.md, "Pages"). dump(1) puts every member and element on a line of its own,
// indented one space a level, an empty list as `[]`; an object's members come in nlohmann's
// order, its keys sorted, so callers give them sorted. Numbers go through nlohmann's own double
// formatting (Grisu2, `12.0` for an integral value), which is not always the shortest fmt
// would write; strings that need escaping go through nlohmann itself.

class Dump1 {
 public:
  explicit Dump1(std::string& out) : out_(out) {}

  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  // the next value is this member's
  void key(std::string_view k) {
    item();
    string_text(k);
    out_ += ": ";
    keyed_ = true;
  }
  void value(double d) {
    item();
    if (!std::isfinite(d)) {
      out_ += "null";
      return;
    }
    // A set's layout repeats its numbers (the cells' columns, sizes, the code's place): on 100
    // sheets 101,303 numbers, 1,637 distinct. Grisu2's text of each is remembered by its bits.
    const auto bits = portable::bit_cast<std::uint64_t>(d);
    NumberText& slot = number_slot(bits);
    if (!slot.used || slot.bits != bits) {
      std::array<char, 64> buf;  // nlohmann's own number buffer's size
      char* end = nlohmann::detail::to_chars(buf.data(), buf.data() + buf.size(), d);
      const auto length = static_cast<std::size_t>(end - buf.data());
      if (length > sizeof slot.text) {  // never taken (the static_assert above): a guard, should
        out_.append(buf.data(), length);  // nlohmann's format ever grow
        return;
      }
      slot.used = true;
      slot.bits = bits;
      slot.length = static_cast<unsigned char>(length);
      std::memcpy(slot.text, buf.data(), length);
    }
    out_.append(slot.text, slot.length);
  }
  void value(int n) {
    item();
    fmt::format_to(std::back_inserter(out_), "{}", n);
  }
  void value(bool b) {
    item();
    out_ += b ? "true" : "false";
  }
  void value(std::string_view s) {
    item();
    string_text(s);
  }
  void value(const char* s) { value(std::string_view(s)); }

 private:
  // before a value: a member's value follows its key; an element starts a line of its own
  void item() {
    if (std::exchange(keyed_, false) || open_.empty()) return;
    if (open_.back()) open_.back() = false;
    else out_ += ',';
    out_ += '\n';
    out_.append(open_.size(), ' ');
  }
  void open(char c) {
    item();
    out_ += c;
    open_.push_back(true);
  }
  void close(char c) {
    const bool empty = open_.back();
    open_.pop_back();
    if (!empty) {
      out_ += '\n';
      out_.append(open_.size(), ' ');
    }
    out_ += c;
  }
  void string_text(std::string_view s) {
    // printable ASCII without a quote or backslash is written as it is; the rest (controls,
    // UTF-8, whose validity nlohmann checks) as nlohmann escapes it
    const bool plain = std::all_of(s.begin(), s.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return u >= 0x20 && u < 0x80 && c != '"' && c != '\\';
    });
    if (plain) {
      out_ += '"';
      out_ += s;
      out_ += '"';
    } else {
      out_ += json(std::string(s)).dump();
    }
  }

  std::string& out_;
  std::vector<bool> open_;  // per open object or list: nothing written in it yet
  bool keyed_ = false;
};

void put_rect(Dump1& d, const Rect& r) {
  d.begin_array();
  for (double v : {r.x, r.y, r.width, r.height}) d.value(v);
  d.end_array();
}

}  // namespace

std::string layout_json_sheet(const SheetLayout& s, bool first) {
  std::string out = first ? "" : ",\n";
  Dump1 d(out);
  // keys in sorted order throughout (Dump1)
  d.begin_object();
  d.key("pages");
  d.begin_array();
  for (const auto& p : s.pages) {
    d.begin_object();
    d.key("code");
    put_rect(d, p.code);
    d.key("fields");
    d.begin_array();
    for (const auto& f : p.fields) {
      d.begin_object();
      d.key("cells");
      d.begin_array();
      for (const auto& c : f.cells) put_rect(d, c);
      d.end_array();
      if (f.type == FieldType::comb) {
        d.key("decimals");
        d.value(f.decimals);
        d.key("question");
        d.value(f.question);
        d.key("sign");
        d.value(f.sign);
        d.key("type");
        d.value("comb");
      } else {
        d.key("question");
        d.value(f.question);
        d.key("select");
        d.value(f.multiple ? "any" : "one");
        d.key("type");
        d.value("tick");
        d.key("values");
        d.begin_array();
        for (const auto& v : f.values) d.value(v);
        d.end_array();
      }
      d.end_object();
    }
    d.end_array();
    d.key("height");
    d.value(p.height);
    d.key("mark_size");
    d.value(p.mark_size);
    d.key("marks");
    d.begin_array();
    for (const auto& m : p.marks) {
      d.begin_array();
      d.value(m.x);
      d.value(m.y);
      d.end_array();
    }
    d.end_array();
    d.key("page");
    d.value(p.page);
    d.key("width");
    d.value(p.width);
    d.end_object();
  }
  d.end_array();
  d.key("sheet");
  d.value(s.sheet);
  if (s.student) {
    d.key("student");
    d.begin_object();
    d.key("name");
    d.value(s.student->name);
    d.key("number");
    d.value(s.student->number);
    d.end_object();
  }
  d.end_object();
  return out;
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
