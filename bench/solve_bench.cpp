// `epure solve` in process: ns per line of solve::solve_line (reading the JSON, solving, writing
// the result), per kind and on the mixed stream that solve_bench.sh times end to end. Each
// benchmark cycles through 4096 lines of solve_lines.h, one line per iteration.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "solve/solve.h"
#include "solve_lines.h"

namespace {

constexpr std::size_t kBatch = 4096;

// kind < 0: every kind in turn, as in the end-to-end file.
std::vector<std::string> lines_of(int kind) {
  epure::bench::SolveLines draw(2024);
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < kBatch; ++i)
    lines.push_back(draw.line(kind >= 0 ? kind : static_cast<int>(i % epure::bench::SolveLines::kKinds)));
  return lines;
}

void solve_line(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  const auto lines = lines_of(kind);
  fmt::memory_buffer out;
  std::size_t i = 0, failed = 0;
  for (auto _ : state) {
    failed += !epure::solve::solve_line(lines[i], out).empty();
    benchmark::DoNotOptimize(out.data());
    if (out.size() > (1 << 16)) out.clear();
    i = (i + 1) & (kBatch - 1);
  }
  if (failed) state.SkipWithError("a benchmark line failed: solve_lines.h draws valid lines only");
  state.SetLabel(kind >= 0 ? std::string(epure::bench::SolveLines::kNames[kind]) : "mixed");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

BENCHMARK(solve_line)->DenseRange(-1, epure::bench::SolveLines::kKinds - 1);

}  // namespace

BENCHMARK_MAIN();
