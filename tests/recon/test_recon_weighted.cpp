// The weighted reconstruction: each term weighted by the inverse of its input's variance
// estimate, so the solve leans on whichever input is less noisy, pixel by pixel; zero estimates
// keep the weights bounded; and the kernels solve the objective the header defines.
#include <gtest/gtest.h>

#include <algorithm>

#include "recon/reconstruct.h"
#include "recon_fixtures.h"
#include "support/devices.h"
#include "util/error.h"

namespace gdr {
namespace {

using test::GradientImage;

ReconSettings weighted(ReconSettings::Solver solver, float alpha = 1.0f) {
  ReconSettings s = test::converged(ReconNorm::Weighted, solver);
  s.alpha = alpha;
  return s;
}

// Variance sigma(x, y)^2 for every value of an interleaved image.
template <class Sigma>
std::vector<float> variance_map(int w, int h, Sigma sigma) {
  std::vector<float> v(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) v[(size_t(y) * w + x) * 3 + c] = sigma(x, y) * sigma(x, y);
    }
  }
  return v;
}

// Gaussian noise of standard deviation sqrt(variance) on every value (std::mt19937 `seed`).
void add_noise(std::vector<float>& v, const std::vector<float>& variance, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> n(0.0f, 1.0f);
  for (size_t i = 0; i < v.size(); ++i) v[i] += std::sqrt(variance[i]) * n(rng);
}

ReconResult solve(const GradientImage& g, const ReconVariance& var, const ReconSettings& s, Stats* stats = nullptr) {
  return reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, stats, &var);
}

class ReconWeighted : public ::testing::TestWithParam<ReconSettings::Solver> {};

// Exact gradients (variance 0) and a primal whose noise grows from sigma 0.02 on the left to 0.4
// on the right (seed 7): the gradients carry the image, the primal only its level, taken where
// it is least noisy, so the result is far closer to the truth than the primal, and than the
// unweighted L2 solve, which averages the level over all of the primal alike.
TEST_P(ReconWeighted, NoisyPrimalExactGradients) {
  GradientImage g = test::exact_problem(64, 48);
  auto sigma = [&](int x, int) { return 0.02f + 0.38f * x / (g.w - 1); };
  ReconVariance var{variance_map(g.w, g.h, sigma), std::vector<float>(g.dx.size(), 0.0f),
                    std::vector<float>(g.dy.size(), 0.0f)};
  add_noise(g.primal, var.primal, 7);
  ReconResult r = solve(g, var, weighted(GetParam()));
  ReconSettings l2 = test::converged(ReconNorm::L2, GetParam());
  ReconResult u = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, l2, nullptr);
  double before = test::rmse(g.primal, g.truth), after = test::rmse(r.rgb, g.truth);
  EXPECT_TRUE(test::all_finite(r.rgb));
  EXPECT_LT(after, before / 25) << "primal RMSE " << before << ", weighted " << after;
  EXPECT_LT(after, test::rmse(u.rgb, g.truth) / 2) << "unweighted L2 " << test::rmse(u.rgb, g.truth);
}

// Exact primal (variance 0) and gradients with noise sigma 0.3 (seed 8): the primal carries the
// image, the gradients get weights ~1e4 times lower, and the result is the primal nearly exactly,
// where the unweighted L2 solve is pulled by the noisy gradients.
TEST_P(ReconWeighted, ExactPrimalNoisyGradients) {
  GradientImage g = test::exact_problem(64, 48);
  std::vector<float> noisy = variance_map(g.w, g.h, [](int, int) { return 0.3f; });
  ReconVariance var{std::vector<float>(g.primal.size(), 0.0f), noisy, noisy};
  add_noise(g.dx, noisy, 8);
  add_noise(g.dy, noisy, 9);
  ReconResult r = solve(g, var, weighted(GetParam()));
  ReconSettings l2 = test::converged(ReconNorm::L2, GetParam());
  ReconResult u = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, l2, nullptr);
  double after = test::rmse(r.rgb, g.truth), unweighted = test::rmse(u.rgb, g.truth);
  EXPECT_LT(after, 0.01) << "weighted RMSE " << after;
  EXPECT_LT(after, unweighted / 10) << "unweighted L2 RMSE " << unweighted;
}

// Both cases in one image, pixel by pixel: the left half has a noisy primal (sigma 0.3) and exact
// gradients, the right half an exact primal and noisy gradients (sigma 0.3; seeds 10, 11, 12).
// Each half leans on its own good input; the unweighted solve, with one alpha for the whole
// image, cannot do both.
TEST_P(ReconWeighted, EachPixelLeansOnItsLessNoisyInput) {
  GradientImage g = test::exact_problem(64, 48);
  const int half = g.w / 2;
  ReconVariance var{variance_map(g.w, g.h, [&](int x, int) { return x < half ? 0.3f : 0.0f; }),
                    variance_map(g.w, g.h, [&](int x, int) { return x < half - 1 ? 0.0f : 0.3f; }),
                    variance_map(g.w, g.h, [&](int x, int) { return x < half ? 0.0f : 0.3f; })};
  add_noise(g.primal, var.primal, 10);
  add_noise(g.dx, var.dx, 11);
  add_noise(g.dy, var.dy, 12);
  ReconResult r = solve(g, var, weighted(GetParam()));
  ReconSettings l2 = test::converged(ReconNorm::L2, GetParam());
  ReconResult u = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, l2, nullptr);
  double after = test::rmse(r.rgb, g.truth), unweighted = test::rmse(u.rgb, g.truth);
  EXPECT_LT(after, 0.02) << "weighted RMSE " << after;
  EXPECT_LT(after, unweighted / 5) << "unweighted L2 RMSE " << unweighted;
}

// Zero estimates everywhere: every weight is the bound 1 / floor (alpha^2 / floor on the primal),
// so the solve is the unweighted L2 solve, finite, whatever the inputs' noise (seeds 13-15).
TEST_P(ReconWeighted, ZeroVarianceEstimatesGiveBoundedWeights) {
  const int w = 5, h = 4;
  std::vector<float> primal(size_t(w) * h * 3, 0.5f), dx(primal.size(), 0.0f), dy(primal.size(), 0.0f);
  test::add_gaussian_noise(primal, 0.5f, 13);
  test::add_gaussian_noise(dx, 0.3f, 14);
  test::add_gaussian_noise(dy, 0.3f, 15);
  std::vector<float> zero(primal.size(), 0.0f);
  ReconVariance var{zero, zero, zero};
  const float alpha = 0.5f;
  ReconResult r = reconstruct(test::default_context(), w, h, primal, dx, dy, weighted(GetParam(), alpha), nullptr, &var);
  EXPECT_TRUE(test::all_finite(r.rgb));
  EXPECT_TRUE(std::isfinite(r.energy));
  EXPECT_LT(test::max_abs_error(r.rgb, test::dense_l2_solve(w, h, alpha, primal, dx, dy)), 1e-4);
}

// Estimates that are zero, huge (1e30) or non-finite side by side: a finite image, the
// non-finite ones counted with the inputs, and exact data still reconstructed exactly.
TEST_P(ReconWeighted, ExtremeAndNonFiniteEstimatesStayFinite) {
  GradientImage g = test::exact_problem(31, 17);
  ReconVariance var{std::vector<float>(g.primal.size(), 0.0f), std::vector<float>(g.dx.size(), 1e30f),
                    std::vector<float>(g.dy.size(), 1e-3f)};
  for (size_t i = 0; i < var.primal.size(); i += 7) var.primal[i] = 1e30f;
  var.primal[5] = NAN;
  var.dx[40] = INFINITY;
  var.dy[41] = -INFINITY;
  Stats stats;
  ReconResult r = solve(g, var, weighted(GetParam()), &stats);
  EXPECT_TRUE(test::all_finite(r.rgb));
  EXPECT_EQ(stats.count("recon/nonfinite_inputs"), 3u);
  EXPECT_LT(test::max_abs_error(r.rgb, g.truth), 2e-3);
  EXPECT_EQ(stats.to_json()["recon"]["norm"], "weighted");
}

// The weights are relative to the image's variance scale: the same problem at 1e-6 and 1e6 times
// the brightness (variances scaled by the square) gives the same image scaled (seeds 16-18).
TEST_P(ReconWeighted, ResultScalesWithTheImage) {
  GradientImage g = test::exact_problem(24, 16);
  std::vector<float> vp = variance_map(g.w, g.h, [](int x, int) { return 0.05f + 0.02f * x; });
  std::vector<float> vg = variance_map(g.w, g.h, [](int, int y) { return 0.02f + 0.02f * y; });
  add_noise(g.primal, vp, 16);
  add_noise(g.dx, vg, 17);
  add_noise(g.dy, vg, 18);
  ReconResult base = solve(g, ReconVariance{vp, vg, vg}, weighted(GetParam()));
  for (float scale : {1e-6f, 1e6f}) {
    SCOPED_TRACE(scale);
    GradientImage sg = g;
    ReconVariance sv{vp, vg, vg};
    for (auto* v : {&sg.primal, &sg.dx, &sg.dy}) {
      for (float& x : *v) x *= scale;
    }
    for (auto* v : {&sv.primal, &sv.dx, &sv.dy}) {
      for (float& x : *v) x *= scale * scale;
    }
    ReconResult r = solve(sg, sv, weighted(GetParam()));
    ASSERT_TRUE(test::all_finite(r.rgb));
    for (size_t i = 0; i < r.rgb.size(); ++i) ASSERT_NEAR(r.rgb[i] / scale, base.rgb[i], 1e-3) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Recon, ReconWeighted,
                         ::testing::Values(ReconSettings::Solver::CG, ReconSettings::Solver::Fast),
                         [](const auto& info) { return info.param == ReconSettings::Solver::CG ? "CG" : "Fast"; });

// Per channel, the median of the positive estimates of all three inputs (the scale the header
// defines), computed here independently.
double median_positive(const ReconVariance& v, int c) {
  std::vector<double> x;
  for (const auto* layer : {&v.primal, &v.dx, &v.dy}) {
    for (size_t i = size_t(c); i < layer->size(); i += 3) {
      if ((*layer)[i] > 0) x.push_back((*layer)[i]);
    }
  }
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

// Random inputs and random estimates (seeds 19-24): the kernels' answer is the minimiser of the
// weighted objective the header states, w = 1 / (v / s + floor), built and solved densely here.
TEST(ReconWeightedDense, KernelSolveMatchesDenseWeightedSolve) {
  const int w = 6, h = 5;
  std::vector<float> primal(size_t(w) * h * 3, 0.5f), dx(primal.size(), 0.0f), dy(primal.size(), 0.0f);
  test::add_gaussian_noise(primal, 0.5f, 19);
  test::add_gaussian_noise(dx, 0.3f, 20);
  test::add_gaussian_noise(dy, 0.3f, 21);
  ReconVariance var;
  unsigned seed = 22;
  for (auto* v : {&var.primal, &var.dx, &var.dy}) {
    std::mt19937 rng(seed++);
    std::lognormal_distribution<float> d(-3.0f, 2.0f);  // spans several decades
    v->resize(primal.size());
    for (float& x : *v) x = d(rng);
  }
  // Terms that do not exist (dx of the last column, dy of the last row) carry no estimate.
  for (int y = 0; y < h; ++y) {
    for (int c = 0; c < 3; ++c) {
      var.dx[(size_t(y) * w + w - 1) * 3 + c] = 0.0f;
      if (y == h - 1) {
        for (int x = 0; x < w; ++x) var.dy[(size_t(y) * w + x) * 3 + c] = 0.0f;
      }
    }
  }
  const float alpha = 0.7f;
  ReconSettings s = weighted(ReconSettings::Solver::Fast, alpha);
  auto weights = [&](const std::vector<float>& v, double factor) {
    std::vector<double> out(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
      out[i] = factor / (v[i] / median_positive(var, int(i % 3)) + s.variance_floor);
    }
    return out;
  };
  std::vector<float> expected = test::dense_weighted_solve(w, h, weights(var.primal, double(alpha) * alpha),
                                                           weights(var.dx, 1.0), weights(var.dy, 1.0), primal, dx, dy);
  for (auto solver : {ReconSettings::Solver::CG, ReconSettings::Solver::Fast}) {
    s.solver = solver;
    ReconResult r = reconstruct(test::default_context(), w, h, primal, dx, dy, s, nullptr, &var);
    EXPECT_LT(test::max_abs_error(r.rgb, expected), 1e-3);
  }
}

TEST(ReconWeightedInput, VarianceEstimatesAreRequired) {
  GradientImage g = test::exact_problem(8, 6);
  ReconSettings s = weighted(ReconSettings::Solver::Fast);
  try {
    reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, nullptr);
    ADD_FAILURE() << "no error without variance estimates";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("variance"), std::string::npos) << e.what();
  }
  ReconVariance short_dy{g.primal, g.dx, std::vector<float>(5, 0.0f)};
  try {
    solve(g, short_dy, s);
    ADD_FAILURE() << "no error for a dy variance of the wrong size";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("dy variance"), std::string::npos) << e.what();
  }
  EXPECT_EQ(recon_settings("weighted", 1.0f, "fast").norm, ReconNorm::Weighted);
}

}  // namespace
}  // namespace gdr
