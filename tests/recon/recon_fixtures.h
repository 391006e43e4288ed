// Test images for the reconstruction tests: a known image (smooth ramps plus hard edges), its
// exact forward-difference gradients, seeded noise, and error measures.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "recon/reconstruct.h"

namespace gdr::test {

struct GradientImage {
  int w = 0, h = 0;
  std::vector<float> truth, primal, dx, dy;  // interleaved RGB
};

// Smooth gradients plus a bright disc and a dark bar (edges), values in about [0, 1.5].
inline std::vector<float> known_image(int w, int h) {
  std::vector<float> img(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float u = (x + 0.5f) / w, v = (y + 0.5f) / h;
      float disc = (u - 0.6f) * (u - 0.6f) + (v - 0.4f) * (v - 0.4f) < 0.06f ? 0.8f : 0.0f;
      float bar = (u > 0.15f && u < 0.3f) ? -0.3f : 0.0f;
      float* p = &img[(size_t(y) * w + x) * 3];
      p[0] = 0.3f + 0.4f * u + disc + 0.1f * std::sin(6.0f * v) + 0.3f + bar;
      p[1] = 0.2f + 0.5f * v * v + 0.5f * disc + 0.3f;
      p[2] = 0.5f + 0.2f * std::cos(4.0f * u + 3.0f * v) + bar + 0.3f;
    }
  }
  return img;
}

inline void exact_gradients(const std::vector<float>& img, int w, int h, std::vector<float>& dx,
                            std::vector<float>& dy) {
  dx.assign(img.size(), 0.0f);
  dy.assign(img.size(), 0.0f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        size_t i = (size_t(y) * w + x) * 3 + c;
        if (x + 1 < w) dx[i] = img[i + 3] - img[i];
        if (y + 1 < h) dy[i] = img[i + size_t(w) * 3] - img[i];
      }
    }
  }
}

// Exact primal and gradients of known_image.
inline GradientImage exact_problem(int w, int h) {
  GradientImage g;
  g.w = w;
  g.h = h;
  g.truth = known_image(w, h);
  g.primal = g.truth;
  exact_gradients(g.truth, w, h, g.dx, g.dy);
  return g;
}

inline void add_gaussian_noise(std::vector<float>& v, float sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> n(0.0f, sigma);
  for (float& x : v) x += n(rng);
}

inline double rmse(const std::vector<float>& a, const std::vector<float>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += double(a[i] - b[i]) * (a[i] - b[i]);
  return a.empty() ? 0.0 : std::sqrt(s / a.size());
}

inline double max_abs_error(const std::vector<float>& a, const std::vector<float>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, double(std::fabs(a[i] - b[i])));
  return m;
}

inline bool all_finite(const std::vector<float>& v) {
  for (float x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

// Dense normal equations built here from the definition of the weighted objective
//   sum wp (x - p)^2 + wx (x_right - x - dx)^2 + wy (x_down - x - dy)^2
// (weights interleaved RGB like the images; the last column's wx and last row's wy unused),
// solved by Gaussian elimination with partial pivoting (double precision), per channel.
inline std::vector<float> dense_weighted_solve(int w, int h, const std::vector<double>& wp,
                                               const std::vector<double>& wx, const std::vector<double>& wy,
                                               const std::vector<float>& primal, const std::vector<float>& dx,
                                               const std::vector<float>& dy) {
  int n = w * h;
  std::vector<float> out(size_t(n) * 3);
  for (int c = 0; c < 3; ++c) {
    std::vector<std::vector<double>> A(n, std::vector<double>(n + 1, 0.0));
    auto add_term = [&](int i, int j, double g, double k) {  // k (x_j - x_i - g)^2
      A[i][i] += k; A[j][j] += k; A[i][j] -= k; A[j][i] -= k;
      A[i][n] -= k * g; A[j][n] += k * g;
    };
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        int i = y * w + x;
        A[i][i] += wp[i * 3 + c];  // wp (x_i - p_i)^2
        A[i][n] += wp[i * 3 + c] * primal[i * 3 + c];
        if (x + 1 < w) add_term(i, i + 1, dx[i * 3 + c], wx[i * 3 + c]);
        if (y + 1 < h) add_term(i, i + w, dy[i * 3 + c], wy[i * 3 + c]);
      }
    }
    for (int k = 0; k < n; ++k) {
      int piv = k;
      for (int i = k + 1; i < n; ++i) if (std::fabs(A[i][k]) > std::fabs(A[piv][k])) piv = i;
      std::swap(A[k], A[piv]);
      for (int i = k + 1; i < n; ++i) {
        double f = A[i][k] / A[k][k];
        for (int j = k; j <= n; ++j) A[i][j] -= f * A[k][j];
      }
    }
    std::vector<double> x(n);
    for (int k = n - 1; k >= 0; --k) {
      double s = A[k][n];
      for (int j = k + 1; j < n; ++j) s -= A[k][j] * x[j];
      x[k] = s / A[k][k];
    }
    for (int i = 0; i < n; ++i) out[i * 3 + c] = float(x[i]);
  }
  return out;
}

// The unweighted L2 objective: weight alpha^2 on the primal, 1 on the gradients.
inline std::vector<float> dense_l2_solve(int w, int h, float alpha, const std::vector<float>& primal,
                                  const std::vector<float>& dx, const std::vector<float>& dy) {
  std::vector<double> wp(primal.size(), double(alpha) * alpha), ones(primal.size(), 1.0);
  return dense_weighted_solve(w, h, wp, ones, ones, primal, dx, dy);
}

// Settings that solve to convergence (for comparisons with exact answers).
inline ReconSettings converged(ReconNorm norm, ReconSettings::Solver solver) {
  ReconSettings s;
  s.norm = norm;
  s.solver = solver;
  s.cg_iterations = 2000;
  s.tolerance = 1e-6;
  return s;
}

// All four (norm, solver) combinations, for parameterised tests.
struct ReconCase {
  ReconNorm norm;
  ReconSettings::Solver solver;
};
inline std::vector<ReconCase> all_cases() {
  using S = ReconSettings::Solver;
  return {{ReconNorm::L2, S::CG}, {ReconNorm::L2, S::Fast}, {ReconNorm::L1, S::CG},
          {ReconNorm::L1, S::Fast}};
}
inline std::string case_name(const ReconCase& c) {
  return std::string(c.norm == ReconNorm::L1 ? "L1" : "L2") +
         (c.solver == ReconSettings::Solver::CG ? "_CG" : "_Fast");
}

}  // namespace gdr::test
