#include "grading/corrections.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace epure::grading {

namespace {

using json = nlohmann::json;

struct TooDeep {};

std::string type_name(const json& v) {
  if (v.is_string()) return "string";
  if (v.is_number()) return "number";
  if (v.is_boolean()) return "boolean";
  if (v.is_null()) return "null";
  if (v.is_array()) return "list";
  return "object";
}

// nlohmann's message without its id ("[json.exception.parse_error.101] ").
std::string without_id(std::string_view what) {
  if (what.substr(0, 1) == "[")
    if (const auto close = what.find("] "); close != std::string_view::npos) what.remove_prefix(close + 2);
  return std::string(what);
}

}  // namespace

std::string describe(const CorrectionsProblem& p, const Texts& texts) {
  TextVars vars = p.vars;
  for (auto& [name, value] : vars)
    if (name == "type") value = texts.get("grading.corrections.type." + value);
  vars.emplace_back("format", std::string(kCorrectionsFormat));
  vars.emplace_back("version", std::to_string(kCorrectionsVersion));
  std::string text = texts.format("grading.corrections." + p.code, vars);
  if (p.entry > 0) text = texts.format("grading.corrections.entry", {{"entry", std::to_string(p.entry)}, {"problem", text}});
  return text;
}

Corrections read_corrections(std::string_view text, std::string_view source) {
  Corrections out;
  out.source = std::string(source);
  auto whole = [&](std::string code, TextVars vars = {}) { out.problems.push_back({0, std::move(code), std::move(vars)}); };
  if (text.size() > kMaxCorrectionsBytes) {
    whole("too_large", {{"bytes", std::to_string(text.size())}, {"max", std::to_string(kMaxCorrectionsBytes)}});
    return out;
  }
  if (text.substr(0, 3) == "\xef\xbb\xbf") text.remove_prefix(3);
  json root;
  try {
    root = json::parse(text.begin(), text.end(), [](int depth, json::parse_event_t event, json&) {
      if (depth >= kMaxCorrectionsDepth &&
          (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start))
        throw TooDeep{};
      return true;
    });
  } catch (const json::parse_error& e) {
    whole("not_json", {{"byte", std::to_string(e.byte)}, {"why", without_id(e.what())}});
    return out;
  } catch (const json::exception& e) {  // a number past the doubles' range
    whole("not_json", {{"byte", "?"}, {"why", without_id(e.what())}});
    return out;
  } catch (const TooDeep&) {
    whole("too_deep", {{"levels", std::to_string(kMaxCorrectionsDepth)}});
    return out;
  }
  if (!root.is_object()) {
    whole("not_object", {{"type", type_name(root)}});
    return out;
  }
  const auto format = root.find("format");
  if (format == root.end() || !format->is_string() || format->get_ref<const std::string&>() != kCorrectionsFormat) {
    whole("bad_format", {{"found", format == root.end() ? std::string("—") : format->dump()}});
    return out;
  }
  const auto version = root.find("version");
  if (version == root.end() || !version->is_number_integer() || version->get<long long>() != kCorrectionsVersion) {
    whole("bad_version", {{"found", version == root.end() ? std::string("—") : version->dump()}});
    return out;
  }
  const auto list = root.find("corrections");
  if (list == root.end() || !list->is_array()) {
    whole("no_list", {{"found", list == root.end() ? std::string("—") : type_name(*list)}});
    return out;
  }
  out.readable = true;
  int entry = 0;
  for (const json& item : *list) {
    ++entry;
    auto bad = [&](std::string code, TextVars vars = {}) { out.problems.push_back({entry, std::move(code), std::move(vars)}); };
    if (!item.is_object()) {
      bad("entry_not_object", {{"type", type_name(item)}});
      continue;
    }
    Correction c;
    c.entry = entry;
    bool ok = true;
    for (auto [name, into, required] : {std::tuple{"sheet", &c.sheet, true}, std::tuple{"question", &c.question, true},
                                        std::tuple{"value", &c.value, true}, std::tuple{"note", &c.note, false}}) {
      const auto it = item.find(name);
      if (it == item.end()) {
        if (required) {
          bad("missing", {{"field", name}});
          ok = false;
        }
        continue;
      }
      if (!it->is_string()) {
        bad(std::string_view(name) == "value" ? "value_not_string" : "not_string", {{"field", name}, {"type", type_name(*it)}});
        ok = false;
        continue;
      }
      *into = it->get<std::string>();
    }
    if (!ok) continue;
    if (c.sheet.empty() || c.question.empty()) {
      bad("empty", {{"field", c.sheet.empty() ? "sheet" : "question"}});
      continue;
    }
    if (c.value.size() > kMaxCorrectionValueBytes) {
      bad("value_too_long", {{"bytes", std::to_string(c.value.size())}, {"max", std::to_string(kMaxCorrectionValueBytes)}});
      continue;
    }
    out.entries.push_back(std::move(c));
  }
  return out;
}

Corrections read_corrections_file(const std::filesystem::path& path) {
  std::error_code error;
  const auto bytes = std::filesystem::file_size(path, error);
  if (!error && bytes > kMaxCorrectionsBytes) {
    Corrections out;
    out.source = path.string();
    out.problems.push_back({0, "too_large", {{"bytes", std::to_string(bytes)}, {"max", std::to_string(kMaxCorrectionsBytes)}}});
    return out;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read", path.string()));
  std::stringstream text;
  text << in.rdbuf();
  return read_corrections(text.str(), path.string());
}

std::string corrections_json(std::span<const Correction> entries) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& e : entries) {
    nlohmann::ordered_json o;
    o["sheet"] = e.sheet;
    o["question"] = e.question;
    o["value"] = e.value;
    if (!e.note.empty()) o["note"] = e.note;
    list.push_back(std::move(o));
  }
  nlohmann::ordered_json root;
  root["format"] = kCorrectionsFormat;
  root["version"] = kCorrectionsVersion;
  root["corrections"] = std::move(list);
  // strings as they are (no \u escapes), invalid UTF-8 replaced rather than thrown on
  return root.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace epure::grading
