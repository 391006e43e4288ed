// Gauss-Legendre rules integrate polynomials up to degree 2n - 1 exactly, on any interval.
#include <gtest/gtest.h>

#include <cmath>

#include "util/gauss_legendre.h"

namespace gdr {
namespace {

TEST(GaussLegendre, ExactForPolynomialsUpToDegree2nMinus1) {
  for (int n : {1, 2, 3, 8, 32, 128}) {
    GaussLegendre g = gauss_legendre(n, 0.0, 2.0);
    double weight_sum = 0;
    for (int i = 0; i < n; ++i) {
      weight_sum += g.weights[i];
      if (i > 0) {
        EXPECT_LT(g.nodes[i - 1], g.nodes[i]) << n;
      }
    }
    EXPECT_NEAR(weight_sum, 2.0, 1e-13) << n;
    for (int k : {0, 1, 2 * n - 1, 2 * n}) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += g.weights[i] * std::pow(g.nodes[i], k);
      double exact = std::pow(2.0, k + 1) / (k + 1);
      if (k <= 2 * n - 1) {
        EXPECT_NEAR(sum / exact, 1.0, 1e-12) << "n " << n << " degree " << k;
      } else if (n <= 8) {  // the error, exact / C(2n, n)^2, is below rounding for larger n
        EXPECT_GT(std::fabs(sum / exact - 1.0), 1e-12)
            << "n " << n << " degree " << k << " is not exact";
      }
    }
  }
}

TEST(GaussLegendre, RefusesBadCounts) {
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  EXPECT_THROW(gauss_legendre(2000), std::invalid_argument);
}

}  // namespace
}  // namespace gdr
