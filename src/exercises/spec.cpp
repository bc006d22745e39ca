#include "exercises/spec.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <set>

#include "embed/embedded.h"
#include "exercises/exercise.h"
#include "exercises/points.h"
#include "exercises/texts.h"

namespace epure {

std::string_view to_string(Difficulty d) {
  switch (d) {
    case Difficulty::easy: return "easy";
    case Difficulty::standard: return "standard";
    case Difficulty::hard: return "hard";
  }
  return "?";
}

std::optional<Difficulty> parse_difficulty(std::string_view s) {
  if (s == "easy") return Difficulty::easy;
  if (s == "standard") return Difficulty::standard;
  if (s == "hard") return Difficulty::hard;
  return std::nullopt;
}

namespace {

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const toml::node& node, std::string_view key, std::string_view why) const {
    const auto& at = node.source().begin;
    throw SpecError(fmt::format("{}:{}:{}: key '{}': {}", source_, at.line, at.column, key, why));
  }

  // Every key of `table` must be one of `known`: a typo is an error, not a silent default.
  void only(const toml::table& table, std::string_view prefix,
            std::initializer_list<std::string_view> known) const {
    for (const auto& [k, node] : table) {
      bool ok = false;
      for (auto name : known) ok = ok || k.str() == name;
      if (!ok) {
        std::string names;
        for (auto name : known) names += fmt::format("{}{}", names.empty() ? "" : ", ", name);
        fail(node, qualified(prefix, k.str()), fmt::format("unknown key (known: {})", names));
      }
    }
  }

  std::string string(const toml::table& t, std::string_view prefix, std::string_view key,
                     std::string fallback) const {
    const toml::node* node = t.get(key);
    if (!node) return fallback;
    if (!node->is_string()) fail(*node, qualified(prefix, key), "expected a string");
    return node->as_string()->get();
  }

  // A string, or a table of strings by language ({ en = "…", fr = "…" }): the value in
  // `language`, else `fallback`; every language given goes into `by_language[lang].*field`.
  std::string localized(const toml::table& t, std::string_view key, std::string_view language,
                        std::string fallback, std::map<std::string, SpecWords>& by_language,
                        std::string SpecWords::*field) const {
    const toml::node* node = t.get(key);
    if (!node) return fallback;
    if (node->is_string()) return node->as_string()->get();
    const auto* table = node->as_table();
    if (!table) fail(*node, key, "expected a string, or a table of strings by language ({ en = \"…\", fr = \"…\" })");
    std::string value = std::move(fallback);
    for (const auto& [lang, v] : *table) {
      const std::string name = qualified(key, lang.str());
      bool known = false;
      for (const auto& l : builtin_languages()) known = known || l == lang.str();
      if (!known) fail(v, name, "unknown language (languages: en, fr)");
      if (!v.is_string()) fail(v, name, "expected a string");
      by_language[std::string(lang.str())].*field = v.as_string()->get();
      if (lang.str() == language) value = v.as_string()->get();
    }
    return value;
  }

  // The same for a value of its own: the string in `language` (or the first given), every
  // language into `by_language`.
  std::string localized(const toml::table& t, std::string_view prefix, std::string_view key,
                        std::string_view language, std::map<std::string, std::string>& by_language) const {
    const toml::node* node = t.get(key);
    if (!node) return {};
    const std::string name = qualified(prefix, key);
    if (node->is_string()) return node->as_string()->get();
    const auto* table = node->as_table();
    if (!table || table->empty())
      fail(*node, name, "expected a string, or a table of strings by language ({ en = \"…\", fr = \"…\" })");
    std::string value;
    for (const auto& [lang, v] : *table) {
      const std::string lname = qualified(name, lang.str());
      bool known = false;
      for (const auto& l : builtin_languages()) known = known || l == lang.str();
      if (!known) fail(v, lname, "unknown language (languages: en, fr)");
      if (!v.is_string()) fail(v, lname, "expected a string");
      by_language[std::string(lang.str())] = v.as_string()->get();
      if (lang.str() == language || value.empty()) value = v.as_string()->get();
    }
    return value;
  }

  double number(const toml::node& node, std::string_view key) const {
    if (auto i = node.as_integer()) return static_cast<double>(i->get());
    if (auto f = node.as_floating_point()) {
      if (!std::isfinite(f->get())) fail(node, key, "expected a finite number");
      return f->get();
    }
    fail(node, key, "expected a number");
  }

  static std::string qualified(std::string_view prefix, std::string_view key) {
    return prefix.empty() ? std::string(key) : fmt::format("{}.{}", prefix, key);
  }

 private:
  std::string source_;
};

constexpr std::size_t kMaxNumberLength = 12;

// "P", "2", "3.3": printed beside fields and read back as CSV columns, so plain ASCII, no space.
bool valid_number(std::string_view n) {
  if (n.empty() || n.size() > kMaxNumberLength || n.front() == '.' || n.back() == '.') return false;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const char c = n[i];
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!alnum && !(c == '.' && n[i - 1] != '.')) return false;
  }
  return true;
}

ExerciseSpec read_exercise(const Reader& r, const toml::table& t, std::string_view prefix,
                           Difficulty default_difficulty, std::string_view language, const toml::node& where) {
  r.only(t, prefix, {"kind", "heading", "number", "difficulty", "branches", "points", "questions", "constraints"});
  ExerciseSpec e;
  e.heading = r.localized(t, prefix, "heading", language, e.heading_by_language);
  if (const toml::node* n = t.get("number")) {
    const std::string key = Reader::qualified(prefix, "number");
    if (const auto* i = n->as_integer()) e.number = std::to_string(i->get());
    else if (n->is_string()) e.number = n->as_string()->get();
    else r.fail(*n, key, "expected a string such as \"3.3\" or \"P\"");
    if (!valid_number(e.number))
      r.fail(*n, key,
             fmt::format("\"{}\": letters and digits, parts joined by single dots, at most {} characters "
                         "(\"P\", \"2\", \"3.3\"): it starts every question id of the exercise",
                         e.number, kMaxNumberLength));
  }
  e.kind = r.string(t, prefix, "kind", "");
  if (e.kind.empty()) r.fail(where, Reader::qualified(prefix, "kind"), "missing");
  const ExerciseKind* kind = find_kind(e.kind);
  if (!kind) {
    std::string names;
    for (auto* k : all_kinds()) names += fmt::format("{}{}", names.empty() ? "" : ", ", k->name());
    r.fail(*t.get("kind"), Reader::qualified(prefix, "kind"),
           fmt::format("unknown exercise kind '{}' (kinds: {})", e.kind, names));
  }

  e.difficulty = default_difficulty;
  if (const toml::node* d = t.get("difficulty")) {
    auto parsed = d->is_string() ? parse_difficulty(d->as_string()->get()) : std::nullopt;
    if (!parsed) r.fail(*d, Reader::qualified(prefix, "difficulty"), "expected easy, standard or hard");
    e.difficulty = *parsed;
  }
  if (const toml::node* p = t.get("points")) {
    e.points = r.number(*p, Reader::qualified(prefix, "points"));
    if (!(*e.points >= 0)) r.fail(*p, Reader::qualified(prefix, "points"), "must be ≥ 0");
    if (!on_point_step(*e.points))
      r.fail(*p, Reader::qualified(prefix, "points"),
             fmt::format("must be a multiple of {} (each question gets a share in steps of {})", kPointStep, kPointStep));
  }

  if (const toml::node* b = t.get("branches")) {
    const std::string key = Reader::qualified(prefix, "branches");
    const auto* table = b->as_table();
    if (!table) r.fail(*b, key, "expected a table of weights, e.g. { hit = 2, miss = 1 }");
    const auto known = kind->default_branches();
    double total = 0;
    for (const auto& [name, node] : *table) {
      bool ok = false;
      for (const auto& [k, w] : known) ok = ok || k == name.str();
      if (!ok) {
        std::string names;
        for (const auto& [k, w] : known) names += fmt::format("{}{}", names.empty() ? "" : ", ", k);
        r.fail(node, Reader::qualified(key, name.str()),
               fmt::format("no branch '{}' for {} (branches: {})", name.str(), e.kind, names));
      }
      double w = r.number(node, Reader::qualified(key, name.str()));
      if (!(w >= 0)) r.fail(node, Reader::qualified(key, name.str()), "weight must be ≥ 0");
      total += w;
    }
    if (!(total > 0)) r.fail(*b, key, "at least one branch needs a positive weight");
    // keep the kind's order, so that the schedule does not depend on the file's key order
    for (const auto& [k, w] : known)
      if (const toml::node* node = table->get(k)) e.branches.emplace_back(k, r.number(*node, k));
  }

  if (const toml::node* q = t.get("questions")) {
    const std::string key = Reader::qualified(prefix, "questions");
    const auto* table = q->as_table();
    if (!table) r.fail(*q, key, "expected a table, e.g. { t = { points = 2 } }");
    const auto fields = kind->fields();
    for (const auto& [name, node] : *table) {
      const std::string qkey = Reader::qualified(key, name.str());
      bool ok = false;
      for (const auto& f : fields) ok = ok || f == name.str();
      if (!ok) {
        std::string names;
        for (const auto& f : fields) names += fmt::format("{}{}", names.empty() ? "" : ", ", f);
        r.fail(node, qkey, fmt::format("{} asks no '{}' (fields: {})", e.kind, name.str(), names));
      }
      const auto* qt = node.as_table();
      if (!qt) r.fail(node, qkey, "expected a table, e.g. { points = 2, abs = 0.01 }");
      r.only(*qt, qkey, {"points", "rel", "abs", "whole_point"});
      QuestionSpec qs;
      if (auto* p = qt->get("points")) qs.points = r.number(*p, qkey + ".points");
      if (auto* p = qt->get("rel")) qs.rel = r.number(*p, qkey + ".rel");
      if (auto* p = qt->get("abs")) qs.abs = r.number(*p, qkey + ".abs");
      if (auto* p = qt->get("whole_point")) {
        if (!p->is_boolean()) r.fail(*p, qkey + ".whole_point", "expected true or false");
        qs.whole_point = p->as_boolean()->get();
      }
      if ((qs.points && *qs.points < 0) || (qs.rel && *qs.rel < 0) || (qs.abs && *qs.abs < 0))
        r.fail(node, qkey, "points and tolerances must be ≥ 0");
      e.questions.emplace(std::string(name.str()), qs);
    }
  }

  if (const toml::node* c = t.get("constraints")) {
    const std::string key = Reader::qualified(prefix, "constraints");
    const auto* table = c->as_table();
    if (!table) r.fail(*c, key, "expected a table of numbers");
    const auto known = kind->default_constraints();
    for (const auto& [name, node] : *table) {
      if (!known.count(std::string(name.str()))) {
        std::string names;
        for (const auto& [k, v] : known) names += fmt::format("{}{}", names.empty() ? "" : ", ", k);
        r.fail(node, Reader::qualified(key, name.str()),
               fmt::format("no constraint '{}' for {} (constraints: {})", name.str(), e.kind,
                           names.empty() ? "none" : names));
      }
      e.constraints[std::string(name.str())] = r.number(node, Reader::qualified(key, name.str()));
    }
  }
  return e;
}

}  // namespace

WorksheetSpec parse_spec(std::string_view toml_text, std::string_view source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw SpecError(fmt::format("{}:{}:{}: {}", source_name, e.source().begin.line,
                                e.source().begin.column, e.description()));
  }
  Reader r(source_name);
  r.only(root, "", {"title", "course", "author", "subject", "language", "page", "decimals", "student_number_digits",
                    "difficulty", "follow_through", "scale", "exercise"});
  WorksheetSpec spec;
  spec.source = std::string(source_name);
  spec.text = std::string(toml_text);
  spec.language = r.string(root, "", "language", "en");
  {
    bool known = false;
    for (const auto& l : builtin_languages()) known = known || l == spec.language;
    if (!known) r.fail(*root.get("language"), "language", "expected en or fr");
  }
  auto& by = spec.words_by_language;
  spec.title = r.localized(root, "title", spec.language, "Worksheet", by, &SpecWords::title);
  spec.course = r.localized(root, "course", spec.language, "", by, &SpecWords::course);
  spec.author = r.localized(root, "author", spec.language, "", by, &SpecWords::author);
  spec.subject = r.localized(root, "subject", spec.language, "", by, &SpecWords::subject);
  spec.page = r.string(root, "", "page", "A4");
  if (spec.page != "A4" && spec.page != "letter")
    r.fail(*root.get("page"), "page", "expected \"A4\" or \"letter\"");
  if (const toml::node* d = root.get("decimals")) {
    auto* i = d->as_integer();
    if (!i || i->get() < 0 || i->get() > 6) r.fail(*d, "decimals", "expected an integer from 0 to 6");
    spec.decimals = static_cast<int>(i->get());
  }
  if (const toml::node* n = root.get("student_number_digits")) {
    auto* i = n->as_integer();
    if (!i || i->get() < kMinStudentNumberDigits || i->get() > kMaxStudentNumberDigits)
      r.fail(*n, "student_number_digits",
             fmt::format("expected an integer from {} to {} (the cells of the student number's comb)",
                         kMinStudentNumberDigits, kMaxStudentNumberDigits));
    else
      spec.student_number_digits = static_cast<int>(i->get());
  }
  if (const toml::node* f = root.get("follow_through")) {
    if (!f->is_boolean()) r.fail(*f, "follow_through", "expected true or false");
    spec.follow_through = f->as_boolean()->get();
  }
  if (const toml::node* s = root.get("scale")) {
    spec.scale = r.number(*s, "scale");
    if (!(*spec.scale > 0)) r.fail(*s, "scale", "expected a positive number (20: marks out of 20)");
  }
  Difficulty difficulty = Difficulty::standard;
  if (const toml::node* d = root.get("difficulty")) {
    auto parsed = d->is_string() ? parse_difficulty(d->as_string()->get()) : std::nullopt;
    if (!parsed) r.fail(*d, "difficulty", "expected easy, standard or hard");
    difficulty = *parsed;
  }
  const toml::node* exercises = root.get("exercise");
  if (!exercises) throw SpecError(fmt::format("{}: no [[exercise]]: a worksheet needs at least one", source_name));
  const auto* array = exercises->as_array();
  if (!array || array->empty()) r.fail(*exercises, "exercise", "expected [[exercise]] tables");
  if (array->size() > kMaxExercises)
    r.fail(*exercises, "exercise",
           fmt::format("{} [[exercise]] tables: a spec holds at most {}", array->size(), kMaxExercises));
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& node = *array->get(i);
    const auto* t = node.as_table();
    const std::string prefix = fmt::format("exercise[{}]", i + 1);
    if (!t) r.fail(node, prefix, "expected a table");
    spec.exercises.push_back(read_exercise(r, *t, prefix, difficulty, spec.language, node));
  }
  // every exercise's number, given or derived, and none twice: a question id names one question
  std::vector<std::string> numbers;
  for (std::size_t i = 0; i < spec.exercises.size(); ++i) numbers.push_back(exercise_id(spec, i));
  for (std::size_t i = 0; i < numbers.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (numbers[i] == numbers[j])
        r.fail(*array->get(i), fmt::format("exercise[{}]", i + 1),
               fmt::format("its number {} is exercise[{}]'s too: give one of them another `number`", numbers[i], j + 1));
  for (std::size_t i = 0; i < numbers.size(); ++i) spec.exercises[i].number = numbers[i];
  return spec;
}

SpecWords WorksheetSpec::words_in(std::string_view lang) const {
  SpecWords words{title, course, author, subject};
  const auto it = words_by_language.find(std::string(lang));
  if (it == words_by_language.end()) return words;
  for (auto field : {&SpecWords::title, &SpecWords::course, &SpecWords::author, &SpecWords::subject})
    if (!(it->second.*field).empty()) words.*field = it->second.*field;
  return words;
}

std::string ExerciseSpec::heading_in(std::string_view language) const {
  const auto it = heading_by_language.find(std::string(language));
  return it != heading_by_language.end() ? it->second : heading;
}

int exercise_number(const WorksheetSpec& spec, std::size_t slot) {
  int n = 1;
  for (std::size_t i = 0; i < slot && i < spec.exercises.size(); ++i)
    if (spec.exercises[i].heading.empty()) ++n;
  return n;
}

std::string exercise_id(const WorksheetSpec& spec, std::size_t slot) {
  const auto& e = spec.exercises.at(slot);
  if (!e.number.empty()) return e.number;
  if (e.heading.empty()) return std::to_string(exercise_number(spec, slot));
  const std::string place = std::to_string(slot + 1);
  for (std::size_t i = 0; i < spec.exercises.size(); ++i) {
    if (i == slot) continue;
    const auto& o = spec.exercises[i];
    // the numbers the others have without asking this one's (no recursion through headings)
    const std::string theirs = !o.number.empty() ? o.number
                               : o.heading.empty() ? std::to_string(exercise_number(spec, i))
                                                   : std::string();
    if (theirs == place) return "s" + place;
  }
  return place;
}

namespace {

// The built-in specs: their command-line name and the templates/ file they are read from, the
// course's first. The one table builtin_spec, builtin_specs and builtin_spec_names read.
struct BuiltinSpecFile {
  std::string_view name, file;
};
constexpr BuiltinSpecFile kBuiltinSpecs[] = {{"builtin", "course.toml"}, {"builtin:3d", "course-3d.toml"}};

const WorksheetSpec& parsed_builtin(std::size_t i) {
  static const std::vector<WorksheetSpec> specs = [] {
    std::vector<WorksheetSpec> all;
    for (const auto& b : kBuiltinSpecs)
      all.push_back(parse_spec(*embedded_file(b.file), fmt::format("templates/{}", b.file)));
    return all;
  }();
  return specs[i];
}

}  // namespace

WorksheetSpec builtin_spec() { return parsed_builtin(0); }

std::optional<WorksheetSpec> builtin_spec(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kBuiltinSpecs); ++i)
    if (kBuiltinSpecs[i].name == name) return parsed_builtin(i);
  return std::nullopt;
}

std::vector<WorksheetSpec> builtin_specs() {
  std::vector<WorksheetSpec> specs;
  for (std::size_t i = 0; i < std::size(kBuiltinSpecs); ++i) specs.push_back(parsed_builtin(i));
  return specs;
}

std::vector<std::string> builtin_spec_names() {
  std::vector<std::string> names;
  for (const auto& b : kBuiltinSpecs) names.emplace_back(b.name);
  return names;
}

}  // namespace epure
