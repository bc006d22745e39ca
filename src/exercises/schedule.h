#pragma once
// Which branch each sheet of a set draws, for one exercise. Smooth weighted round-robin (the
// nginx scheme): over any run of consecutive sheets each branch appears in proportion to its
// weight, to within one sheet, so a class set of 30 under the default weights shows every
// branch and neighbours in a room rarely share one. The sequence does not depend on the size of
// the set (sheet i's branch is the same in a set of 30 or 3,000), and the seed rotates where it
// starts so that two sets do not begin alike.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace epure {

class BranchSchedule {
 public:
  BranchSchedule(std::vector<std::pair<std::string, double>> weights, std::uint64_t seed);

  // The branch of sheet `index` (≥ 0). Cheap for increasing indices; any index works.
  const std::string& at(int index);

 private:
  void step();
  std::vector<std::pair<std::string, double>> weights_;
  std::vector<double> current_;
  std::vector<int> sequence_;  // branch index per step, computed so far
  int offset_ = 0;
};

}  // namespace epure
