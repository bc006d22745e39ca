#include "exercises/schedule.h"

#include <stdexcept>

#include "exercises/rng.h"

namespace epure {

BranchSchedule::BranchSchedule(std::vector<std::pair<std::string, double>> weights, std::uint64_t seed)
    : weights_(std::move(weights)), current_(weights_.size(), 0.0) {
  // zero-weight branches never come up: drop them so the arithmetic below stays exact
  std::erase_if(weights_, [](const auto& w) { return !(w.second > 0); });
  current_.assign(weights_.size(), 0.0);
  if (weights_.empty()) throw std::invalid_argument("a branch schedule needs a positive weight");
  offset_ = static_cast<int>(mix64(seed) % 997);
}

void BranchSchedule::step() {
  double total = 0;
  int best = 0;
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    current_[i] += weights_[i].second;
    total += weights_[i].second;
    if (current_[i] > current_[best]) best = static_cast<int>(i);  // ties: the first listed
  }
  current_[best] -= total;
  sequence_.push_back(best);
}

const std::string& BranchSchedule::at(int index) {
  const auto step_index = static_cast<std::size_t>(index + offset_);
  while (sequence_.size() <= step_index) step();
  return weights_[sequence_[step_index]].first;
}

}  // namespace epure
