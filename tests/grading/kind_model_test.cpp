// Every kind written as one method (exercises/kind_method.h), run through the registry over every
// branch, difficulty and many seeds: the method agrees with the core (the build checks it and
// throws), exact forms evaluate to the value, perfect answers score full marks, every declared
// mistake is recognised with its code and has its feedback in both languages, and a chain after
// one wrong answer earns follow-through. Per-kind tests keep only literal cases.
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <variant>

#include "exercises/key_json.h"
#include "exercises/kind_support.h"
#include "exercises/texts.h"
#include "grading/answer_key.h"
#include "grading/expression.h"
#include "grading/marking.h"
#include "support/drawn_instances.h"

using namespace epure;

namespace {

constexpr int kSeeds = 12;

// The key of one generated instance, as grading reads it from key.json.
grading::ExerciseKey key_of(const ExerciseInstance& inst) {
  Sheet sheet{SheetId{kDrawVersion, 1, 0}, {inst}};
  fmt::memory_buffer buf;
  KeyJson::sheet(buf, sheet, true);
  return grading::read_sheet_json(nlohmann::json::parse(std::string(buf.data(), buf.size())), "test").exercises.at(0);
}

std::string cell_of(const Expected& e) {
  if (const double* x = std::get_if<double>(&e)) return fmt::format("{}", *x);
  if (const bool* b = std::get_if<bool>(&e)) return *b ? "yes" : "no";
  if (const std::string* w = std::get_if<std::string>(&e)) return *w;
  const auto& faces = std::get<std::vector<std::string>>(e);
  if (faces.empty()) return "none";
  std::string s;
  for (const auto& f : faces) {
    if (!s.empty()) s += ' ';
    s += f;
  }
  return s;
}

std::string faces_cell(method::FaceMask bits) {
  static constexpr const char* kNames[] = {"+x", "+y", "+z", "-x", "-y", "-z"};
  std::string s;
  for (int i = 0; i < 6; ++i)
    if (bits & (1u << i)) {
      if (!s.empty()) s += ' ';
      s += kNames[i];
    }
  return s.empty() ? "none" : s;
}

// A run's answers as cells for the key's questions ("I" gives "I.x" and "I.y"); blank where the
// run does not reach a question.
std::vector<std::string> cells_of(const grading::ExerciseKey& key, const std::vector<method::Recorded<method::Traced>>& run,
                                  int decimals = -1) {
  // written as they are, or rounded to `decimals` as a student writes them
  auto number = [decimals](double x) { return decimals < 0 ? fmt::format("{}", x) : fmt::format("{:.{}f}", x, decimals); };
  std::vector<std::string> cells(key.questions.size());
  for (const auto& a : run) {
    auto put = [&](std::string_view field, std::string text) {
      const int i = key.find(field);
      if (i >= 0) cells[static_cast<std::size_t>(i)] = std::move(text);
    };
    switch (a.type) {
      case method::AnswerType::number: put(a.id, number(a.x.v)); break;
      case method::AnswerType::point:
        put(method::coordinate_name(a.id, 'x'), number(a.x.v));
        put(method::coordinate_name(a.id, 'y'), number(a.y.v));
        break;
      case method::AnswerType::boolean: put(a.id, a.boolean ? "yes" : "no"); break;
      case method::AnswerType::choice: put(a.id, std::string(a.word)); break;
      case method::AnswerType::faces: put(a.id, faces_cell(a.faces)); break;
    }
  }
  return cells;
}

grading::ExerciseMarks mark(const grading::ExerciseKey& key, const std::vector<std::string>& cells) {
  std::vector<std::string_view> views(cells.begin(), cells.end());
  grading::MarkingOptions options;
  options.numbers = NumberStyle::for_language("en");
  grading::ExerciseMarks marks;
  grading::mark_exercise(key, views, options, marks);
  return marks;
}

double key_max(const grading::ExerciseKey& key) {
  double t = 0;
  for (const auto& q : key.questions) t += q.points;
  return t;
}

double total(const grading::ExerciseMarks& marks) {
  double t = 0;
  for (const auto& m : marks) t += m.points;
  return t;
}

// The student's answers as a map, for a Traced run on their own values.
class Given final : public method::GivenAnswers {
 public:
  std::map<std::string, double, std::less<>> numbers;
  std::optional<double> number(std::string_view f) const override {
    auto it = numbers.find(f);
    if (it == numbers.end()) return std::nullopt;
    return it->second;
  }
  std::optional<bool> boolean(std::string_view) const override { return std::nullopt; }
  std::optional<std::string_view> word(std::string_view) const override { return std::nullopt; }
  std::optional<method::FaceMask> faces(std::string_view) const override { return std::nullopt; }
};

}  // namespace

TEST_CASE("every kind written as a method: exact forms, full marks, named mistakes, follow-through") {
  int kinds_checked = 0;
  for (const ExerciseKind* kind : all_kinds()) {
    if (kind->questions().empty()) continue;
    ++kinds_checked;
    CAPTURE(kind->name());
    std::map<std::string_view, int> named;  // mistake code → instances where grading named it
    int chains = 0;
    test::for_each_drawn(*kind, kSeeds, 2, 7919u, 0, [&](const std::string&, Difficulty, int, const ExerciseInstance& inst) {
          const auto key = key_of(inst);

          // exact forms evaluate to the value
          for (const auto& q : inst.questions)
            if (q.exact) {
              const auto parsed = grading::parse_number(*q.exact);
              REQUIRE(parsed.ok);
              const double v = std::get<double>(q.expected);
              CHECK(std::abs(parsed.value - v) <= 1e-9 * std::max(1.0, std::abs(v)));
            }

          // perfect answers: full marks
          std::vector<std::string> perfect;
          for (const auto& q : inst.questions) perfect.push_back(cell_of(q.expected));
          const auto right = mark(key, perfect);
          CHECK(total(right) == doctest::Approx(key_max(key)).epsilon(1e-12));

          // every declared mistake, on the key's data: its wrong answers are named
          const auto data = kind->read_instance(nlohmann::json::parse(inst.instance));
          for (auto code : kind->mistakes()) {
            CAPTURE(code);
            const auto cells = cells_of(key, kind->evaluate(data, nullptr, code, 2));
            const auto marks = mark(key, cells);
            bool wrong = false, this_code = false;
            for (const auto& m : marks) {
              if (m.verdict == grading::Verdict::wrong) wrong = true;
              if (m.mistake == code) this_code = true;
            }
            if (this_code) ++named[code];
            // a mistake that changes an answer is never left unexplained
            if (wrong) {
              bool explained = false;
              for (const auto& m : marks) explained = explained || !m.mistake.empty();
              CHECK(explained);
            }
          }

          // follow-through: one numeric answer wrong, the later ones computed from it as the sheet
          // says (each value carried to 4 significant digits, the wrong one too; every answer
          // written to 2 decimals)
          const auto key_run = kind->evaluate(data, nullptr, {}, 2);
          for (std::size_t k = 0; k < key_run.size(); ++k) {
            if (key_run[k].type != method::AnswerType::number) continue;
            const int qi = key.find(key_run[k].id);
            if (qi < 0) continue;
            Given given;
            for (const auto& q : key.questions)
              if (q.type == grading::AnswerType::number) given.numbers[q.field] = q.number;
            const double wrong_value = method::carried(key.questions[qi].number + 4 * std::max(key.questions[qi].rule.abs, 0.01) + 0.05123);
            given.numbers[std::string(key_run[k].id)] = wrong_value;
            const auto theirs = kind->evaluate_as_told(data, 2, &given);
            // the same questions reached: their own values stay on the key's branch
            bool same_road = theirs.size() == key_run.size();
            for (std::size_t i = 0; same_road && i < theirs.size(); ++i) same_road = theirs[i].id == key_run[i].id;
            if (!same_road) continue;
            std::vector<std::string> cells = perfect;
            // later answers as the student computes them from their wrong one
            const auto later = cells_of(key, {theirs.begin() + static_cast<std::ptrdiff_t>(k) + 1, theirs.end()}, 2);
            for (std::size_t i = 0; i < cells.size(); ++i)
              if (!later[i].empty()) cells[i] = later[i];
            cells[static_cast<std::size_t>(qi)] = fmt::format("{:.2f}", wrong_value);
            const auto marks = mark(key, cells);
            CHECK(marks[static_cast<std::size_t>(qi)].verdict == grading::Verdict::wrong);
            CHECK(total(marks) == doctest::Approx(key_max(key) - key.questions[qi].points).epsilon(1e-9));
            ++chains;
            break;
          }
    });
    // every named mistake the kind declares is recognised somewhere, and explained in both
    // languages
    for (auto code : kind->mistakes()) {
      CAPTURE(code);
      CHECK(named[code] > 0);
      for (const char* lang : {"en", "fr"}) CHECK(Texts::builtin(lang).has(fmt::format("grading.mistake.{}", code)));
    }
    CHECK(chains > 0);
  }
  CHECK(kinds_checked >= 5);
}
