// The explorer's core natively, per view: the time of one pointer move as the page makes it
// (explorer.h's drag, then view_parts with the frame held still), over a scripted drag of every handle
// (the browser test's path: 12 moves of (3, −2) figure units, from each handle). Prints the
// median and the 95th percentile per view, in microseconds. Not a test: a measure of the core's
// part of a frame (README, explore-timings), to profile natively (perf record build/explore_bench).
//   explore_bench [ROUNDS]
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "explore/explorer.h"

int main(int argc, char** argv) {
  namespace ex = epure::explore;
  using nlohmann::json;
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 5;
  for (const auto& k : json::parse(ex::kinds())) {
    const std::string kind = k.get<std::string>();
    std::vector<double> us;
    for (int round = 0; round < rounds; ++round) {
      const std::string start = ex::starting_instance(kind);
      const json v0 = json::parse(ex::view(start, "en"));
      for (const auto& h : v0["handles"]) {
        std::string instance = start;
        std::string frame = v0["frame"].dump();
        const double x = h["x"].get<double>(), y = h["y"].get<double>();
        for (int i = 1; i <= 12; ++i) {
          const auto t0 = std::chrono::steady_clock::now();
          const std::string next = ex::drag(instance, h["id"].get<std::string>(), x + 3 * i, y - 2 * i, frame, false);
          const ex::ViewParts shown = next != instance ? ex::view_parts(next, "en", 1, frame) : ex::ViewParts{};
          const auto t1 = std::chrono::steady_clock::now();
          us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
          if (shown.head.empty()) continue;
          const json v = json::parse(shown.head);
          if (!v.contains("error")) instance = v["instance"].get<std::string>();
        }
      }
    }
    std::sort(us.begin(), us.end());
    const auto q = [&](double p) { return us.empty() ? 0.0 : us[std::min(us.size() - 1, std::size_t(p * us.size()))]; };
    std::printf("%-14s %4zu moves  median %8.1f us  p95 %8.1f us\n", kind.c_str(), us.size(), q(0.5), q(0.95));
  }
}
