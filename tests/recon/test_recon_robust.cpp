// Reconstruction with imperfect inputs: noisy primal, outlier gradients, non-finite values, and
// extreme scales.
#include <gtest/gtest.h>

#include "recon/reconstruct.h"
#include "util/error.h"
#include "recon_fixtures.h"
#include "support/devices.h"

namespace gdr {
namespace {

class ReconRobust : public ::testing::TestWithParam<test::ReconCase> {
 protected:
  ReconSettings published() const {  // the default iteration budget
    ReconSettings s;
    s.norm = GetParam().norm;
    s.solver = GetParam().solver;
    return s;
  }
};

// Exact gradients, primal with Gaussian noise sigma 0.3 (seed 5, 64*48*3 values). The gradients
// pin everything but the mean, which averages the noise over the image, so the result is far
// closer to the truth; a factor 4 leaves a wide margin.
TEST_P(ReconRobust, NoisyPrimalExactGradients) {
  test::GradientImage g = test::exact_problem(64, 48);
  test::add_gaussian_noise(g.primal, 0.3f, 5);
  ReconResult r = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, published(), nullptr);
  double before = test::rmse(g.primal, g.truth), after = test::rmse(r.rgb, g.truth);
  EXPECT_LT(after, before / 4) << "primal RMSE " << before << ", result RMSE " << after;
}

// NaN / Inf in primal, dx and dy (only in positions that are terms of the objective): finite
// output, every one counted, and the rest of the exact data still gives the truth.
TEST_P(ReconRobust, NonFiniteInputsAreDroppedAndCounted) {
  test::GradientImage g = test::exact_problem(31, 17);
  const float inf = INFINITY;
  g.primal[3 * 40 + 0] = NAN;
  g.primal[3 * 41 + 2] = inf;
  g.primal[3 * 100 + 1] = -inf;
  g.dx[3 * 5 + 0] = NAN;  // (5, 0)
  g.dx[3 * 200 + 1] = inf;
  g.dy[3 * 7 + 2] = -inf;
  g.dy[3 * 300 + 0] = NAN;
  Stats stats;
  ReconSettings s = test::converged(GetParam().norm, GetParam().solver);
  ReconResult r = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, &stats);
  EXPECT_TRUE(test::all_finite(r.rgb));
  EXPECT_EQ(stats.count("recon/nonfinite_inputs"), 7u);
  EXPECT_LT(test::max_abs_error(r.rgb, g.truth), 2e-3);
  EXPECT_TRUE(std::isfinite(r.residual));
}

// Everything non-finite: nothing to reconstruct from, and still a finite image.
TEST_P(ReconRobust, AllInputsNonFinite) {
  int w = 9, h = 7;
  std::vector<float> bad(size_t(w) * h * 3, NAN);
  ReconResult r = reconstruct(test::default_context(), w, h, bad, bad, bad, published(), nullptr);
  EXPECT_TRUE(test::all_finite(r.rgb));
}

TEST_P(ReconRobust, ZeroAndConstantInputs) {
  int w = 13, h = 9;
  std::vector<float> zero(size_t(w) * h * 3, 0.0f), constant(zero.size(), 0.75f);
  ReconResult r = reconstruct(test::default_context(), w, h, zero, zero, zero, published(), nullptr);
  EXPECT_EQ(test::max_abs_error(r.rgb, zero), 0.0);
  r = reconstruct(test::default_context(), w, h, constant, zero, zero, published(), nullptr);
  EXPECT_LT(test::max_abs_error(r.rgb, constant), 1e-6);
}

// The same problem scaled by 1e6 and 1e-6 (noisy primal, holes): the result scales with it.
// L1's reg is absolute, so at 1e-6 the scale sits below reg: compare with a relative tolerance
// that covers the L1 result's smoothing there.
TEST_P(ReconRobust, ExtremeScalesStayFiniteAndScale) {
  test::GradientImage g = test::exact_problem(24, 16);
  for (size_t p = 0; p < size_t(g.w) * g.h; p += 4) g.primal[p * 3] = NAN;
  ReconSettings s = test::converged(GetParam().norm, GetParam().solver);
  for (float scale : {1e6f, 1e-6f}) {
    SCOPED_TRACE(scale);
    test::GradientImage sg = g;
    for (auto* v : {&sg.truth, &sg.primal, &sg.dx, &sg.dy}) {
      for (float& x : *v) x *= scale;
    }
    ReconResult r = reconstruct(test::default_context(), g.w, g.h, sg.primal, sg.dx, sg.dy, s, nullptr);
    EXPECT_TRUE(test::all_finite(r.rgb));
    EXPECT_LT(test::max_abs_error(r.rgb, sg.truth), 5e-3 * scale);
  }
}

INSTANTIATE_TEST_SUITE_P(Recon, ReconRobust, ::testing::ValuesIn(test::all_cases()),
                         [](const auto& info) { return test::case_name(info.param); });

// A few huge outliers among exact gradients (exact primal). L1 ignores them (the IRLS weight of a
// term with residual ~1000 is ~1/1000); L2 spreads each one over its neighbourhood.
TEST(ReconNorms, L1IgnoresSparseOutlierGradientsWhereL2IsPulled) {
  for (auto solver : {ReconSettings::Solver::CG, ReconSettings::Solver::Fast}) {
    test::GradientImage g = test::exact_problem(64, 48);
    const size_t outliers[] = {3 * (10 * 64 + 10), 3 * (30 * 64 + 40) + 1, 3 * (20 * 64 + 50) + 2};
    for (size_t i : outliers) {
      g.dx[i] = 1000.0f;
      g.dy[i] = -1000.0f;
    }
    ReconSettings s;
    s.solver = solver;
    s.norm = ReconNorm::L1;
    ReconResult l1 = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, nullptr);
    s.norm = ReconNorm::L2;
    ReconResult l2 = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, nullptr);
    EXPECT_LT(test::max_abs_error(l1.rgb, g.truth), 0.05);
    EXPECT_GT(test::max_abs_error(l2.rgb, g.truth), 10.0);
    EXPECT_LT(test::rmse(l1.rgb, g.truth) * 100, test::rmse(l2.rgb, g.truth));
  }
}

TEST(ReconInput, MismatchedSizesAreRejected) {
  std::vector<float> ok(4 * 3 * 3, 0.0f), small(5, 0.0f);
  ReconSettings s;
  EXPECT_THROW(reconstruct(test::default_context(), 4, 3, small, ok, ok, s, nullptr), Error);
  EXPECT_THROW(reconstruct(test::default_context(), 4, 3, ok, ok, small, s, nullptr), Error);
  EXPECT_THROW(reconstruct(test::default_context(), 0, 3, ok, ok, ok, s, nullptr), Error);
  // Too large for the kernels' 32-bit indices (a strip: the row stride pads 1 pixel to 16), caught
  // as such before the inputs are looked at.
  try {
    reconstruct(test::default_context(), 1, 60000000, ok, ok, ok, s, nullptr);
    ADD_FAILURE() << "no error for a 1x60000000 image";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("invalid image size"), std::string::npos) << e.what();
  }
}

TEST(ReconStats, SolveIsRecorded) {
  test::GradientImage g = test::exact_problem(16, 8);
  test::add_gaussian_noise(g.primal, 0.1f, 3);  // seed 3
  Stats stats;
  ReconSettings s;
  s.norm = ReconNorm::L2;
  s.solver = ReconSettings::Solver::CG;
  ReconResult r = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, &stats);
  EXPECT_EQ(r.iterations, 50);
  EXPECT_EQ(stats.count("recon/iterations"), 50u);
  EXPECT_EQ(stats.to_json()["recon"]["norm"], "L2");
  EXPECT_GT(stats.seconds("recon/solve"), 0.0);
  EXPECT_GT(r.residual, 0.0);
  EXPECT_LT(r.residual, 1e-2);
}

}  // namespace
}  // namespace gdr
