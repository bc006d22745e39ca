// solve_input N [SEED]: writes N valid, mixed `epure solve` lines to stdout (see solve_lines.h),
// every kind in turn, the same bytes for the same N and seed on every machine.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "solve_lines.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: solve_input N [SEED]\n");
    return 2;
  }
  const long n = std::atol(argv[1]);
  const unsigned long long seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 2024;
  epure::bench::SolveLines lines(seed);
  std::string buffer;
  for (long i = 0; i < n; ++i) {
    buffer += lines.line(static_cast<int>(i % epure::bench::SolveLines::kKinds));
    buffer += '\n';
    if (buffer.size() > (1 << 16)) {
      std::fwrite(buffer.data(), 1, buffer.size(), stdout);
      buffer.clear();
    }
  }
  std::fwrite(buffer.data(), 1, buffer.size(), stdout);
  return 0;
}
