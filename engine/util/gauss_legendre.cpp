#include "util/gauss_legendre.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gdr {

GaussLegendre gauss_legendre(int n, double a, double b) {
  if (n < 1 || n > 1024)
    throw std::invalid_argument("gauss_legendre: n = " + std::to_string(n) + " outside 1 .. 1024");
  GaussLegendre g;
  g.nodes.assign(n, 0.0);
  g.weights.assign(n, 0.0);
  double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  // Newton's method on P_n from the Chebyshev guess; the roots are symmetric about 0.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; the recurrence climbs to P_n (p1) and P_{n-1} (p0)
      for (int k = 2; k <= n; ++k) {
        double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      double step = p1 / dp;
      x -= step;
      if (std::fabs(step) <= 1e-15) break;
    }
    double w = 2.0 / ((1 - x * x) * dp * dp);
    g.nodes[i] = mid - half * x;
    g.nodes[n - 1 - i] = mid + half * x;
    g.weights[i] = g.weights[n - 1 - i] = half * w;
  }
  return g;
}

}  // namespace gdr
