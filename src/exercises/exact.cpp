#include "exercises/exact.h"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

namespace epure::exact {

namespace {

Wide gcd128(Wide a, Wide b) {
  if (a < 0) a = -a;
  if (b < 0) b = -b;
  // most operands fit 64 bits: the same gcd without 128-bit divisions (a call each)
  if (a <= Wide(UINT64_MAX) && b <= Wide(UINT64_MAX)) return std::gcd(static_cast<std::uint64_t>(a), static_cast<std::uint64_t>(b));
  while (b != 0) {
    Wide t = a % b;
    a = b;
    b = t;
  }
  return a;
}

constexpr Wide kMax = INT64_MAX;

std::int64_t isqrt(std::int64_t n) {
  auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n)));
  while (r > 0 && r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}

}  // namespace

Rational Rational::from_wide(Wide n, Wide d) {
  if (d == 0) throw std::domain_error("division by zero");
  if (d < 0) {
    n = -n;
    d = -d;
  }
  Wide g = gcd128(n, d);
  if (g > 1) {
    n /= g;
    d /= g;
  }
  if (n > kMax || n < -kMax || d > kMax) throw ExactOverflow();
  Rational r;
  r.num_ = static_cast<std::int64_t>(n);
  r.den_ = static_cast<std::int64_t>(d);
  return r;
}

Rational::Rational(std::int64_t n, std::int64_t d) { *this = from_wide(n, d); }

Rational operator+(Rational a, Rational b) {
  return Rational::from_wide(Wide(a.num_) * b.den_ + Wide(b.num_) * a.den_,
                             Wide(a.den_) * b.den_);
}
Rational operator-(Rational a, Rational b) { return a + (-b); }
Rational operator*(Rational a, Rational b) {
  return Rational::from_wide(Wide(a.num_) * b.num_, Wide(a.den_) * b.den_);
}
Rational operator/(Rational a, Rational b) {
  if (b.num_ == 0) throw std::domain_error("division by zero");
  return Rational::from_wide(Wide(a.num_) * b.den_, Wide(a.den_) * b.num_);
}
bool operator<(Rational a, Rational b) {
  return Wide(a.num_) * b.den_ < Wide(b.num_) * a.den_;
}

std::optional<Rational> Rational::sqrt() const {
  if (num_ < 0) return std::nullopt;
  std::int64_t p = isqrt(num_), q = isqrt(den_);
  if (p * p != num_ || q * q != den_) return std::nullopt;
  return Rational(p, q);
}

Surd::Surd(Rational a, Rational b, std::int64_t c) : a_(a), b_(b), c_(c) {
  if (c < 0) throw std::domain_error("negative radicand");
  if (b_.is_zero() || c_ <= 1) {
    if (c_ == 1) a_ = a_ + b_;
    b_ = Rational(0);
    c_ = 1;
    return;
  }
  // pull square factors out of c: √(k²m) = k√m
  std::int64_t k = 1;
  for (std::int64_t f = 2; f * f <= c_; ++f)
    while (c_ % (f * f) == 0) {
      c_ /= f * f;
      k *= f;
    }
  b_ = b_ * Rational(k);
  if (c_ == 1) {
    a_ = a_ + b_;
    b_ = Rational(0);
  }
}

Surd Surd::sqrt(Rational r) {
  if (r.sign() < 0) throw std::domain_error("square root of a negative number");
  if (auto s = r.sqrt()) return Surd(*s);
  // √(n/d) = √(n·d)/d
  const Wide nd = Wide(r.num()) * r.den();
  if (nd > kMax) throw ExactOverflow();
  return Surd(Rational(0), Rational(1, r.den()), static_cast<std::int64_t>(nd));
}

double Surd::value() const {
  return a_.value() + b_.value() * std::sqrt(static_cast<double>(c_));
}

namespace {
std::int64_t common_radicand(const Surd& x, const Surd& y) {
  if (x.is_rational()) return y.c();
  if (y.is_rational() || x.c() == y.c()) return x.c();
  throw std::domain_error("surds with different radicands");
}
}  // namespace

Surd operator+(const Surd& x, const Surd& y) {
  return Surd(x.a_ + y.a_, x.b_ + y.b_, common_radicand(x, y));
}
Surd operator-(const Surd& x, const Surd& y) { return x + (-y); }
Surd operator*(const Surd& x, const Surd& y) {
  const std::int64_t c = common_radicand(x, y);
  // (a + b√c)(a' + b'√c) = aa' + bb'c + (ab' + a'b)√c
  return Surd(x.a_ * y.a_ + x.b_ * y.b_ * Rational(c), x.a_ * y.b_ + y.a_ * x.b_, c);
}
Surd operator/(const Surd& x, Rational r) { return Surd(x.a_ / r, x.b_ / r, x.c_); }

namespace {

struct Parts {  // (p + q√c)/d, d > 0
  std::int64_t p, q, c, d;
};

Parts parts(const Surd& s) {
  const Wide d = std::lcm(s.a().den(), s.b().den());
  if (d > kMax) throw ExactOverflow();
  const Wide p = Wide(s.a().num()) * (d / s.a().den());
  const Wide q = Wide(s.b().num()) * (d / s.b().den());
  if (p > kMax || p < -kMax || q > kMax || q < -kMax) throw ExactOverflow();
  return {static_cast<std::int64_t>(p), static_cast<std::int64_t>(q), s.c(),
          static_cast<std::int64_t>(d)};
}

// q√c written with `times` and `root` ("2*sqrt(3)" or "2√3"), sign excluded
std::string radical(std::int64_t q, std::int64_t c, bool ascii) {
  std::int64_t m = q < 0 ? -q : q;
  std::string r = ascii ? fmt::format("sqrt({})", c) : fmt::format("√{}", c);
  if (m == 1) return r;
  return ascii ? fmt::format("{}*{}", m, r) : fmt::format("{}{}", m, r);
}

std::string render(const Surd& s, bool ascii) {
  const Parts x = parts(s);
  const char* minus = ascii ? "-" : "−";
  std::string numerator;
  bool compound = false;
  if (x.q == 0) {
    numerator = x.p < 0 ? fmt::format("{}{}", minus, -x.p) : fmt::format("{}", x.p);
  } else if (x.p == 0) {
    numerator = (x.q < 0 ? std::string(minus) : std::string()) + radical(x.q, x.c, ascii);
  } else {
    const char* op = x.q < 0 ? (ascii ? "-" : " − ") : (ascii ? "+" : " + ");
    numerator = fmt::format("{}{}{}{}", x.p < 0 ? minus : "", x.p < 0 ? -x.p : x.p, op,
                            radical(x.q, x.c, ascii));
    compound = true;
  }
  if (x.d == 1) return numerator;
  return compound ? fmt::format("({})/{}", numerator, x.d) : fmt::format("{}/{}", numerator, x.d);
}

}  // namespace

std::string Surd::machine() const { return render(*this, true); }
std::string Surd::pretty() const { return render(*this, false); }

}  // namespace epure::exact
