#include "grading/method_grader.h"

#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>

#include "support/agrees.h"
#include "grading/review.h"

namespace epure::grading {

namespace {

using method::AnswerType;
using method::Recorded;
using method::Traced;

// The student's readable answers, as the method reads them.
class GivenFromReview final : public method::GivenAnswers {
 public:
  explicit GivenFromReview(const ExerciseReview& r) : r_(r) {}
  std::optional<double> number(std::string_view field) const override { return r_.number(field); }
  std::optional<bool> boolean(std::string_view field) const override { return r_.boolean(field); }
  std::optional<std::string_view> word(std::string_view field) const override { return r_.word(field); }
  std::optional<method::FaceMask> faces(std::string_view field) const override { return r_.faces(field); }

 private:
  const ExerciseReview& r_;
};

// "t_proj d2": the answers a value was computed from, by name, in the kind's order. Marks keep
// a view of it (QuestionMark::from), so each spelling is kept once for the process.
std::string_view names_of(method::Deps deps, std::span<const method::QuestionDecl> decls) {
  std::string s;
  for (std::size_t i = 0; i < decls.size(); ++i)
    if (deps & (1u << i)) {
      if (!s.empty()) s += ' ';
      s += decls[i].field;
    }
  static std::mutex mutex;
  static std::set<std::string, std::less<>> pool;
  std::lock_guard lock(mutex);
  return *pool.insert(std::move(s)).first;
}

method::Deps bit_of(std::string_view field, std::span<const method::QuestionDecl> decls) {
  for (std::size_t i = 0; i < decls.size(); ++i)
    if (decls[i].field == field) return method::Deps(1u << i);
  return 0;
}

// Equal but for the last bits: a mistake that leaves an answer where it was says nothing of it.
bool unchanged(double a, double b) { return agrees(b, a); }

bool same_answer(const Recorded<Traced>& a, const Recorded<Traced>& b) {
  switch (a.type) {
    case AnswerType::number: return unchanged(a.x.v, b.x.v);
    case AnswerType::point: return unchanged(a.x.v, b.x.v) && unchanged(a.y.v, b.y.v);
    case AnswerType::boolean: return a.boolean == b.boolean;
    case AnswerType::choice: return a.word == b.word;
    case AnswerType::faces: return a.faces == b.faces;
  }
  return true;
}

// Follow-through: the answer is what the student's own earlier answers give.
bool follow(ExerciseReview& r, const Recorded<Traced>& a, std::string_view from, std::string_view code = {}) {
  switch (a.type) {
    case AnswerType::number: return r.follow(a.id, a.x.v, from, code);
    case AnswerType::point: return r.follow_point(a.id, {a.x.v, a.y.v}, from, code);
    case AnswerType::boolean: return r.follow_boolean(a.id, a.boolean, from, code);
    case AnswerType::choice: return r.follow_word(a.id, a.word, from, code);
    case AnswerType::faces: return r.follow_faces(a.id, a.faces, from, code);
  }
  return false;
}

// A named mistake: the answer is what the mistake gives.
bool name_mistake(ExerciseReview& r, const Recorded<Traced>& a, std::string_view code) {
  switch (a.type) {
    case AnswerType::number: return r.mistake(a.id, a.x.v, code);
    case AnswerType::point: return r.mistake_point(a.id, {a.x.v, a.y.v}, code);
    case AnswerType::boolean: return false;  // a yes/no answer is wrong, not diagnosed
    case AnswerType::choice: return r.mistake_word(a.id, a.word, code);
    case AnswerType::faces: return r.mistake_faces(a.id, a.faces, code);
  }
  return false;
}

const Recorded<Traced>* find(const std::vector<Recorded<Traced>>& run, std::string_view field) {
  for (const auto& a : run)
    if (a.id == field) return &a;
  return nullptr;
}

method::Deps deps_of(const Recorded<Traced>& a) {
  switch (a.type) {
    case AnswerType::number: return a.x.deps;
    case AnswerType::point: return a.x.deps | a.y.deps;
    default: return a.deps;
  }
}

class MethodGrader final : public KindGrader {
 public:
  explicit MethodGrader(const ExerciseKind& kind) : kind_(kind) {}

  std::string_view kind() const override { return kind_.name(); }
  std::any prepare(const nlohmann::json& instance) const override { return kind_.read_instance(instance); }
  std::vector<std::string_view> mistakes() const override {
    const auto m = kind_.mistakes();
    return {m.begin(), m.end()};
  }
  std::vector<DrawnField> drawn() const override { return kind_.drawn(); }

  // In the order of the method, for each answer still wrong: first, is it what the student's
  // own earlier answers give (follow-through)? Then, is it what a named mistake gives? A mistake
  // is counted once: named on the first answer it explains, it credits the later answers that
  // carry it on as follow-through.
  void review(const std::any& prepared, ExerciseReview& r) const override {
    const auto decls = kind_.questions();
    const auto codes = kind_.mistakes();
    const auto roads = kind_.roads();
    const GivenFromReview given(r);
    const int decimals = r.decimals();
    const auto base = kind_.evaluate(prepared, &given, {}, decimals);
    std::vector<std::vector<Recorded<Traced>>> road_runs, theirs, pure;
    for (auto road : roads) road_runs.push_back(kind_.evaluate(prepared, &given, road, decimals));
    // each mistake on the student's own earlier answers, and on the key's data alone (a wrong
    // answer next to right earlier ones: J given as I with a right t)
    for (auto code : codes) {
      theirs.push_back(kind_.evaluate(prepared, &given, code, decimals));
      pure.push_back(kind_.evaluate(prepared, nullptr, code, decimals));
    }
    const auto key_values = kind_.evaluate(prepared, nullptr, {}, decimals);
    std::map<std::string_view, std::string_view> named;  // mistake code → the answer it was named on

    auto is_open = [&](std::string_view id) {
      return r.open(id) || r.open(method::coordinate_name(id, 'x')) || r.open(method::coordinate_name(id, 'y'));
    };
    // follow-through, by the usual road or another right one
    auto follows = [&](const Recorded<Traced>* a) {
      if (!a) return false;
      const auto deps = deps_of(*a);
      return deps && follow(r, *a, names_of(deps, decls));
    };
    // the named mistake `k` explains the answer as `b` gives it
    // (counted once: an answer computed from the one the mistake was named on follows from it)
    auto explains = [&](std::size_t k, const Recorded<Traced>* b, const Recorded<Traced>* right) {
      if (!b || (right && same_answer(*b, *right))) return false;
      if (auto it = named.find(codes[k]); it != named.end() && (deps_of(*b) & bit_of(it->second, decls)))
        return follow(r, *b, it->second, codes[k]);
      if (!name_mistake(r, *b, codes[k])) return false;
      named.emplace(codes[k], b->id);
      return true;
    };

    for (const auto& a : base) {
      if (!is_open(a.id)) continue;
      if (follows(&a)) continue;
      bool done = false;
      for (std::size_t k = 0; k < road_runs.size() && !done; ++k) done = follows(find(road_runs[k], a.id));
      for (std::size_t k = 0; k < codes.size() && !done; ++k) done = explains(k, find(theirs[k], a.id), &a);
      for (std::size_t k = 0; k < codes.size() && !done; ++k)
        done = explains(k, find(pure[k], a.id), find(key_values, a.id));
    }
  }

 private:
  const ExerciseKind& kind_;
};

}  // namespace

const KindGrader* method_grader(const ExerciseKind& kind) {
  if (kind.questions().empty()) return nullptr;
  static std::mutex mutex;
  static std::map<const ExerciseKind*, std::unique_ptr<MethodGrader>> graders;
  std::lock_guard lock(mutex);
  auto& g = graders[&kind];
  if (!g) g = std::make_unique<MethodGrader>(kind);
  return g.get();
}

std::vector<const KindGrader*> all_graders() {
  std::vector<const KindGrader*> out;
  for (const auto* k : all_kinds())
    if (const auto* g = method_grader(*k)) out.push_back(g);
  return out;
}

const KindGrader* find_grader(std::string_view kind) {
  if (const auto* k = find_kind(kind)) return method_grader(*k);
  return nullptr;
}

}  // namespace epure::grading
