#pragma once
// The one random generator of epure: PCG32 (O'Neill, pcg-random.org, the 64-bit state / 32-bit
// output variant pbrt uses), with our own mapping to ranges. The standard library's
// distributions differ between implementations; these functions are specified here, bit for
// bit, so that a spec and a seed give the same sheets on every platform.
//
// No global state: a generator is created from a seed and passed by reference.
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace epure {

class Rng {
 public:
  // `stream` selects one of 2^63 independent sequences for the same seed (one per sheet, one per
  // exercise), so that drawing more for one exercise never shifts another.
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) {
    inc_ = (stream << 1u) | 1u;
    state_ = 0;
    next_u32();
    state_ += seed;
    next_u32();
  }

  std::uint32_t next_u32() {
    std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
  }

  std::uint64_t next_u64() {
    std::uint64_t hi = next_u32();
    return (hi << 32) | next_u32();
  }

  // Uniform in [0, 1): the top 53 bits of a 64-bit draw, scaled exactly.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  // Uniform integer in [lo, hi] (both included, at most 2^32 values), without modulo bias:
  // Lemire's multiply-and-reject on 32-bit draws.
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    const std::uint64_t range = static_cast<std::uint64_t>(hi - lo) + 1;
    if (hi < lo || range > (1ULL << 32)) throw std::invalid_argument("Rng::integer: bad range");
    const std::uint64_t threshold = ((1ULL << 32) - range) % range;  // 2^32 mod range
    for (;;) {
      const std::uint64_t m = std::uint64_t(next_u32()) * range;
      if ((m & 0xFFFFFFFFULL) >= threshold) return lo + static_cast<std::int64_t>(m >> 32);
    }
  }

  // True with probability p.
  bool chance(double p) { return uniform() < p; }

  // A derived seed for a child generator (a sheet's exercise), a pure function of this
  // generator's next draw.
  std::uint64_t split() { return next_u64(); }

 private:
  std::uint64_t state_ = 0, inc_ = 0;
};

// SplitMix64: a bijective mix of a 64-bit value, to turn (seed, sheet index, exercise) into
// well-spread generator seeds.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace epure
