#include "exercises/points.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

namespace epure {

namespace {

// How far from a whole number of steps a total may be and still be that number (a spec
// total is written by hand: 2.5 and 0.75 are exact in binary, 0.1 steps would not be).
constexpr double kStepSlack = 1e-9;

}  // namespace

bool on_point_step(double points) {
  const double units = points / kPointStep;
  return std::abs(units - std::round(units)) <= kStepSlack;
}

void spread_points(std::vector<Question>& questions, double total) {
  if (questions.empty()) return;
  // The items that share: a question, or a point group (its coordinates together).
  struct Item {
    std::vector<std::size_t> members;
    double weight = 0;
    long long units = 0;
    double remainder = 0;
  };
  std::vector<Item> items;
  for (std::size_t i = 0; i < questions.size(); ++i) {
    const Question& q = questions[i];
    auto it = q.point_group.empty() ? items.end()
                                    : std::find_if(items.begin(), items.end(), [&](const Item& item) {
                                        return questions[item.members.front()].point_group == q.point_group;
                                      });
    if (it == items.end()) {
      items.push_back({{i}, 0, 0, 0});
      it = items.end() - 1;
    } else {
      it->members.push_back(i);
    }
    it->weight += std::max(0.0, q.points);
  }
  double weights = 0;
  for (const auto& item : items) weights += item.weight;
  if (!(weights > 0)) {
    for (auto& item : items) item.weight = 1;
    weights = static_cast<double>(items.size());
  }
  const long long units = std::llround(std::max(0.0, total) / kPointStep);
  // A point's coordinates get equal shares: its units go two by two.
  auto quantum = [&](const Item& item) { return static_cast<long long>(item.members.size()); };
  long long given = 0;
  for (auto& item : items) {
    const double ideal = static_cast<double>(units) * item.weight / weights;
    const long long q = quantum(item);
    item.units = static_cast<long long>(std::floor(ideal / static_cast<double>(q))) * q;
    item.remainder = ideal - static_cast<double>(item.units);
    given += item.units;
  }
  // The units left go to the largest remainders first (ties: the question asked first), each
  // item taking its quantum while that fits; what no quantum fits is given unit by unit.
  std::vector<std::size_t> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return items[a].remainder > items[b].remainder; });
  long long left = units - given;
  for (std::size_t k = 0; left > 0 && k < order.size(); ++k) {
    Item& item = items[order[k]];
    if (quantum(item) <= left) {
      item.units += quantum(item);
      left -= quantum(item);
    }
  }
  std::vector<long long> share(questions.size(), 0);
  for (const auto& item : items) {
    const long long q = quantum(item);
    for (std::size_t m = 0; m < item.members.size(); ++m) share[item.members[m]] = item.units / q;
  }
  // an odd unit no point can take whole: to the first coordinate of the largest remainder
  for (std::size_t k = 0; left > 0 && k < order.size(); ++k, --left) share[items[order[k]].members.front()] += 1;
  for (std::size_t i = 0; i < questions.size(); ++i) questions[i].points = static_cast<double>(share[i]) * kPointStep;
}

bool ticked(const Question& q) { return !std::holds_alternative<double>(q.expected); }

namespace {

// The pool shared across a sheet. A tick gets its work's share rounded down to a quarter (at
// least a quarter), so ticks of equal weight get equal points and rounding never makes what can
// be read off the figure worth more than its work; the computed answers share the rest by
// largest remainder. Where that cannot hold (no computed answer, or a total too small to give
// every tick a quarter) everything shares the pool by largest remainder alone.
void spread_pool(std::vector<Question>& questions, double total) {
  const long long units = std::llround(std::max(0.0, total) / kPointStep);
  double weights = 0;
  for (const Question& q : questions) weights += std::max(0.0, q.points);
  std::vector<Question> computed;
  long long tick_units = 0;
  std::vector<long long> tick_share(questions.size(), -1);
  for (std::size_t i = 0; i < questions.size(); ++i) {
    const Question& q = questions[i];
    if (!ticked(q)) {
      computed.push_back(q);
      continue;
    }
    const double w = std::max(0.0, q.points);
    const double ideal = weights > 0 ? static_cast<double>(units) * w / weights : 0;
    tick_share[i] = w > 0 ? std::max(1LL, static_cast<long long>(std::floor(ideal + kStepSlack))) : 0;
    tick_units += tick_share[i];
  }
  if (computed.empty() || !(weights > 0) || tick_units > units) {
    spread_points(questions, total);
    return;
  }
  spread_points(computed, static_cast<double>(units - tick_units) * kPointStep);
  std::size_t k = 0;
  for (std::size_t i = 0; i < questions.size(); ++i)
    questions[i].points = tick_share[i] >= 0 ? static_cast<double>(tick_share[i]) * kPointStep : computed[k++].points;
}

}  // namespace

void spread_sheet_points(std::vector<ExerciseInstance>& exercises, const std::vector<std::optional<double>>& fixed,
                         double pool) {
  std::vector<Question> pooled;
  for (std::size_t e = 0; e < exercises.size(); ++e) {
    if (e < fixed.size() && fixed[e]) {
      spread_points(exercises[e].questions, *fixed[e]);
      continue;
    }
    for (const Question& q : exercises[e].questions) {
      pooled.push_back(q);
      // "I" of exercise 3 and "I" of exercise 4 are two points: groups are named per exercise
      if (!q.point_group.empty()) pooled.back().point_group = fmt::format("{}\x1f{}", e, q.point_group);
    }
  }
  spread_pool(pooled, pool);
  std::size_t k = 0;
  for (std::size_t e = 0; e < exercises.size(); ++e) {
    if (e < fixed.size() && fixed[e]) continue;
    for (Question& q : exercises[e].questions) q.points = pooled[k++].points;
  }
}

}  // namespace epure
