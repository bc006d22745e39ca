// The branch schedule: exact proportions over runs of sheets, every branch in a class of 30,
// independence from the size of the set.
#include <doctest/doctest.h>

#include <map>

#include "exercises/schedule.h"

TEST_CASE("branches come at their weights' rates, within one sheet over any prefix") {
  for (std::uint64_t seed : {1ULL, 2ULL, 99ULL, 123456ULL}) {
    CAPTURE(seed);
    epure::BranchSchedule s({{"hit", 3}, {"behind", 1}, {"miss", 1}, {"inside", 1}}, seed);
    std::map<std::string, int> count;
    for (int i = 0; i < 600; ++i) {
      ++count[s.at(i)];
      const double n = i + 1;
      // smooth weighted round-robin keeps every count within ±1 of its share (plus the rotation)
      CHECK(std::abs(count["hit"] - n * 3 / 6) <= 2.0);
      CHECK(std::abs(count["miss"] - n / 6) <= 2.0);
    }
  }
}

TEST_CASE("a class set of 30 shows every branch under the default weights") {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    CAPTURE(seed);
    epure::BranchSchedule s({{"before", 1}, {"between", 2}, {"after", 1}}, seed);
    std::map<std::string, int> count;
    for (int i = 0; i < 30; ++i) ++count[s.at(i)];
    CHECK(count.size() == 3);
  }
}

TEST_CASE("sheet i's branch does not depend on the order of the questions asked") {
  epure::BranchSchedule a({{"x", 1}, {"y", 2}}, 5), b({{"x", 1}, {"y", 2}}, 5);
  std::vector<std::string> forward;
  for (int i = 0; i < 100; ++i) forward.push_back(a.at(i));
  for (int i = 99; i >= 0; --i) CHECK(b.at(i) == forward[i]);
}

TEST_CASE("zero weights never come up") {
  epure::BranchSchedule s({{"a", 1}, {"b", 0}, {"c", 1}}, 1);
  for (int i = 0; i < 50; ++i) CHECK(s.at(i) != "b");
  CHECK_THROWS(epure::BranchSchedule({{"a", 0}}, 1));
}
