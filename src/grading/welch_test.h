#pragma once
// Is one group's mean lower than another's by more than chance? Welch's two-sample t-test
// (unequal variances), one-sided, as item analysis asks it of a branch of an exercise against
// the other branches of that exercise (item_analysis.h).
//
//   t  = (m₂ − m₁) / √(s₁²/n₁ + s₂²/n₂)                       (group 1 the one tested lower)
//   ν  = (s₁²/n₁ + s₂²/n₂)² / ((s₁²/n₁)²/(n₁−1) + (s₂²/n₂)²/(n₂−1))   (Welch–Satterthwaite)
//   p  = P(T_ν ≥ t)                                            (Student's t with ν degrees)
//
// The t distribution's tail is the regularised incomplete beta function,
// P(T_ν ≥ t) = ½·I_{ν/(ν+t²)}(ν/2, ½) for t ≥ 0, evaluated by its continued fraction (Lentz's
// method, as in Numerical Recipes §6.4), to about 1e-13. Hand-written rather than taken from
// Boost.Math (students_t_distribution, Debian's libboost-math-dev): one function of thirty lines
// against a 180 MB header package in every CI install; GSL's gsl_cdf_tdist_Q is GPL. It is
// checked against an independent numerical integration of the t density in
// tests/tools/item_analysis.py and against table values in tests/grading/welch_test_test.cpp.
#include <optional>

namespace epure::grading {

// Regularised incomplete beta I_x(a, b), for a, b > 0 and x in [0, 1].
double incomplete_beta(double a, double b, double x);

// P(T ≥ t) for Student's t with `df` > 0 degrees of freedom (df need not be a whole number).
double student_t_upper(double t, double df);

struct WelchResult {
  double t = 0;
  double df = 0;
  double p = 1;  // one-sided: the chance of a difference at least this large if the means were equal
};

// The test that group 1 (n₁ values of mean m₁ and sample variance v₁) has a lower mean than
// group 2. Nothing when a group has fewer than 2 values. Both variances 0: p is 0 when m₁ < m₂
// (every value of group 1 below every value of group 2), else 1.
std::optional<WelchResult> welch_lower(double n1, double m1, double v1, double n2, double m2, double v2);

}  // namespace epure::grading
