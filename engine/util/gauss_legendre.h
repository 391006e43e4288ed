// Gauss-Legendre quadrature: n nodes and weights on [a, b], exact for polynomials of degree
// 2n - 1. Generic numerics (the coating tables and tests integrate with it).
#pragma once
#include <vector>

namespace gdr {

struct GaussLegendre {
  std::vector<double> nodes;    // ascending
  std::vector<double> weights;  // sum to b - a
};

// Throws std::invalid_argument unless 1 <= n <= 1024.
GaussLegendre gauss_legendre(int n, double a = -1.0, double b = 1.0);

}  // namespace gdr
