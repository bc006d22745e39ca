#include "grading/method_grader.h"

#include <array>
#include <deque>
#include <functional>
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

// One answer as the sheet asks it: a number, a decision, a word, a set of faces, a point in the
// plane (one recorded answer), or a point in space (three recorded numbers of one group, which a
// slip moves as a whole: v∧u for u∧v changes all three components, and is one mistake).
struct Unit {
  std::array<const Recorded<Traced>*, 3> part{};
  std::size_t size = 0;

  explicit operator bool() const { return size > 0; }
  const Recorded<Traced>& first() const { return *part[0]; }
  bool in_space() const { return !first().group.empty(); }
  // the name the review knows it by: the field, or the point's group
  std::string_view name() const { return in_space() ? first().group : first().id; }
  method::Deps deps() const {
    method::Deps d = 0;
    for (std::size_t k = 0; k < size; ++k) d |= deps_of(*part[k]);
    return d;
  }
  std::array<double, 3> values() const {
    std::array<double, 3> v{};
    for (std::size_t k = 0; k < size; ++k) v[k] = part[k]->x.v;
    return v;
  }
  bool same(const Unit& o) const {
    if (o.size != size) return false;
    for (std::size_t k = 0; k < size; ++k)
      if (!same_answer(*part[k], *o.part[k])) return false;
    return true;
  }
};

// The run's answers as units, in the method's order.
std::vector<Unit> units_of(const std::vector<Recorded<Traced>>& run) {
  std::vector<Unit> out;
  for (std::size_t i = 0; i < run.size();) {
    Unit u;
    u.part[u.size++] = &run[i];
    while (!run[i].group.empty() && i + u.size < run.size() && u.size < 3 && run[i + u.size].group == run[i].group)
      u.part[u.size] = &run[i + u.size], ++u.size;
    i += u.size;
    out.push_back(u);
  }
  return out;
}

// The unit of `run` that answers what `like` answers, or an empty one when the run did not reach
// it (a mistake can change the branch).
Unit same_unit(const std::vector<Recorded<Traced>>& run, const Unit& like) {
  Unit u;
  for (std::size_t k = 0; k < like.size; ++k) {
    const auto* a = find(run, like.part[k]->id);
    if (!a) return {};
    u.part[u.size++] = a;
  }
  return u;
}

// Follow-through: the answer is what the student's own earlier answers give.
bool follow(ExerciseReview& r, const Unit& u, std::string_view from, std::string_view code = {}) {
  if (u.in_space()) {
    const auto v = u.values();
    return r.follow_point(u.name(), std::span<const double>(v.data(), u.size), from, code);
  }
  const auto& a = u.first();
  switch (a.type) {
    case AnswerType::number: return r.follow(a.id, a.x.v, from, code);
    case AnswerType::point: return r.follow_point(a.id, {a.x.v, a.y.v}, from, code);
    case AnswerType::boolean: return r.follow_boolean(a.id, a.boolean, from, code);
    case AnswerType::choice: return r.follow_word(a.id, a.word, from, code);
    case AnswerType::faces: return r.follow_faces(a.id, a.faces, from, code);
  }
  return false;
}

// A named mistake: the answer is what the mistake gives (a point: every coordinate of it).
bool name_mistake(ExerciseReview& r, const Unit& u, std::string_view code) {
  if (u.in_space()) {
    const auto v = u.values();
    return r.mistake_point(u.name(), std::span<const double>(v.data(), u.size), code);
  }
  const auto& a = u.first();
  switch (a.type) {
    case AnswerType::number: return r.mistake(a.id, a.x.v, code);
    case AnswerType::point: return r.mistake_point(a.id, {a.x.v, a.y.v}, code);
    case AnswerType::boolean: return false;  // a yes/no answer is wrong, not diagnosed
    case AnswerType::choice: return r.mistake_word(a.id, a.word, code);
    case AnswerType::faces: return r.mistake_faces(a.id, a.faces, code);
  }
  return false;
}

// Whether what the student gave for `u` fits the value `theirs` records (blank fits anything).
bool student_fits(const ExerciseReview& r, const Unit& u, const Unit& theirs) {
  if (u.in_space()) {
    const auto v = theirs.values();
    return r.fits_point(u.name(), std::span<const double>(v.data(), theirs.size));
  }
  const auto& a = theirs.first();
  switch (a.type) {
    case AnswerType::number: return r.fits(a.id, a.x.v);
    case AnswerType::point: {
      const double xy[2] = {a.x.v, a.y.v};
      return r.fits_point(a.id, xy);
    }
    case AnswerType::boolean: return true;
    case AnswerType::choice: {
      const auto w = r.word(a.id);
      return !w || *w == a.word;
    }
    case AnswerType::faces: {
      const auto f = r.faces(a.id);
      return !f || *f == a.faces;
    }
  }
  return true;
}

using Answers = std::vector<Recorded<Traced>>;

// Runs of the method made on first use, by index (a road, a mistake).
class Lazy {
 public:
  template <class Make>
  Lazy(std::size_t n, Make make) : runs_(n), make_(std::move(make)) {}
  std::size_t size() const { return runs_.size(); }
  const Answers& operator[](std::size_t k) {
    if (!runs_[k]) runs_[k] = &own_.emplace_back(make_(k));
    return *runs_[k];
  }

 private:
  std::vector<const Answers*> runs_;
  std::deque<Answers> own_;  // stable addresses
  std::function<Answers(std::size_t)> make_;
};

// The method's runs on the key's data alone, without the student's answers (the key's values,
// and each named mistake made on them): they depend on the instance only, so a sheet's rows
// share them. Made on first use, for the `decimals` a grading asks.
class KeyRuns {
 public:
  const Answers& run(const ExerciseKind& kind, const std::any& data, method::Switches switches, int decimals) const {
    std::lock_guard lock(mutex_);
    const auto key = std::pair{switches.mistake, switches.road};
    auto it = runs_.find(key);
    if (it == runs_.end()) it = runs_.emplace(key, kind.evaluate(data, nullptr, switches, decimals)).first;
    return it->second;  // a std::map's elements stay where they are
  }

 private:
  mutable std::mutex mutex_;
  // Keyed by views, not copies (a lookup per review must not allocate): a mistake's and a
  // road's names are views into the kind's static tables (ExerciseKind::mistakes(), roads()) or
  // the empty literal, which outlive every key.json read.
  mutable std::map<std::pair<std::string_view, std::string_view>, Answers> runs_;
};

// What prepare() makes of an instance: the kind's reading of it, and the runs on its data alone.
struct PreparedExercise {
  explicit PreparedExercise(std::any d) : data(std::move(d)) {}
  std::any data;

  const KeyRuns& key_runs(int decimals) const {
    std::lock_guard lock(mutex_);
    return by_decimals_[decimals];
  }

 private:
  mutable std::mutex mutex_;
  mutable std::map<int, KeyRuns> by_decimals_;
};

class MethodGrader final : public KindGrader {
 public:
  explicit MethodGrader(const ExerciseKind& kind) : kind_(kind) {}

  std::string_view kind() const override { return kind_.name(); }
  std::any prepare(const nlohmann::json& instance) const override {
    return std::make_shared<const PreparedExercise>(kind_.read_instance(instance));
  }
  std::vector<std::string_view> mistakes() const override {
    const auto m = kind_.mistakes();
    return {m.begin(), m.end()};
  }
  std::vector<DrawnField> drawn() const override { return kind_.drawn(); }

  // In the order of the method, for each answer still wrong: first, is it what the student's
  // own earlier answers give (follow-through)? Then, is it what a named mistake gives? A mistake
  // is named on an answer only where the student's own earlier answers that answer was computed
  // from agree with it (never against their own right answers: u_c given right, t is not "u_c
  // renormalised"). A mistake is counted once: named on the first answer it explains (a point as
  // a whole), it credits the later answers that carry it on as follow-through.
  void review(const std::any& prepared_any, ExerciseReview& r) const override {
    const auto& prepared = *std::any_cast<const std::shared_ptr<const PreparedExercise>&>(prepared_any);
    const std::any& data = prepared.data;
    const auto decls = kind_.questions();
    const auto codes = kind_.mistakes();
    const auto roads = kind_.roads();
    const GivenFromReview given(r);
    const int decimals = r.decimals();
    const auto base = kind_.evaluate(data, &given, {}, decimals);
    // The other runs are made when first asked: most wrong answers are settled by
    // follow-through or by the first mistakes tried. Those on the key's data alone are the
    // instance's, made once for every row of the sheet (PreparedExercise).
    // the usual road (0) and each other right road the kind declares (1…)
    const std::size_t n_roads = roads.size() + 1;
    auto road = [&](std::size_t j) { return j == 0 ? std::string_view{} : roads[j - 1]; };
    Lazy road_runs(roads.size(), [&](std::size_t j) { return kind_.evaluate(data, &given, {"", roads[j]}, decimals); });
    auto right_on = [&](std::size_t j) -> const Answers& { return j == 0 ? base : road_runs[j - 1]; };
    // each mistake on each road, on the student's own earlier answers, and on the key's data
    // alone (a wrong answer next to blank earlier ones: J given as I, t not given)
    Lazy theirs(n_roads * codes.size(), [&](std::size_t jk) {
      return kind_.evaluate(data, &given, {codes[jk % codes.size()], road(jk / codes.size())}, decimals);
    });
    const KeyRuns& alone = prepared.key_runs(decimals);
    auto key_on = [&](std::size_t j) -> const Answers& { return alone.run(kind_, data, {"", road(j)}, decimals); };
    auto pure = [&](std::size_t k, std::size_t j) -> const Answers& {
      return alone.run(kind_, data, {codes[k], road(j)}, decimals);
    };
    const std::vector<Unit> units = units_of(base);
    struct Named {
      method::Deps bits;        // the answers it was named on
      std::string_view names;   // the same, by name
    };
    std::map<std::string_view, Named> named;  // mistake code → where it was named

    auto bits_of = [&](const Unit& u) {
      method::Deps b = 0;
      for (std::size_t k = 0; k < u.size; ++k) b |= bit_of(u.part[k]->id, decls);
      return b;
    };
    auto is_open = [&](const Unit& u) {
      for (std::size_t k = 0; k < u.size; ++k) {
        const auto id = u.part[k]->id;
        if (r.open(id) || r.open(method::coordinate_name(id, 'x')) || r.open(method::coordinate_name(id, 'y')))
          return true;
      }
      return false;
    };
    // follow-through, by the usual road or another right one
    auto follows = [&](const Unit& u) {
      if (!u) return false;
      const auto deps = u.deps();
      return deps && follow(r, u, names_of(deps, decls));
    };
    // whether the student's own earlier answers that `at` (the i-th unit) is computed from agree
    // with the mistake's run: each one the mistake moves (from where `right` has it) was either
    // left blank or given as the mistake gives it
    auto consistent = [&](std::size_t at, const std::vector<Recorded<Traced>>& run,
                          const std::vector<Recorded<Traced>>& right) {
      const method::Deps from = units[at].deps();
      for (std::size_t e = 0; e < at; ++e) {
        const Unit& earlier = units[e];
        if (earlier.first().type == AnswerType::boolean || !(bits_of(earlier) & from)) continue;
        const Unit wrong = same_unit(run, earlier), usual = same_unit(right, earlier);
        if (!wrong || !usual || wrong.same(usual)) continue;
        if (!student_fits(r, earlier, wrong)) return false;
      }
      return true;
    };
    // the named mistake `k` explains the `at`-th answer as `run` gives it, where `right` gives
    // the answer without the mistake (counted once: an answer computed from the one the mistake
    // was named on follows from it)
    auto explains = [&](std::size_t k, std::size_t at, const std::vector<Recorded<Traced>>& run,
                        const std::vector<Recorded<Traced>>& right) {
      const Unit b = same_unit(run, units[at]), usual = same_unit(right, units[at]);
      if (!b || (usual && b.same(usual))) return false;
      // An answer computed from the one the mistake was named on, by the road taken or by the
      // usual one, carries it on: d² by the course's cross product does not go through t_proj,
      // but the usual road's d² does, and both carry the same unnormalised û. (t_ab and t_cd
      // swapped are two slips of one name: neither is computed from the other.)
      if (auto it = named.find(codes[k]); it != named.end() && ((b.deps() | units[at].deps()) & it->second.bits))
        return follow(r, b, it->second.names, codes[k]);
      // (the student's answer fitting the mistake first: the cheap test, which most fail)
      if (!student_fits(r, units[at], b) || !consistent(at, run, right) || !name_mistake(r, b, codes[k]))
        return false;
      const method::Deps bits = bits_of(units[at]);
      named.emplace(codes[k], Named{bits, names_of(bits, decls)});
      return true;
    };

    for (std::size_t i = 0; i < units.size(); ++i) {
      const Unit& a = units[i];
      if (!is_open(a)) continue;
      if (follows(a)) continue;
      bool done = false;
      for (std::size_t j = 0; j < road_runs.size() && !done; ++j) done = follows(same_unit(road_runs[j], a));
      // the mistakes on the usual road first, then on each other one (û left unnormalised, then
      // d² by the course's cross product)
      for (std::size_t j = 0; j < n_roads && !done; ++j)
        for (std::size_t k = 0; k < codes.size() && !done; ++k)
          done = explains(k, i, theirs[j * codes.size() + k], right_on(j));
      for (std::size_t j = 0; j < n_roads && !done; ++j)
        for (std::size_t k = 0; k < codes.size() && !done; ++k) done = explains(k, i, pure(k, j), key_on(j));
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
