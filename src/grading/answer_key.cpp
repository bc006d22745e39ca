#include "grading/answer_key.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/key_json.h"
#include "exercises/worksheet.h"
#include "grading/kind_grader.h"
#include "grading/words.h"

namespace epure::grading {

using nlohmann::json;

namespace {

// Where in the key a value sits, for messages: "key.json: sheet 1000-0001-000X: question 2.t".
struct Where {
  std::string_view source;
  std::string sheet;
  std::string item;

  [[noreturn]] void fail(std::string_view why) const {
    std::string at(source);
    if (!sheet.empty()) at += fmt::format(": sheet {}", sheet);
    if (!item.empty()) at += fmt::format(": {}", item);
    throw KeyError(fmt::format("{}: {}", at, why));
  }
};

const json& member(const json& object, const char* name, const Where& where) {
  if (!object.is_object()) where.fail("expected an object");
  auto it = object.find(name);
  if (it == object.end()) where.fail(fmt::format("missing '{}'", name));
  return *it;
}

std::string string_member(const json& object, const char* name, const Where& where) {
  const json& v = member(object, name, where);
  if (!v.is_string()) where.fail(fmt::format("'{}' must be a string", name));
  return v.get<std::string>();
}

double number_member(const json& object, const char* name, const Where& where) {
  const json& v = member(object, name, where);
  if (!v.is_number()) where.fail(fmt::format("'{}' must be a number", name));
  return v.get<double>();
}

// An optional member of `object`, of the type asked, or `fallback` when absent: a value of
// another type is refused with its name, never read as nlohmann's type_error.
std::string optional_string(const json& object, const char* name, std::string fallback, const Where& where) {
  const auto it = object.find(name);
  if (it == object.end()) return fallback;
  if (!it->is_string()) where.fail(fmt::format("'{}' must be a string", name));
  return it->get<std::string>();
}

bool optional_bool(const json& object, const char* name, bool fallback, const Where& where) {
  const auto it = object.find(name);
  if (it == object.end()) return fallback;
  if (!it->is_boolean()) where.fail(fmt::format("'{}' must be true or false", name));
  return it->get<bool>();
}

// An integer from `lo` to `hi` (a JSON number with no fraction: 2 and 2.0 alike).
std::int64_t integer_member(const json& object, const char* name, std::int64_t lo, std::int64_t hi,
                            const Where& where) {
  const json& v = member(object, name, where);
  const auto refuse = [&] { where.fail(fmt::format("'{}' must be an integer from {} to {}", name, lo, hi)); };
  if (v.is_number_unsigned()) {
    if (v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) refuse();
    return static_cast<std::int64_t>(v.get<std::uint64_t>());
  }
  if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if (i < lo || i > hi) refuse();
    return i;
  }
  if (!v.is_number()) refuse();
  const double d = v.get<double>();
  if (!(d >= static_cast<double>(lo) && d <= static_cast<double>(hi)) || d != std::floor(d)) refuse();
  return static_cast<std::int64_t>(d);
}

ToleranceRule read_rule(const json& q, const Where& where) {
  const json& t = member(q, "tolerance", where);
  ToleranceRule r;
  const std::string rule = string_member(t, "rule", where);
  if (rule == "exact") r.kind = ToleranceRule::Kind::exact;
  else if (rule == "isclose") r.kind = ToleranceRule::Kind::isclose;
  else if (rule == "distance") r.kind = ToleranceRule::Kind::distance;
  else where.fail(fmt::format("unknown tolerance rule '{}' (exact, isclose or distance)", rule));
  if (r.kind == ToleranceRule::Kind::isclose) r.rel = number_member(t, "rel", where);
  if (r.kind != ToleranceRule::Kind::exact) r.abs = number_member(t, "abs", where);
  if (r.kind != ToleranceRule::Kind::exact && t.contains("follow_abs")) r.follow_abs = number_member(t, "follow_abs", where);
  if (!(r.rel >= 0 && r.abs >= 0 && r.follow_abs >= 0)) where.fail("tolerances must be ≥ 0");
  if (auto why = t.find("why"); why != t.end() && why->is_string()) r.why = why->get<std::string>();
  return r;
}

QuestionKey read_question(const json& q, const std::string& number, Where where) {
  QuestionKey k;
  k.id = string_member(q, "id", where);
  where.item = fmt::format("question {}", k.id);
  const std::string prefix = number + ".";
  if (k.id.rfind(prefix, 0) != 0 || k.id.size() == prefix.size())
    where.fail(fmt::format("its id should start with '{}' (the exercise's number)", prefix));
  k.field = k.id.substr(prefix.size());
  k.field_hash = field_hash(k.field);
  const json& e = member(q, "expected", where);
  if (e.is_number()) {
    k.type = AnswerType::number;
    k.number = e.get<double>();
  } else if (e.is_boolean()) {
    k.type = AnswerType::boolean;
    k.boolean = e.get<bool>();
  } else if (e.is_string()) {
    k.type = AnswerType::choice;
    k.word = e.get<std::string>();
  } else if (e.is_array()) {
    k.type = AnswerType::faces;
    for (const auto& f : e) {
      const FaceBits bit = f.is_string() ? face_bit(f.get<std::string>()) : FaceBits(0);
      if (!bit) where.fail(fmt::format("'expected' lists {}, not a face name (+x, -y, …)", f.dump()));
      k.faces |= bit;
    }
  } else {
    where.fail("'expected' must be a number, a boolean, a string or a list of faces");
  }
  if (auto ex = q.find("exact"); ex != q.end() && ex->is_string()) k.exact = ex->get<std::string>();
  k.rule = read_rule(q, where);
  k.points = number_member(q, "points", where);
  if (!(k.points >= 0)) where.fail("'points' must be ≥ 0");
  if (auto p = q.find("point"); p != q.end()) {
    if (!p->is_string()) where.fail("'point' must be a string");
    k.point = p->get<std::string>();
  }
  return k;
}

}  // namespace

const std::string* AnswerKey::id_of_place_name(std::string_view name) const {
  const auto it = place_names_.find(name);
  return it == place_names_.end() ? nullptr : &it->second;
}

bool AnswerKey::only_by_place(std::string_view name) const {
  return place_names_.find(name) != place_names_.end() &&
         std::find(question_ids_.begin(), question_ids_.end(), name) == question_ids_.end();
}

bool AnswerKey::has_number(std::string_view number) const { return numbers_.find(number) != numbers_.end(); }

int ExerciseKey::find(std::string_view field) const {
  // kinds' graders ask by name many times per exercise: by hash alone once packed (every
  // field name the kinds use hashes apart, tests/grading/answer_key_test.cpp checks it)
  const std::uint32_t h = field_hash(field);
  if (field_hashes.size() == questions.size()) {
    for (std::size_t i = 0; i < field_hashes.size(); ++i)
      if (field_hashes[i] == h) return static_cast<int>(i);
    return -1;
  }
  for (std::size_t i = 0; i < questions.size(); ++i)
    if (questions[i].field_hash == h && questions[i].field == field) return static_cast<int>(i);
  return -1;
}

namespace {

// The slot to start probing at: FNV-1a spread by a Fibonacci multiply (ids differ in a few
// trailing characters, which FNV-1a alone leaves in its low bits).
std::size_t first_slot(std::string_view id, std::size_t mask) {
  return static_cast<std::size_t>(field_hash(id) * 2654435769u) & mask;
}

}  // namespace

const SheetKey* AnswerKey::find(std::string_view canonical_id) const {
  if (slots_.empty()) return nullptr;
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = first_slot(canonical_id, mask);; i = (i + 1) & mask) {
    const std::uint32_t slot = slots_[i];
    if (slot == 0) return nullptr;
    const SheetKey& s = sheets_[slot - 1];
    if (s.id == canonical_id) return &s;
  }
}

void AnswerKey::rehash(std::size_t slots) {
  slots_.assign(slots, 0);
  const std::size_t mask = slots - 1;
  for (std::size_t k = 0; k < sheets_.size(); ++k) {
    std::size_t i = first_slot(sheets_[k].id, mask);
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = static_cast<std::uint32_t>(k + 1);
  }
}

void AnswerKey::add(SheetKey sheet) {
  // Merge this sheet's ids into the report order: a new id goes right after the id asked
  // before it on this sheet (or first among its exercise's), so every exercise keeps the
  // order its sheets ask in, whatever branch each sheet drew.
  for (const auto& e : sheet.exercises) {
    numbers_.try_emplace(e.number, e.n);
    std::string previous;
    for (const auto& q : e.questions) {
      auto it = std::find(question_ids_.begin(), question_ids_.end(), q.id);
      if (it == question_ids_.end()) {
        auto at = question_ids_.end();
        if (!previous.empty()) {
          at = std::find(question_ids_.begin(), question_ids_.end(), previous) + 1;
        } else {
          // before the first id of a later exercise
          at = question_ids_.begin() +
               (std::find_if(question_places_.begin(), question_places_.end(), [&](int n) { return n > e.n; }) -
                question_places_.begin());
        }
        question_places_.insert(question_places_.begin() + (at - question_ids_.begin()), e.n);
        question_ids_.insert(at, q.id);
        // its name by place, once a key has an exercise numbered otherwise than by its place
        // (first seen here, a question's id is new: a sheet adds nothing after the first few)
        if (e.number != std::to_string(e.n) || !place_names_.empty()) {
          if (place_names_.empty())  // the questions seen before: their ids are their places
            for (const auto& id : question_ids_)
              if (id != q.id) place_names_.emplace(id, id);
          place_names_.emplace(fmt::format("{}.{}", e.n, q.field), q.id);
        }
      }
      previous = q.id;
    }
  }
  if (find(sheet.id)) throw KeyError(fmt::format("{}: sheet {} appears twice", info.source, sheet.id));
  sheets_.push_back(std::move(sheet));
  // at most half full, so that a probe for an id not in the key ends soon
  if (sheets_.size() * 2 > slots_.size()) {
    rehash(std::max<std::size_t>(16, slots_.size() * 2));
  } else {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = first_slot(sheets_.back().id, mask);
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = static_cast<std::uint32_t>(sheets_.size());
  }
}

namespace {

// A point in space is asked as three numbers, "I.x", "I.y", "I.z", which keys do not group: they
// are grouped here, as the plane's points are by their key ("point"), so that a point in space
// gets the plane's rules (marked as a whole by distance when its rule says so, two coordinates
// typed in each other's cells, a point typed in one cell).
void group_points_in_space(ExerciseKey& ex) {
  for (auto& q : ex.questions) {
    if (!q.point.empty() || q.type != AnswerType::number || !q.field.ends_with(".x")) continue;
    const std::string base = q.field.substr(0, q.field.size() - 2);
    const int y = ex.find(base + ".y"), z = ex.find(base + ".z");
    if (y < 0 || z < 0) continue;
    auto& qy = ex.questions[static_cast<std::size_t>(y)];
    auto& qz = ex.questions[static_cast<std::size_t>(z)];
    if (!qy.point.empty() || !qz.point.empty() || qy.type != AnswerType::number || qz.type != AnswerType::number)
      continue;
    const std::string group = fmt::format("{}.{}", ex.n, base);
    q.point = qy.point = qz.point = group;
  }
}

}  // namespace

SheetKey read_sheet_json(const json& s, std::string_view source) {
  Where where{source, {}, {}};
  SheetKey sheet;
  const std::string id_text = string_member(s, "id", where);
  where.sheet = id_text;
  const auto parsed = parse_sheet_id(id_text);
  if (!parsed.id) where.fail(fmt::format("not a sheet id: {}", parsed.error.message));
  sheet.sheet = *parsed.id;
  sheet.id = parsed.id->str();
  const json& exercises = member(s, "exercises", where);
  if (!exercises.is_array()) where.fail("'exercises' must be an array");
  for (const auto& e : exercises) {
    where.item.clear();
    ExerciseKey ex;
    ex.n = static_cast<int>(integer_member(e, "n", 1, static_cast<std::int64_t>(kMaxExercises), where));
    where.item = fmt::format("exercise {}", ex.n);
    ex.number = std::to_string(ex.n);
    if (auto num = e.find("number"); num != e.end()) {
      if (!num->is_string() || num->get<std::string>().empty() || num->get<std::string>().size() > 64)
        where.fail("'number' must be a short string (\"3.3\")");
      ex.number = num->get<std::string>();
    }
    ex.kind = string_member(e, "kind", where);
    if (auto b = e.find("branch"); b != e.end() && b->is_string()) ex.branch = b->get<std::string>();
    ex.instance = member(e, "instance", where);
    ex.solution = member(e, "solution", where);
    const json& qs = member(e, "questions", where);
    if (!qs.is_array()) where.fail("'questions' must be an array");
    for (const auto& q : qs) ex.questions.push_back(read_question(q, ex.number, where));
    ex.grader = find_grader(ex.kind);
    if (ex.grader) {
      try {
        ex.prepared = ex.grader->prepare(ex.instance);
      } catch (const std::exception& err) {
        where.fail(fmt::format("instance: {}", err.what()));
      }
    }
    group_points_in_space(ex);
    for (std::size_t i = 0; i < ex.questions.size(); ++i) {
      auto& q = ex.questions[i];
      sheet.max_points += q.points;
      if (q.point.empty() || q.rule.kind != ToleranceRule::Kind::distance) continue;
      // the point's coordinates in a ring (x → y → x, or x → y → z → x): marking walks it to
      // decide them together
      for (std::size_t step = 1; step < ex.questions.size(); ++step) {
        const std::size_t j = (i + step) % ex.questions.size();
        if (ex.questions[j].point == q.point) {
          q.partner = static_cast<int>(j);
          break;
        }
      }
    }
    sheet.exercises.push_back(std::move(ex));
  }
  // packed last, one exercise after the other, so that they sit together in memory
  for (auto& ex : sheet.exercises) {
    ex.hot.reserve(ex.questions.size());
    ex.field_hashes.reserve(ex.questions.size());
    for (const auto& q : ex.questions) {
      HotQuestion h;
      h.number = q.number;
      h.points = q.points;
      h.rel = q.rule.rel;
      h.abs = q.rule.abs;
      h.follow_abs = q.rule.follow_abs;
      if (q.type == AnswerType::choice) {
        const auto token = read_word(q.word);
        h.word = token && *token == q.word ? token->data() : nullptr;  // null: no answer reads as it
      }
      h.partner = q.partner;
      h.field_hash = q.field_hash;
      h.type = q.type;
      h.rule = q.rule.kind;
      h.boolean = q.boolean;
      h.faces = q.faces;
      ex.hot.push_back(h);
      ex.field_hashes.push_back(q.field_hash);
    }
  }
  return sheet;
}

AnswerKey read_key_json(std::string_view text, std::string_view source) {
  AnswerKey key;
  key.info.source = std::string(source);
  bool in_sheets = false;
  // Each sheet is converted as soon as its object closes, and dropped from the tree.
  if (text.size() > kMaxKeyBytes)
    throw KeyError(fmt::format("{}: {} bytes: a key.json holds at most {} bytes (1 GiB)", source, text.size(),
                               kMaxKeyBytes));
  auto callback = [&](int depth, json::parse_event_t event, json& parsed) {
    if (depth > kMaxKeyDepth && (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start))
      throw KeyError(fmt::format("{}: nested deeper than {} levels: not a key.json", source, kMaxKeyDepth));
    if (depth == 1 && event == json::parse_event_t::key) in_sheets = parsed == "sheets";
    if (depth == 2 && in_sheets && event == json::parse_event_t::object_end) {
      if (key.sheets().size() >= static_cast<std::size_t>(kMaxSheets))
        throw KeyError(fmt::format("{}: more than {} sheets: a set holds at most {}", source, kMaxSheets, kMaxSheets));
      key.add(read_sheet_json(parsed, source));
      return false;
    }
    return true;
  };
  json root;
  try {
    root = json::parse(text.begin(), text.end(), callback);
  } catch (const json::parse_error& e) {
    throw KeyError(fmt::format("{}: not valid JSON (byte {}): {}", source, e.byte, e.what()));
  } catch (const json::exception& e) {
    // a number past the doubles' range (1e400) is out_of_range.406, not a parse_error
    std::string_view what = e.what();
    if (const auto close = what.find("] "); what.substr(0, 1) == "[" && close != std::string_view::npos)
      what.remove_prefix(close + 2);
    throw KeyError(fmt::format("{}: not valid JSON: {}", source, what));
  }
  Where where{source, {}, {}};
  if (!root.is_object()) where.fail("expected one JSON object, as `epure generate` writes key.json");
  const json& spec = member(root, "spec", where);
  where.item = "spec";
  if (!spec.is_object()) where.fail("expected an object");
  key.info.title = optional_string(spec, "title", {}, where);
  key.info.language = optional_string(spec, "language", "en", where);
  if (spec.contains("decimals")) key.info.decimals = static_cast<int>(integer_member(spec, "decimals", 0, 6, where));
  key.info.follow_through = optional_bool(spec, "follow_through", true, where);
  if (const auto it = spec.find("scale"); it != spec.end()) {
    if (!it->is_number() || !(it->get<double>() > 0)) where.fail("'scale' must be a positive number");
    key.info.scale = it->get<double>();
  }
  key.info.spec_text = optional_string(spec, "text", {}, where);
  key.info.spec_source = optional_string(spec, "source", {}, where);
  where.item.clear();
  key.info.seed = static_cast<std::uint64_t>(integer_member(root, "seed", 0, static_cast<std::int64_t>(kMaxSeed), where));
  const json& version = member(root, "version", where);
  where.item = "version";
  key.info.epure_version = string_member(version, "epure", where);
  key.info.draw_version = static_cast<int>(integer_member(version, "draw", 0, 31, where));
  where.item.clear();
  if (!root.contains("sheets")) where.fail("missing 'sheets'");
  if (key.sheets().empty()) where.fail("the key has no sheets");
  return key;
}

AnswerKey key_from_spec(const WorksheetSpec& spec, const std::vector<SheetId>& ids,
                        std::string_view epure_version) {
  AnswerKey key;
  key.info.source = spec.source;
  key.info.title = spec.title;
  key.info.language = spec.language;
  key.info.decimals = spec.decimals;
  key.info.follow_through = spec.follow_through;
  key.info.scale = spec.scale;
  key.info.spec_text = spec.text;
  key.info.spec_source = spec.source;
  key.info.epure_version = std::string(epure_version);
  key.info.draw_version = kDrawVersion;

  std::vector<SheetId> sorted = ids;
  std::sort(sorted.begin(), sorted.end(), [](const SheetId& a, const SheetId& b) {
    return std::tie(a.seed, a.index) < std::tie(b.seed, b.index);
  });
  if (!sorted.empty()) key.info.seed = sorted.front().seed;
  std::optional<WorksheetSet> set;
  fmt::memory_buffer buffer;
  for (const SheetId& id : sorted) {
    if (id.version != kDrawVersion) {
      key.refuse(id.str(), fmt::format("drawn by generator version {}; this epure draws version {} and "
                                       "would rebuild a different sheet: grade it with key.json or with "
                                       "the epure that made it",
                                       id.version, kDrawVersion));
      continue;
    }
    if (key.find(id.str())) continue;
    if (!set || set->seed() != id.seed) set.emplace(spec, id.seed);
    const Sheet sheet = set->rebuild(id);
    buffer.clear();
    KeyJson::sheet(buffer, sheet, true);
    key.add(read_sheet_json(json::parse(std::string_view(buffer.data(), buffer.size())), spec.source));
  }
  return key;
}

}  // namespace epure::grading
