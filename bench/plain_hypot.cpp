// Measurement only (geometry_bench_plain_hypot): defines libm's hypot in the executable, so the
// geometry kernels call this one. √(x² + y²) overflows beyond 1e154 and is not correctly
// rounded; it tells what the careful hypot costs, nothing more.
#include <cmath>

extern "C" double hypot(double x, double y) noexcept { return std::sqrt(x * x + y * y); }
