// Pearson's chi-square goodness-of-fit test as used by pbrt and Mitsuba for sampling routines:
// cells with expected count < 5 are pooled, p-value from the regularized incomplete gamma.
#pragma once
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace gdr::test {

// Regularized lower incomplete gamma P(a, x) (series for x < a + 1, else continued fraction;
// Numerical Recipes 6.2), to double precision.
inline double gamma_p(double a, double x) {
  if (x <= 0.0) return 0.0;
  double gln = std::lgamma(a);
  if (x < a + 1.0) {
    double ap = a, sum = 1.0 / a, del = sum;
    for (int n = 0; n < 100000; ++n) {
      ap += 1.0;
      del *= x / ap;
      sum += del;
      if (std::fabs(del) < std::fabs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - gln);
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < 1e-15) break;
  }
  return 1.0 - std::exp(-x + a * std::log(x) - gln) * h;
}

struct Chi2Result {
  double statistic = 0.0;
  int dof = 0;
  double p_value = 1.0;
  std::string error;  // non-empty: samples where the pdf says none can be
};

// observed / expected counts per cell; `total` samples were drawn.
inline Chi2Result chi2_test(const std::vector<double>& observed,
                            const std::vector<double>& expected, double total,
                            double min_expected = 5.0) {
  Chi2Result r;
  std::vector<size_t> order(observed.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double pooled_obs = 0.0, pooled_exp = 0.0;
  int cells = 0;
  for (size_t i : order) {
    if (expected[i] <= 0.0) {
      if (observed[i] > total * 1e-5) {
        std::ostringstream s;
        s << "cell " << i << ": " << observed[i] << " samples where the pdf integrates to 0";
        r.error = s.str();
      }
      pooled_obs += observed[i];
    } else if (expected[i] < min_expected || (pooled_exp > 0.0 && pooled_exp < min_expected)) {
      pooled_obs += observed[i];
      pooled_exp += expected[i];
    } else {
      r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
      ++cells;
    }
  }
  if (pooled_exp > 0.0) {
    r.statistic += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
    ++cells;
  }
  r.dof = cells - 1;
  r.p_value = r.dof > 0 ? 1.0 - gamma_p(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
  return r;
}

}  // namespace gdr::test
