// The balanced draw: each block of sheets keeps its exercises' scheduled branches (only which
// sheet gets which changes), a block's sheets end up close in work, and it is deterministic.
// The works and weights are the 2D course's (tick 0.5, number 2, point 2).
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <string>

#include "exercises/balance.h"

namespace {

using Work = std::vector<std::vector<std::pair<std::string, double>>>;

std::vector<epure::BranchSchedule> schedules(std::uint64_t seed) {
  return {epure::BranchSchedule({{"intersects", 2}, {"outside", 1}, {"parallel", 1}}, seed),
          epure::BranchSchedule({{"hit", 3}, {"behind", 1}, {"miss", 1}, {"inside", 1}}, seed + 1),
          epure::BranchSchedule({{"hit", 3}, {"miss", 1}, {"inside", 1}}, seed + 2),
          epure::BranchSchedule({{"hit", 2}, {"miss", 1}, {"inside", 1}}, seed + 3),
          epure::BranchSchedule({{"hit", 2}, {"miss", 1}, {"inside", 1}}, seed + 4),
          epure::BranchSchedule({{"acute", 2}, {"right", 1}, {"obtuse", 2}}, seed + 5)};
}

const Work kWork = {{{"intersects", 6.5}, {"outside", 5}, {"parallel", 1}},
                    {{"hit", 11}, {"behind", 3.5}, {"miss", 5.5}, {"inside", 11}},
                    {{"hit", 7.5}, {"miss", 1.5}, {"inside", 7.5}},
                    {{"hit", 11}, {"miss", 5}, {"inside", 11}},
                    {{"hit", 11}, {"miss", 5}, {"inside", 11}},
                    {}};  // the same work on every branch (the vectors), listed or not

double work_of(std::size_t slot, const std::string& branch) {
  for (const auto& [name, w] : kWork[slot])
    if (name == branch) return w;
  return 0;
}

}  // namespace

TEST_CASE("a block keeps its scheduled branches, evens out their work, the same every time") {
  constexpr int B = epure::BranchBalance::kBlock;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    CAPTURE(seed);
    auto plain = schedules(seed);
    epure::BranchBalance balance(schedules(seed), kWork), again(schedules(seed), kWork);
    for (int block = 0; block < 4; ++block) {
      std::vector<double> load(B, 0);
      for (std::size_t s = 0; s < plain.size(); ++s) {
        std::map<std::string, int> scheduled, drawn;
        for (int i = block * B; i < (block + 1) * B; ++i) {
          ++scheduled[plain[s].at(i)];
          const std::string& b = balance.at(i, static_cast<int>(s));
          ++drawn[b];
          CHECK(b == again.at(i, static_cast<int>(s)));
          load[static_cast<std::size_t>(i - block * B)] += work_of(s, b);
        }
        CHECK(scheduled == drawn);  // the proportions are the schedule's
      }
      for (double& l : load) l += 14;  // the vectors: the same on every sheet
      // every sheet of the block within 10 % of the block's mean work
      const auto [lo, hi] = std::minmax_element(load.begin(), load.end());
      double mean = 0;
      for (double l : load) mean += l;
      mean /= B;
      CHECK(*hi - mean <= 0.10 * mean);
      CHECK(mean - *lo <= 0.10 * mean);
    }
  }
  SUBCASE("any sheet alone, in any order: the same branches") {
    epure::BranchBalance forward(schedules(3), kWork), backward(schedules(3), kWork);
    std::vector<std::string> f, b;
    for (int i = 0; i < 3 * B; ++i) f.push_back(forward.at(i, 1));
    for (int i = 3 * B - 1; i >= 0; --i) b.push_back(backward.at(i, 1));
    std::reverse(b.begin(), b.end());
    CHECK(f == b);
  }
}
