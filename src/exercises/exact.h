#pragma once
// Exact answers for the hand-computable levels: rationals and quadratic surds (p + q√c)/d. The
// generator computes them from the integer data independently of the double core, and a sheet
// is only issued when both agree: the exact value is a second, independent computation of every
// answer that has one.
//
// Arithmetic is on 64-bit integers with 128-bit intermediates; a result that would overflow
// throws ExactOverflow, and the answer is then simply given without an exact form.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace epure::exact {

// 128-bit intermediates (a GCC/Clang extension, hence __extension__ for -Wpedantic).
__extension__ typedef __int128 Wide;

struct ExactOverflow : std::overflow_error {
  ExactOverflow() : std::overflow_error("exact value out of 64-bit range") {}
};

class Rational {
 public:
  constexpr Rational() = default;
  Rational(std::int64_t n, std::int64_t d = 1);  // throws std::domain_error for d = 0

  std::int64_t num() const { return num_; }
  std::int64_t den() const { return den_; }
  double value() const { return static_cast<double>(num_) / static_cast<double>(den_); }
  bool is_zero() const { return num_ == 0; }
  bool is_integer() const { return den_ == 1; }
  int sign() const { return (num_ > 0) - (num_ < 0); }

  friend Rational operator+(Rational a, Rational b);
  friend Rational operator-(Rational a, Rational b);
  friend Rational operator*(Rational a, Rational b);
  friend Rational operator/(Rational a, Rational b);  // throws std::domain_error for b = 0
  friend Rational operator-(Rational a) { return Rational(-a.num_, a.den_); }
  friend bool operator==(Rational a, Rational b) { return a.num_ == b.num_ && a.den_ == b.den_; }
  friend bool operator<(Rational a, Rational b);

  // If this rational is the square of a rational, its square root.
  std::optional<Rational> sqrt() const;

 private:
  static Rational from_wide(Wide n, Wide d);
  std::int64_t num_ = 0, den_ = 1;
};

// a + b·√c with c a square-free integer ≥ 2, or b = 0 (then c is 1 by convention).
class Surd {
 public:
  Surd(Rational a = {}) : a_(a), b_(0), c_(1) {}
  Surd(Rational a, Rational b, std::int64_t c);  // reduces √c: √12 = 2√3

  // √r for r ≥ 0: rational when r is a square, else (p/q)√c.
  static Surd sqrt(Rational r);

  Rational a() const { return a_; }
  Rational b() const { return b_; }
  std::int64_t c() const { return c_; }
  bool is_rational() const { return b_.is_zero(); }
  double value() const;

  // Surds combine when their radicands agree (or one is rational); else ExactOverflow-like
  // std::domain_error: the caller drops the exact form.
  friend Surd operator+(const Surd& x, const Surd& y);
  friend Surd operator-(const Surd& x, const Surd& y);
  friend Surd operator*(const Surd& x, const Surd& y);
  friend Surd operator/(const Surd& x, Rational r);
  friend Surd operator-(const Surd& x) { return Surd(-x.a_, -x.b_, x.c_); }

  // (p + q√c)/d over a common denominator, ASCII, for machines: "1/4", "(5-2*sqrt(2))/3",
  // "-sqrt(3)/2", "3*sqrt(5)".
  std::string machine() const;
  // The same for people: "(5 − 2√2)/3", "−√3/2" (integers only: no decimal separator).
  std::string pretty() const;

 private:
  Rational a_, b_;
  std::int64_t c_;
};

}  // namespace epure::exact
