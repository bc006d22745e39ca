#include "grading/answer_source.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <unordered_map>

#include "grading/csv_reader.h"

namespace epure::grading {

namespace {

using nlohmann::json;

void read_csv(CsvReader& reader, RowHandler& handler, SourceInfo& info) {
  info.format = "csv";
  CsvRecord rec;
  bool header = true;
  while (reader.next(rec)) {
    if (header) {
      std::vector<std::string> names(rec.cells.begin(), rec.cells.end());
      handler.header(names, rec.line);
      reader.limit_cells(handler.cells_needed());
      header = false;
      continue;
    }
    ++info.rows;
    handler.row(AnswerRow{rec.line, rec.last_line, rec.cells, rec.problem});
  }
  info.delimiter = reader.delimiter();
  info.bom = reader.had_bom();
  info.crlf = reader.crlf();
  info.blank_lines = reader.blank_lines();
}

// JSON objects as rows: every name seen becomes a column (the header grows as names appear).
class JsonRows {
 public:
  JsonRows(RowHandler& handler, SourceInfo& info) : handler_(handler), info_(info) {}

  void object(const json& o, int line) {
    for (auto& c : cells_) c.clear();
    bool grew = false;
    std::string_view problem;
    if (!o.is_object()) {
      problem = "not_an_object";
    } else {
      dropped_ = false;
      for (const auto& [k, v] : o.items()) {
        if (k == "answers" && v.is_object()) {
          for (const auto& [ak, av] : v.items()) put(ak, av, grew);
        } else {
          put(k, v, grew);
        }
      }
      if (dropped_) problem = "too_many_names";
    }
    if (grew) handler_.header(names_, 0);
    views_.assign(cells_.begin(), cells_.end());
    ++info_.rows;
    handler_.row(AnswerRow{line, line, views_, problem});
  }

 private:
  // Every row is as wide as the names seen so far: a file with a new name on every line would
  // make the work grow as rows × names (53 s for 20,000 lines). Past kMaxNames different names,
  // a new one is not a column: the row says so (too_many_names), nothing is dropped silently.
  static constexpr std::size_t kMaxNames = 1024;
  static constexpr std::size_t kNoColumn = static_cast<std::size_t>(-1);

  std::size_t column(const std::string& name, bool& grew) {
    if (names_.size() >= kMaxNames) {
      const auto it = index_.find(name);
      if (it != index_.end()) return it->second;
      dropped_ = true;
      return kNoColumn;
    }
    auto [it, fresh] = index_.emplace(name, names_.size());
    if (fresh) {
      names_.push_back(name);
      cells_.emplace_back();
      grew = true;
    }
    return it->second;
  }

  void put(const std::string& name, const json& v, bool& grew) {
    if (v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number()) {
      set(column(name + ".x", grew), text(v[0]));
      set(column(name + ".y", grew), text(v[1]));
      return;
    }
    set(column(name, grew), text(v));
  }
  void set(std::size_t c, std::string value) {
    if (c != kNoColumn) cells_[c] = std::move(value);
  }

  // A value as the cell a spreadsheet would hold. Arrays are flattened (faces, a point's two
  // coordinates) a few levels deep at most, and an object is not an answer: a file of
  // [[[[…]]]] a million deep or an object inside an answer becomes an unreadable cell, not a
  // recursion as deep as the file (that overflowed the stack).
  static std::string text(const json& v, int depth = 0) {
    constexpr int kMaxDepth = 4;
    if (v.is_string()) return v.get<std::string>();
    if (v.is_null()) return {};
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_number()) return fmt::format("{}", v.get<double>());
    if (v.is_array()) {
      if (depth >= kMaxDepth) return "[…]";
      std::string out;
      for (const auto& e : v) {
        if (!out.empty()) out += ' ';
        out += text(e, depth + 1);
      }
      return out.empty() ? std::string("none") : out;  // [] is the empty set of faces
    }
    return "{…}";
  }

  RowHandler& handler_;
  SourceInfo& info_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, std::size_t> index_;
  std::vector<std::string> cells_;
  std::vector<std::string_view> views_;
  bool dropped_ = false;
};

struct TooDeep {};

// nlohmann's message without its id: "[json.exception.parse_error.101] parse error at …" →
// "parse error at …"
std::string_view without_id(std::string_view what) {
  if (what.substr(0, 1) == "[")
    if (const auto close = what.find("] "); close != std::string_view::npos) what.remove_prefix(close + 2);
  return what;
}

bool too_deep(int depth, json::parse_event_t event) {
  return depth >= kMaxJsonDepth &&
         (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start);
}

// A JSON array of objects, each handed on as soon as it closes and then dropped.
template <class Input>
void read_json_array(Input&& input, RowHandler& handler, SourceInfo& info) {
  info.format = "json";
  info.unit = "record";
  JsonRows rows(handler, info);
  int record = 0;
  auto callback = [&](int depth, json::parse_event_t event, json& parsed) {
    if (too_deep(depth, event)) throw TooDeep{};
    if (depth == 1 && (event == json::parse_event_t::object_end || event == json::parse_event_t::array_end ||
                       event == json::parse_event_t::value)) {
      rows.object(parsed, ++record);
      return false;
    }
    return true;
  };
  try {
    const json rest = json::parse(std::forward<Input>(input), callback);  // the emptied array
    (void)rest;
  } catch (const json::parse_error& e) {
    info.stopped = fmt::format("not valid JSON after record {} (byte {}): {}", record, e.byte, without_id(e.what()));
  } catch (const json::exception& e) {
    // a number past the doubles' range (1e400) is out_of_range.406 (found by tests/fuzz: it
    // escaped the reader as nlohmann's raw text)
    info.stopped = fmt::format("not valid JSON after record {}: {}", record, without_id(e.what()));
  } catch (const TooDeep&) {
    info.stopped = fmt::format("record {} is nested deeper than {} levels: not an answers file", record + 1, kMaxJsonDepth);
  }
}

void read_json_lines(std::string_view text, int first_line, SourceInfo& info,
                     JsonRows& rows) {
  int line = first_line;
  while (!text.empty()) {
    const auto nl = text.find('\n');
    std::string_view l = text.substr(0, nl);
    if (l.find_first_not_of(" \t\r") != std::string_view::npos) {
      json o;
      try {
        o = json::parse(l, [](int depth, json::parse_event_t event, json&) {
          if (too_deep(depth, event)) throw TooDeep{};
          return true;
        });
      } catch (const json::exception&) {  // parse_error, or out_of_range for 1e400
        o = json();  // reported as a row that is not an object
      } catch (const TooDeep&) {
        o = json();
      }
      rows.object(o, line);
    } else {
      ++info.blank_lines;
    }
    ++line;
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
}

// The first character after a byte-order mark and blanks.
char first_significant(std::string_view head) {
  if (head.substr(0, 3) == "\xef\xbb\xbf") head.remove_prefix(3);
  const auto i = head.find_first_not_of(" \t\r\n");
  return i == std::string_view::npos ? '\0' : head[i];
}

}  // namespace

SourceInfo read_answers(const std::filesystem::path& path, RowHandler& handler, std::optional<char> delimiter) {
  SourceInfo info;
  char head[4096];
  std::size_t got = 0;
  {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) throw std::runtime_error(fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
    got = std::fread(head, 1, sizeof head, f.get());
  }
  const char first = first_significant(std::string_view(head, got));
  if (first == '[') {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    read_json_array(f.get(), handler, info);
    return info;
  }
  if (first == '{') {
    info.format = "jsonl";
    JsonRows rows(handler, info);
    std::ifstream in(path, std::ios::binary);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      if (n == 1 && line.substr(0, 3) == "\xef\xbb\xbf") line.erase(0, 3);
      read_json_lines(line, n, info, rows);
    }
    return info;
  }
  CsvReader reader(path, delimiter);
  try {
    read_csv(reader, handler, info);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("{}: {}", path.string(), e.what()));
  }
  return info;
}

SourceInfo read_answers_text(std::string text, std::string_view name, RowHandler& handler,
                             std::optional<char> delimiter) {
  SourceInfo info;
  const char first = first_significant(text);
  if (first == '[') {
    read_json_array(text, handler, info);
    return info;
  }
  if (first == '{') {
    info.format = "jsonl";
    JsonRows rows(handler, info);
    std::string_view t = text;
    if (t.substr(0, 3) == "\xef\xbb\xbf") t.remove_prefix(3);
    read_json_lines(t, 1, info, rows);
    return info;
  }
  try {
    CsvReader reader = CsvReader::from_text(std::move(text), delimiter);
    read_csv(reader, handler, info);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("{}: {}", name, e.what()));
  }
  return info;
}

}  // namespace epure::grading
