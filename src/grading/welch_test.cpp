#include "grading/welch_test.h"

#include <algorithm>
#include <cmath>

namespace epure::grading {

namespace {

// The continued fraction of I_x(a, b) (modified Lentz), converging for x < (a + 1)/(a + b + 2).
double beta_fraction(double a, double b, double x) {
  constexpr int kMaxTerms = 400;
  constexpr double kEpsilon = 1e-15;
  constexpr double kTiny = 1e-300;  // keeps a denominator off zero
  const double qab = a + b, qap = a + 1, qam = a - 1;
  double c = 1, d = 1 - qab * x / qap;
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1 / d;
  double h = d;
  for (int m = 1; m <= kMaxTerms; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1 + aa * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1 + aa * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1) < kEpsilon) break;
  }
  return h;
}

}  // namespace

double incomplete_beta(double a, double b, double x) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  // x^a (1−x)^b / B(a, b), in logarithms
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2)) return front * beta_fraction(a, b, x) / a;
  return 1 - front * beta_fraction(b, a, 1 - x) / b;  // I_x(a, b) = 1 − I_{1−x}(b, a)
}

double student_t_upper(double t, double df) {
  if (std::isnan(t)) return NAN;
  if (std::isinf(t)) return t > 0 ? 0 : 1;
  const double tail = 0.5 * incomplete_beta(df / 2, 0.5, df / (df + t * t));
  return t >= 0 ? tail : 1 - tail;
}

std::optional<WelchResult> welch_lower(double n1, double m1, double v1, double n2, double m2, double v2) {
  if (n1 < 2 || n2 < 2) return std::nullopt;
  const double e1 = std::max(v1, 0.0) / n1, e2 = std::max(v2, 0.0) / n2;
  WelchResult r;
  if (e1 + e2 == 0) {  // guards the division: both groups constant
    r.t = m1 < m2 ? INFINITY : 0;
    r.df = n1 + n2 - 2;
    r.p = m1 < m2 ? 0 : 1;
    return r;
  }
  r.t = (m2 - m1) / std::sqrt(e1 + e2);
  r.df = (e1 + e2) * (e1 + e2) / (e1 * e1 / (n1 - 1) + e2 * e2 / (n2 - 1));
  r.p = student_t_upper(r.t, r.df);
  return r;
}

}  // namespace epure::grading
