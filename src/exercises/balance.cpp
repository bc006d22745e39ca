#include "exercises/balance.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace epure {

namespace {

// Works are sums of a few multiples of 0.5 and 1: a swap must gain more than rounding to count.
constexpr double kWorkSlack = 1e-9;
// Each pass swaps only where the pair gets strictly closer to the mean, so passes end; this
// bounds them all the same.
constexpr int kImprovePasses = 8;

}  // namespace

BranchBalance::BranchBalance(std::vector<BranchSchedule> schedules,
                             std::vector<std::vector<std::pair<std::string, double>>> work)
    : schedules_(std::move(schedules)), work_(std::move(work)) {
  work_.resize(schedules_.size());
}

double BranchBalance::work(int slot, const std::string& branch) const {
  for (const auto& [name, w] : work_[static_cast<std::size_t>(slot)])
    if (name == branch) return w;
  return 0;
}

void BranchBalance::compute(int block) {
  const int slots = static_cast<int>(schedules_.size());
  const int base = block * kBlock;
  // the schedule's branches for the block, and their work
  std::vector<std::vector<std::string>> scheduled(static_cast<std::size_t>(slots));
  std::vector<std::vector<double>> weight(static_cast<std::size_t>(slots));
  std::vector<double> spread(static_cast<std::size_t>(slots), 0);
  for (int s = 0; s < slots; ++s) {
    for (int i = 0; i < kBlock; ++i) {
      scheduled[s].push_back(schedules_[s].at(base + i));
      weight[s].push_back(work(s, scheduled[s].back()));
    }
    const auto [lo, hi] = std::minmax_element(weight[s].begin(), weight[s].end());
    spread[s] = *hi - *lo;
  }
  // Start from the schedule's own order (it interleaves the branches, so neighbours in a room
  // rarely share one and a short set shows every branch), then even the work out by swaps only.
  // Sorting the branches by work and dealing them to the lightest sheets instead evened the work
  // as well but put equal branches on consecutive sheets.
  std::vector<int> order(static_cast<std::size_t>(slots));
  std::iota(order.begin(), order.end(), 0);
  // the exercises whose branches differ most first: their swaps move the most work
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return spread[a] > spread[b]; });
  chosen_.assign(kBlock, std::vector<std::string>(static_cast<std::size_t>(slots)));
  std::vector<double> load(kBlock, 0);
  for (int s = 0; s < slots; ++s)
    for (int i = 0; i < kBlock; ++i) {
      chosen_[i][s] = scheduled[s][i];
      load[i] += weight[s][i];
    }
  // Swaps, exercise by exercise, of two sheets' branches wherever that brings the farther of the
  // two closer to the block's mean; a bounded number of passes, in a fixed order.
  const double mean = std::accumulate(load.begin(), load.end(), 0.0) / kBlock;
  auto off = [&](double x) { return std::abs(x - mean); };
  // weight[s][i] follows chosen_[i][s] through the swaps, so the loop compares no names.
  for (int pass = 0, swapped = 1; swapped && pass < kImprovePasses; ++pass) {
    swapped = 0;
    for (const int s : order)
      for (int i = 0; i < kBlock; ++i)
        for (int j = i + 1; j < kBlock; ++j) {
          double& wi = weight[s][i];
          double& wj = weight[s][j];
          if (std::abs(wi - wj) <= kWorkSlack) continue;  // the same work: a swap moves nothing
          const double li = load[i] - wi + wj, lj = load[j] - wj + wi;
          if (std::max(off(li), off(lj)) + kWorkSlack < std::max(off(load[i]), off(load[j]))) {
            std::swap(chosen_[i][s], chosen_[j][s]);
            std::swap(wi, wj);
            load[i] = li;
            load[j] = lj;
            swapped = 1;
          }
        }
  }
  block_ = block;
}

const std::string& BranchBalance::at(int index, int slot) {
  const int block = index / kBlock;
  if (block != block_) compute(block);
  return chosen_[index % kBlock][slot];
}

}  // namespace epure
