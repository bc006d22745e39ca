#pragma once
// Exact arithmetic on doubles, in Shewchuk's manner ("Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997): a number is an expansion, a sum of
// doubles whose bits do not overlap, and sums and products of expansions are computed without
// any rounding error by TwoSum and the fma's TwoProduct. The sign of an expansion is the sign of
// its largest component, so every sign computed this way is the true sign of the polynomial of
// the data.
//
// This is the slow path of the filtered predicates (predicates.h): it runs only when a cheap
// floating-point evaluation cannot certify a sign, so it favours obvious correctness over speed
// (a growable vector, O(n·m) products). Exact barring overflow, and barring products that fall
// below 2^-969 (where the fma no longer returns a product's error exactly): the kernels bring
// their data near unit size by powers of two first, so this needs data spanning more than about
// 480 binary orders of magnitude within one figure.
#include <cmath>
#include <vector>

#include "geometry/exact.h"

namespace epure::geo::exact {

class Expansion {
 public:
  Expansion() = default;
  explicit Expansion(double x) {
    if (x != 0) c_.push_back(x);
  }
  // a·b exactly.
  static Expansion product(double a, double b) {
    const TwoTerm p = two_product(a, b);
    Expansion e;
    if (p.lo != 0) e.c_.push_back(p.lo);
    if (p.hi != 0) e.c_.push_back(p.hi);
    return e;
  }
  // b − a exactly.
  static Expansion difference(double b, double a) {
    const TwoTerm d = two_difference(b, a);
    Expansion e;
    if (d.lo != 0) e.c_.push_back(d.lo);
    if (d.hi != 0) e.c_.push_back(d.hi);
    return e;
  }

  Expansion operator+(const Expansion& f) const {
    Expansion r = *this;
    for (double x : f.c_) r.grow(x);
    r.compress();
    return r;
  }
  Expansion operator-() const {
    Expansion r = *this;
    for (double& x : r.c_) x = -x;
    return r;
  }
  Expansion operator-(const Expansion& f) const { return *this + (-f); }
  Expansion operator*(const Expansion& f) const {
    Expansion r;
    for (double a : c_)
      for (double b : f.c_) {
        const TwoTerm p = two_product(a, b);
        r.grow(p.lo);
        r.grow(p.hi);
      }
    r.compress();
    return r;
  }

  // −1, 0 or +1: the sign of the exact value.
  int sign() const { return c_.empty() ? 0 : c_.back() > 0 ? 1 : -1; }
  // The value to within about an ulp, of the exact value's sign (zero only when it is zero):
  // the components summed from the smallest, the largest last.
  double estimate() const {
    double s = 0;
    for (double x : c_) s += x;
    return s;
  }
  // estimate() and the rest of the value, to about ε² of it.
  TwoTerm two_term() const {
    double s = 0, lo = 0;
    for (double x : c_) {
      const TwoTerm t = two_sum(s, x);
      s = t.hi;
      lo += t.lo;
    }
    return two_sum(s, lo);
  }
  int size() const { return static_cast<int>(c_.size()); }

 private:
  // Adds one double exactly (Shewchuk's Grow-Expansion, zero components dropped): the
  // components stay non-overlapping and in increasing magnitude.
  void grow(double b) {
    if (b == 0) return;
    std::vector<double> out;
    out.reserve(c_.size() + 1);
    double q = b;
    for (double x : c_) {
      const TwoTerm s = two_sum(q, x);
      q = s.hi;
      if (s.lo != 0) out.push_back(s.lo);
    }
    if (q != 0) out.push_back(q);
    c_.swap(out);
  }
  // Shewchuk's Compress: the same value in as few components as it takes, the largest one
  // within an ulp of the whole.
  void compress() {
    const int n = size();
    if (n < 2) return;
    std::vector<double> g(c_.begin(), c_.end());
    int bottom = n - 1;
    double q = g[bottom];
    for (int i = n - 2; i >= 0; --i) {
      const double s = q + g[i];
      const double lo = g[i] - (s - q);  // fast TwoSum: |q| ≥ |g[i]| by the ordering
      if (lo != 0) {
        g[bottom--] = s;
        q = lo;
      } else {
        q = s;
      }
    }
    g[bottom] = q;
    std::vector<double> h;
    h.reserve(n);
    q = g[bottom];
    for (int i = bottom + 1; i < n; ++i) {
      const double s = g[i] + q;
      const double lo = q - (s - g[i]);
      if (lo != 0) h.push_back(lo);
      q = s;
    }
    if (q != 0) h.push_back(q);
    c_.swap(h);
  }

  std::vector<double> c_;  // increasing magnitude, non-overlapping, no zeros
};

}  // namespace epure::geo::exact
