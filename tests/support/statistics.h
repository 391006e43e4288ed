// Statistics for tests: Student's t distribution (for comparing means whose variances are
// estimated from a few independent runs) and the Šidák correction for many simultaneous tests.
#pragma once
#include <cmath>
#include <vector>

namespace gdr::test {

// Two-sided tail probability P(|T| > t) of Student's t with `dof` degrees of freedom, by
// integrating the density (Simpson's rule; accurate to ~1e-9 for the ranges tests use).
inline double student_t_two_sided_p(double t, double dof) {
  t = std::fabs(t);
  double c = std::exp(std::lgamma((dof + 1) / 2) - std::lgamma(dof / 2)) / std::sqrt(dof * M_PI);
  auto density = [&](double x) { return c * std::pow(1 + x * x / dof, -(dof + 1) / 2); };
  const int n = 20000;  // even
  double h = t / n, sum = density(0) + density(t);
  for (int i = 1; i < n; ++i) sum += density(i * h) * (i % 2 ? 4 : 2);
  double central = sum * h / 3;  // P(0 < T < t)
  return std::max(0.0, 1.0 - 2.0 * central);
}

// Per-test significance that keeps the family-wise false-positive rate at `alpha` over `tests`
// independent tests.
inline double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

struct MeanVar {
  double mean = 0;
  double var_of_mean = 0;  // variance of the mean (sample variance / n)
};

inline MeanVar mean_and_variance(const std::vector<double>& x) {
  MeanVar r;
  double n = static_cast<double>(x.size());
  for (double v : x) r.mean += v;
  r.mean /= n;
  double ss = 0;
  for (double v : x) ss += (v - r.mean) * (v - r.mean);
  r.var_of_mean = n > 1 ? ss / (n - 1) / n : 0;
  return r;
}

// Welch's t-test of equal means: returns the two-sided p-value.
inline double welch_p(const std::vector<double>& a, const std::vector<double>& b) {
  MeanVar ma = mean_and_variance(a), mb = mean_and_variance(b);
  double se2 = ma.var_of_mean + mb.var_of_mean;
  if (se2 <= 0) return ma.mean == mb.mean ? 1.0 : 0.0;
  double t = (ma.mean - mb.mean) / std::sqrt(se2);
  double na = double(a.size()), nb = double(b.size());
  double dof = se2 * se2 / (ma.var_of_mean * ma.var_of_mean / (na - 1) + mb.var_of_mean * mb.var_of_mean / (nb - 1));
  return student_t_two_sided_p(t, dof);
}

}  // namespace gdr::test
