#include "check/classify.h"

#include "check/judge.h"

namespace epure::check {

namespace {

struct Fit {
  std::size_t explained = 0;
  bool consistent = false;
};

Fit fit(Bugs bugs, const std::vector<Case>& cases, const std::vector<std::optional<Outcome>>& got,
        const std::vector<bool>& right) {
  Fit f;
  std::size_t model_wrong = 0, model_wrong_where_right = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (!got[i]) continue;
    const Outcome m = model(cases[i], bugs);
    if (!right[i] && agrees(cases[i], m, *got[i])) ++f.explained;
    if (!judge(cases[i], m).right) {
      ++model_wrong;
      if (right[i]) ++model_wrong_where_right;
    }
  }
  f.consistent = model_wrong > 0 && model_wrong_where_right * 20 <= model_wrong;
  return f;
}

}  // namespace

Classification classify(Fn fn, const std::vector<Case>& cases, const std::vector<std::optional<Outcome>>& got,
                        const std::vector<bool>& right) {
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (got[i] && !right[i]) ++wrong;
  Classification best;
  if (wrong == 0) return best;
  const auto candidates = bugs_of(fn);
  auto consider = [&](std::vector<Bug> set) {
    Bugs bits = 0;
    for (Bug b : set) bits |= bit(b);
    const Fit f = fit(bits, cases, got, right);
    if (!f.consistent || f.explained == 0 || f.explained * 10 < wrong * 9) return;
    if (f.explained > best.explained) best = {std::move(set), f.explained};
  };
  for (Bug b : candidates) consider({b});
  if (!best.bugs.empty()) return best;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t j = i + 1; j < candidates.size(); ++j) consider({candidates[i], candidates[j]});
  return best;
}

}  // namespace epure::check
