// The explorer's core natively, per view: the time of one pointer move as the page makes it
// (explorer.h's drag, then view_parts with the frame held still), over a scripted drag of every handle
// (the browser test's path: 12 moves of (3, −2) figure units, from each handle). Prints the
// median and the 95th percentile per view, in microseconds. Not a test: a measure of the core's
// part of a frame (README, explore-timings), to profile natively (perf record build/explore_bench).
// Then a hash of every text the core returns over more drags (both languages, snapped or not, in
// height mode, the keyboard's nudges, the whole view), untimed: a change meant to make the core
// faster must leave it as it was.
//   explore_bench [ROUNDS [KIND]]      the timings
//   explore_bench hash                 the hashes
// Instructions per move: valgrind --tool=callgrind --toggle-collect='*one_move*' explore_bench 1 KIND
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "explore/explorer.h"

namespace {

namespace ex = epure::explore;
using nlohmann::json;

// One pointer move as the page makes it; apart, so that a profiler can count it alone.
[[gnu::noinline]] ex::ViewParts one_move(const std::string& instance, const std::string& handle, double x, double y,
                                         const std::string& frame) {
  const std::string next = ex::drag(instance, handle, x, y, frame, false);
  return next != instance ? ex::view_parts(next, "en", 1, frame) : ex::ViewParts{};
}

// FNV-1a, 64 bits.
struct Hash {
  std::uint64_t h = 14695981039346656037ull;
  void add(std::string_view s) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xff) * 1099511628211ull;  // a separator
  }
};

std::uint64_t views_hash(const std::string& kind) {
  Hash hash;
  const std::string start = ex::starting_instance(kind);
  for (const char* lang : {"en", "fr"})
    for (bool snap : {false, true})
      for (bool height : {false, true}) {
        const json v0 = json::parse(ex::view(start, lang));
        hash.add(ex::view(start, lang, 3));
        for (const auto& h : v0["handles"]) {
          std::string instance = start;
          const std::string frame = v0["frame"].dump(), id = h["id"].get<std::string>();
          const double x = h["x"].get<double>(), y = h["y"].get<double>();
          for (int i = 1; i <= 12; ++i) {
            instance = ex::drag(instance, id, x + 3.3 * i, y - 2.1 * i * (i % 3 == 0 ? -1 : 1), frame, snap, height);
            hash.add(instance);
            const ex::ViewParts p = ex::view_parts(instance, lang, 1, frame);
            hash.add(p.head), hash.add(p.svg), hash.add(p.steps);
            for (const auto& d : {std::array{1, 0, 0}, std::array{0, -1, 0}, std::array{0, 0, 1}})
              hash.add(ex::nudge(instance, id, d[0], d[1], d[2], snap));
          }
          hash.add(ex::view(instance, lang));
        }
      }
  return hash.h;
}

}  // namespace

int main(int argc, char** argv) {
  const bool hash = argc > 1 && std::string_view(argv[1]) == "hash";
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 5;
  const std::string only = argc > 2 ? argv[2] : "";
  for (const auto& k : json::parse(ex::kinds())) {
    const std::string kind = k.get<std::string>();
    if (!only.empty() && kind != only) continue;
    if (hash) {
      std::printf("%-14s views %016llx\n", kind.c_str(), static_cast<unsigned long long>(views_hash(kind)));
      continue;
    }
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
          const ex::ViewParts shown = one_move(instance, h["id"].get<std::string>(), x + 3 * i, y - 2 * i, frame);
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
