#pragma once
// Which branch each sheet of a set draws, for all its exercises at once, so that every sheet
// asks about the same work (issue 31: a student who draws a short branch on one exercise draws a
// long one on another). Each exercise's BranchSchedule still decides how many sheets draw each
// branch; the balance only decides which sheet gets which. It works on fixed blocks of kBlock
// consecutive sheets: inside a block, each exercise's branches start in its schedule's own
// interleaved order, then swaps of two sheets' branches, exercise by exercise (the one whose
// branches differ most in work first), bring the farther of the two sheets closer to the
// block's mean work. So sheet i's branches depend on its block alone, never on the size of the
// set (a set of 30 and one of 3,000 share their first 30 sheets), and any sheet is found
// in constant time. Deterministic: sums of multiples of 0.5 are exact in doubles.
#include <string>
#include <vector>

#include "exercises/schedule.h"

namespace epure {

class BranchBalance {
 public:
  // 16 sheets hold every branch of the course's kinds in proportion (weights up to 6 in all) at
  // least twice, enough for the swaps to even out the work (tests/exercises/sheet_points_test.cpp:
  // within 10 % of the set's mean on every sheet); a larger block moves branches further from
  // the schedule's order.
  static constexpr int kBlock = 16;

  // One schedule per exercise. `work[slot]` gives the work of each branch by name, in the
  // schedule's order of names or any; a branch it does not list (or an empty list: an exercise
  // whose points are fixed) weighs nothing and keeps the schedule's sheets.
  BranchBalance(std::vector<BranchSchedule> schedules, std::vector<std::vector<std::pair<std::string, double>>> work);

  // The branch exercise `slot` of sheet `index` (≥ 0) draws.
  const std::string& at(int index, int slot);

 private:
  double work(int slot, const std::string& branch) const;
  void compute(int block);

  std::vector<BranchSchedule> schedules_;
  std::vector<std::vector<std::pair<std::string, double>>> work_;
  int block_ = -1;                              // the block computed last
  std::vector<std::vector<std::string>> chosen_;  // [sheet in block][slot]
};

}  // namespace epure
