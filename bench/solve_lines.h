#pragma once
// A fixed, reproducible mix of valid `epure solve` input lines, as worksheets and other tools
// write them: every kind in turn; data mostly small integers and tenths (what a worksheet
// draws), a third full-precision doubles (what a program writes); half compact, half with
// Python's default ", " and ": " separators; rays aimed near the figure two times in three, so
// that hits and misses mix as on a worksheet. Shared by solve_bench and solve_input.
#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>

#include "exercises/rng.h"

namespace epure::bench {

class SolveLines {
 public:
  explicit SolveLines(std::uint64_t seed) : rng_(seed, 3) {}

  static constexpr int kKinds = 9;
  // The kind line(k) writes, for a benchmark's label.
  static constexpr std::string_view kNames[kKinds] = {"vectors",       "projection", "segments",
                                                      "ray_circle",    "ray_square", "ray_ellipse",
                                                      "ray_rectangle", "ray_sphere", "ray_cube"};

  // The next line of kind `kind` (0..8, in the contract's order), without its newline.
  std::string line(int kind) {
    out_.clear();
    spaced_ = rng_.chance(0.5);
    full_ = rng_.chance(1.0 / 3);
    const int dim = kind >= 7 ? 3 : 2;
    const auto A = point(dim), B = other(A, dim), C = point(dim), D = other(C, dim);
    // Figures with a centre C at the origin for the canonical square and cube.
    const auto target = kind == 4 || kind == 8 ? Vec{} : C;
    const auto u = direction(A, target, dim);
    out_ += '{';
    key("kind", false);
    switch (kind) {
      case 0: str("vectors"); vec("u", u, 2); vec("v", other(Vec{}, 2), 2); break;
      case 1: str("projection"); vec("A", A, 2); vec("B", B, 2); vec("C", C, 2); break;
      case 2: str("segments"); vec("A", A, 2); vec("B", B, 2); vec("C", C, 2); vec("D", D, 2); break;
      case 3: str("ray_circle"); vec("A", A, 2); vec("u", u, 2); vec("C", C, 2); num("r", size()); break;
      case 4: str("ray_square"); vec("A", A, 2); vec("u", u, 2); break;
      case 5:
        str("ray_ellipse"); vec("A", A, 2); vec("u", u, 2); vec("C", C, 2);
        vec("radii", {size(), size()}, 2); num("angle", angle());
        break;
      case 6:
        str("ray_rectangle"); vec("A", A, 2); vec("u", u, 2); vec("C", C, 2);
        vec("half", {size(), size()}, 2); num("angle", angle());
        break;
      case 7: str("ray_sphere"); vec("A", A, 3); vec("u", u, 3); vec("C", C, 3); num("r", size()); break;
      default: str("ray_cube"); vec("A", A, 3); vec("u", u, 3); break;
    }
    out_ += '}';
    return out_;
  }

 private:
  using Vec = std::array<double, 3>;

  // A coordinate in [-6, 6]: an integer, a tenth, or any double.
  double coordinate() {
    if (full_) return rng_.uniform(-6, 6);
    if (rng_.chance(0.5)) return static_cast<double>(rng_.integer(-6, 6));
    return static_cast<double>(rng_.integer(-60, 60)) / 10;
  }
  double size() {
    if (full_) return rng_.uniform(0.5, 4);
    return static_cast<double>(rng_.integer(5, 40)) / 10;
  }
  double angle() {
    return full_ ? rng_.uniform(-180, 180) : static_cast<double>(rng_.integer(-12, 12) * 15);
  }
  Vec point(int dim) { return {coordinate(), coordinate(), dim == 3 ? coordinate() : 0.0}; }
  // A second point, never equal to the first: every line must be valid.
  Vec other(const Vec& p, int dim) {
    for (;;) {
      Vec q = point(dim);
      if (q != p) return q;
    }
  }
  // Towards the target, give or take, two times in three; anywhere else otherwise. Never zero.
  Vec direction(const Vec& from, const Vec& target, int dim) {
    for (;;) {
      Vec u = point(dim);
      if (rng_.chance(2.0 / 3))
        for (int k = 0; k < 3; ++k) u[k] = target[k] - from[k] + u[k] / 4;
      if (!full_)  // keep worksheet data short: tenths
        for (double& x : u) x = static_cast<double>(static_cast<long>(x * 10)) / 10;
      if (u != Vec{}) return u;
    }
  }

  void key(std::string_view k, bool comma = true) {
    if (comma) out_ += spaced_ ? ", " : ",";
    out_ += '"';
    out_ += k;
    out_ += spaced_ ? "\": " : "\":";
  }
  void str(std::string_view s) {
    out_ += '"';
    out_ += s;
    out_ += '"';
  }
  void number(double x) { fmt::format_to(std::back_inserter(out_), "{}", x); }
  void num(std::string_view k, double x) {
    key(k);
    number(x);
  }
  void vec(std::string_view k, const Vec& v, int n) {
    key(k);
    out_ += '[';
    for (int i = 0; i < n; ++i) {
      if (i) out_ += spaced_ ? ", " : ",";
      number(v[i]);
    }
    out_ += ']';
  }

  Rng rng_;
  std::string out_;
  bool spaced_ = false, full_ = false;
};

}  // namespace epure::bench
